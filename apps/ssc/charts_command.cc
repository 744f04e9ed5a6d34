// ssc charts: the speed-accuracy charts, for the cup and for the simulator, from the project's
// own runs.
//   cup: a sweep over step length (so speed) for a few (P_ref, beta) -> success, sigma_r, |dr|,
//        contour error vs speed, and the Pareto front of speed vs tracking error;
//   tiers: each fidelity tier (arm, gantry, light, fast, flex) by its cost per step, static curve,
//        Fig. 6 targets and outcomes on a few test objects;
//   simulator: one logged path replayed with cheaper and dearer settings (rays per chamber,
//        sensor rate, time step, integrator, lip segments) -> wall time per simulated second vs
//        pressure error against the finest replay as reference (16 rays per chamber, 32 lip
//        segments, 0.25 ms, RK4).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "studies/object_study.h"
#include "studies/sim_cost_table.h"
#include "studies/sweep.h"

namespace ssc {

namespace fs = std::filesystem;

namespace {

// The tiers table: printed row by row against the published targets, and written to csv.
bool RunTiers(const SimTierSpec& spec, const std::string& csv, std::string* error) {
  std::printf(
      "tiers (P_ref 100 Pa, dL 5 mm, seeds %llu..%llu; published: Pbar 40/100/200 Pa at "
      "0.7/2.5/3.2 mm, |dP| ~200 Pa, sigma_r 1.36/-/1.89 mm, s_c 11/21/31 %%, dr -2.5 "
      "mm at beta 1.5/2.5/3.5; Fig. 6 as mean+-sd over the successful seeds):\n",
      static_cast<unsigned long long>(spec.seed),
      static_cast<unsigned long long>(spec.seed + spec.seeds - 1));
  std::vector<SimTierRow> rows;
  const bool ok = RunSimTierTable(
      spec,
      [](const SimTierRow& r) {
        // Fig. 6 per beta: mean +- sd over the successful seeds.
        std::printf(
            "  %-7s %8.1f us/step  compression %.2f mm  Pbar %.0f/%.0f/%.0f Pa  |dP| %.0f Pa  "
            "sigma_r %.2f+-%.2f/%.2f+-%.2f/%.2f+-%.2f mm  s_c %.1f+-%.1f/%.1f+-%.1f/%.1f+-%.1f %%  "
            "dr %.2f+-%.2f/%.2f+-%.2f/%.2f+-%.2f mm  successes %d/%d %d/%d %d/%d\n",
            r.tier.c_str(), r.us_per_step, r.approach_compression_mm, r.static_pbar_pa[0],
            r.static_pbar_pa[1], r.static_pbar_pa[2], r.static_diff_pa, r.sigma_r_mm[0],
            r.sigma_r_sd_mm[0], r.sigma_r_mm[1], r.sigma_r_sd_mm[1], r.sigma_r_mm[2],
            r.sigma_r_sd_mm[2], 100 * r.s_c[0], 100 * r.s_c_sd[0], 100 * r.s_c[1],
            100 * r.s_c_sd[1], 100 * r.s_c[2], 100 * r.s_c_sd[2], r.dr_mm[0], r.dr_sd_mm[0],
            r.dr_mm[1], r.dr_sd_mm[1], r.dr_mm[2], r.dr_sd_mm[2], r.successes[0], r.trials[0],
            r.successes[1], r.trials[1], r.successes[2], r.trials[2]);
        if (!r.objects.empty()) std::printf("          objects: %s\n", r.objects.c_str());
        std::fflush(stdout);
      },
      &rows, error);
  if (!ok || !WriteWholeFile(csv, SimTierCsv(rows), error)) return false;
  std::printf("wrote %s\n", csv.c_str());
  return true;
}

}  // namespace

int RunChartsCommand(int argc, char** argv) {
  cli::Command cmd("charts",
                   "Makes the speed-accuracy charts from the project's own runs: OUT/cup.csv (a\n"
                   "sweep over dL), OUT/simulator.csv (replays at several fidelities), and\n"
                   "OUT/speed_accuracy.png. Re-running resumes the sweep. First the fidelity\n"
                   "tiers side by side (OUT/tiers.csv): cost per step, the straight-edge static\n"
                   "curve, the Fig. 6 targets and a few test objects per tier.");
  SweepSpec spec;
  spec.pref_pa = {70, 100, 200};
  spec.beta = {1, 2, 3};
  spec.step_mm = {1, 2.5, 5, 7.5, 10, 12.5};
  long repeats = 3, threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "out/charts";
  cmd.NumberList("pref", &spec.pref_pa, "P_ref values", "Pa",
                 NumberRange::Positive(1e6).OpenHigh());
  cmd.NumberList("beta", &spec.beta, "beta values", "", NumberRange::Closed(0, 100));
  cmd.NumberList("step", &spec.step_mm, "step lengths", "mm",
                 NumberRange::Closed(kMinStepMm, kMaxStepMm));
  cmd.Integer("repeats", &repeats, "trials per point", NumberRange::Closed(1, 1000));
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory");
  spec.scene_name = DefaultScene();
  cmd.Text("scene", &spec.scene_name,
           "scene of the cup sweep and of the trial the replays follow (name under scenes/ or a "
           "path)");
  std::string tier_names = "gantry,flex", tier_objects = "corner_a090,corner_a270,hole_d06,fillet";
  SimTierSpec tiers;
  long tier_seeds = tiers.seeds;
  bool tiers_only = false;
  cmd.Text("tiers", &tier_names,
           "fidelity tiers for OUT/tiers.csv, by name: " + RigDiskTierNames());
  cmd.Integer("tier-seeds", &tier_seeds, "disk trials per beta per tier (Fig. 6 targets)",
              NumberRange::Closed(1, 100));
  cmd.Seed("tier-seed", &tiers.seed, "base seed of the tiers' trials");
  cmd.Text("tier-objects", &tier_objects,
           "test objects run in each tier that has object scenes (arm, gantry, flex), or none");
  cmd.Flag("tiers-only", &tiers_only, "only the tiers table (no cup sweep, no replays)");
  cmd.Check([&]() {
    std::string e;
    if (!SimTiersByNames(tier_names, &tiers.tiers, &e)) return "--tiers: " + e;
    if (tier_objects != "none" && !ObjectsByNames(tier_objects, &tiers.objects, &e)) {
      return "--tier-objects: " + e;
    }
    return std::string();
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  tiers.seeds = static_cast<int>(tier_seeds);
  spec.repeats = static_cast<int>(repeats);
  spec.threads = static_cast<int>(threads);
  const fs::path out = out_dir;
  spec.out_csv = (out / "cup.csv").string();
  std::string error;
  ModelPtr model = LoadModel(ResolveScenePath(spec.scene_name), &error);
  if (!model) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    cli::NoteInputError(error);
    return 1;
  }
  if (const std::string e = CheckSweepGrid(spec); !e.empty()) return cmd.Fail(e);
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  tiers.threads = spec.threads;
  tiers.object_dir = (out / "tier_objects").string();
  if (!RunTiers(tiers, (out / "tiers.csv").string(), &error)) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  if (tiers_only) return 0;
  SweepSummary summary;
  if (!RunSweep(model.get(), spec, nullptr, &summary, &error)) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  std::printf("cup sweep: %d trials (%d run now) in %.1f s -> %s\n", summary.total, summary.ran,
              summary.wall_s, spec.out_csv.c_str());

  // The simulator: a path from one twin trial, replayed at several fidelities.
  SimCostTrial trial{spec.scene_name, model->opt.timestep, TrialConfig(), TrialResult()};
  trial.config.law.step_mm = 5;
  trial.result = RunTrial(model.get(), trial.config, true, &error);
  std::vector<SimCostRow> rows;
  const bool ok = RunSimCostTable(
      trial, ResolveScenePath(RigTierFor(RigUse::kReplay).scene),
      ResolveScenePath(RigTierFor(RigUse::kReference).scene),
      [](const SimCostRow& r) {
        std::printf("  %-44s wall/sim %.4f  error %.4f log10, %.1f Pa\n", r.setting.c_str(),
                    r.wall_per_sim_s, r.rms_log10, r.rms_pa);
      },
      &rows, &error);
  if (!ok) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  if (!WriteWholeFile((out / "simulator.csv").string(), SimCostCsv(rows), &error)) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  const std::string png = (out / "speed_accuracy.png").string();
  if (RunPlotScript("plot_speed_accuracy.py",
                    {(out / "cup.csv").string(), (out / "simulator.csv").string(), png})) {
    std::printf("wrote %s\n", png.c_str());
  }
  return 0;
}

}  // namespace ssc
