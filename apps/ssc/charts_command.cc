// ssc charts: the speed-accuracy charts, for the cup and for the simulator, from the project's
// own runs.
//   cup: a sweep over step length (so speed) for a few (P_ref, beta) -> success, sigma_r, |dr|,
//        contour error vs speed, and the Pareto front of speed vs tracking error;
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
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "studies/sim_cost_table.h"
#include "studies/sweep.h"

namespace ssc {

namespace fs = std::filesystem;

int RunChartsCommand(int argc, char** argv) {
  cli::Command cmd("charts",
                   "Makes the speed-accuracy charts from the project's own runs: OUT/cup.csv (a\n"
                   "sweep over dL), OUT/simulator.csv (replays at several fidelities), and\n"
                   "OUT/speed_accuracy.png. Re-running resumes the sweep.");
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
  cmd.Integer("threads", &threads, "threads for the sweep", NumberRange::Closed(1, 256));
  cmd.OutputDir("out", &out_dir, "output directory");
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  spec.repeats = static_cast<int>(repeats);
  spec.threads = static_cast<int>(threads);
  spec.scene_name = "disk_benchmark_gantry";
  const fs::path out = out_dir;
  spec.out_csv = (out / "cup.csv").string();
  std::string error;
  ModelPtr gantry = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
  if (!gantry) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  if (const std::string e = CheckSweepGrid(spec); !e.empty()) return cmd.Fail(e);
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  SweepSummary summary;
  if (!RunSweep(gantry.get(), spec, nullptr, &summary, &error)) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  std::printf("cup sweep: %d trials (%d run now) in %.1f s -> %s\n", summary.total, summary.ran,
              summary.wall_s, spec.out_csv.c_str());

  // The simulator: a path from one twin trial, replayed at several fidelities.
  TrialConfig c;
  c.law.step_mm = 5;
  const TrialResult trial = RunTrial(gantry.get(), c, true, &error);
  std::vector<SimCostRow> rows;
  const bool ok = RunSimCostTable(
      c, trial, SourceDir() + "/scenes/disk_replay.xml", SourceDir() + "/scenes/disk_benchmark.xml",
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
