// ssc sweep: a grid of trials on all cores, resumable, one CSV row per trial.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/progress.h"
#include "apps/ssc/trial_options.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/jobs/job_runner.h"
#include "studies/sweep.h"

namespace ssc {

int RunSweepCommand(int argc, char** argv) {
  cli::Command cmd("sweep",
                   "Runs a grid P_ref x beta x dL x repeats of disk trials (the published grid by\n"
                   "default) on all cores. Rows are appended to OUT/sweep.csv as trials end;\n"
                   "re-running the same command resumes, skipping finished rows.");
  SweepSpec spec;
  spec.scene_name = DefaultScene();
  spec.pref_pa = {40, 70, 100, 150, 200, 250, 300};
  spec.beta = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};
  spec.step_mm = {2.5, 5, 7.5};
  long repeats = 3, threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "out/sweep";
  bool no_plot = false, no_progress = false, no_shared_approach = false;
  TrialSettings settings;
  cmd.Text("scene", &spec.scene_name, "scene (name under scenes/ or a path)");
  cmd.NumberList("pref", &spec.pref_pa, "P_ref values", "Pa",
                 NumberRange::Positive(1e6).OpenHigh());
  cmd.NumberList("beta", &spec.beta, "beta values", "", NumberRange::Closed(0, 100));
  cmd.NumberList("step", &spec.step_mm, "step lengths dL", "mm",
                 NumberRange::Closed(kMinStepMm, kMaxStepMm));
  cmd.Integer("repeats", &repeats, "trials per grid point", NumberRange::Closed(1, 1000));
  cmd.Seed("seed", &spec.seed, "base seed (each trial's seed derives from it and its grid point)");
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory (sweep.csv, success_maps.png)");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Flag("no-progress", &no_progress,
           "no progress (a bar on a terminal, a line per 5 % of the trials otherwise)");
  cmd.Flag("no-shared-approach", &no_shared_approach,
           "simulate every trial's approach and move to the start point itself (by default "
           "each distinct approach is simulated once and shared; the rows are the same)");
  // The trial settings are checked with the grid's first point (each point is checked again).
  cmd.Check([&spec]() {
    spec.base.law.p_ref_pa = spec.pref_pa.front();
    spec.base.law.beta = spec.beta.front();
    spec.base.law.step_mm = spec.step_mm.front();
    return std::string();
  });
  AddControllerOptions(&cmd, &settings.controller, &settings.controller_params,
                       &spec.base.controller);
  AddTrialSettingOptions(&cmd, &spec.base, &settings);
  // Then every point of the grid, before anything is created.
  cmd.Check([&spec, &repeats]() {
    spec.repeats = static_cast<int>(repeats);
    return CheckSweepGrid(spec);
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  std::string error;
  spec.threads = static_cast<int>(threads);
  spec.share_approach = !no_shared_approach;
  const std::filesystem::path out = out_dir;
  spec.out_csv = (out / "sweep.csv").string();

  const std::string scene = ResolveScenePath(spec.scene_name);
  ModelPtr model = LoadTrialScene(cmd, scene, spec.base);
  if (!model) return 1;
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const bool rank0 = JobRunnerRank() == 0;
  TrialProgress progress("ssc sweep", rank0 && !no_progress);
  SweepSummary summary;
  if (!RunSweep(model.get(), spec, std::ref(progress), &summary, &error)) {
    std::fprintf(stderr, "ssc sweep: %s\n", error.c_str());
    return 1;
  }
  progress.Finish();
  if (!rank0) return summary.interrupted ? 130 : 0;
  std::printf(
      "sweep: %d trials (%d already in %s, %d run) in %.1f s wall on %d rank(s) x %d "
      "threads (%.2f trials/s)\n",
      summary.total, summary.skipped, spec.out_csv.c_str(), summary.ran, summary.wall_s,
      summary.ranks, summary.threads, summary.wall_s > 0 ? summary.ran / summary.wall_s : 0.0);
  double busy = 0;
  for (double b : summary.rank_busy_s) busy += b;
  std::printf("load: %.1f trial-s busy, longest trial %.2f s; rank busy max/mean %.3f (", busy,
              summary.longest_trial_s, summary.balance_max_over_mean);
  for (size_t r = 0; r < summary.rank_busy_s.size(); ++r) {
    std::printf("%s%.1f", r ? " " : "", summary.rank_busy_s[r]);
  }
  std::printf(" s)\n");
  PrintApproachSharing(spec.share_approach, summary);
  if (summary.interrupted) {
    std::fprintf(stderr,
                 "ssc sweep: interrupted; %d finished rows kept in %s, re-run the same "
                 "command to resume\n",
                 summary.ran, spec.out_csv.c_str());
    return 130;
  }
  if (!no_plot) {
    const std::string png = (out / "success_maps.png").string();
    if (RunPlotScript("plot_success_maps.py", {spec.out_csv, png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
