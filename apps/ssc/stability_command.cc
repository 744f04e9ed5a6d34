// ssc stability: for each integrator, the largest time step at which trials stay stable and
// their results unchanged within tolerance.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "runtime/mujoco_model.h"
#include "runtime/trial.h"

namespace ssc {

int RunStabilityCommand(int argc, char** argv) {
  cli::Command cmd("stability",
                   "Runs the same disk trial with every integrator over a range of time steps and\n"
                   "reports, per integrator, the largest step at which the trial stays stable and its\n"
                   "outcome, mean radius and path length stay within tolerance of a 0.5 ms RK4 reference.\n"
                   "Writes OUT/stability.csv.");
  std::string scene_name = "disk_benchmark_gantry", out_dir = "out/stability";
  std::vector<double> steps_ms = {0.5, 1, 2, 4, 8, 16};
  double dl = 5, dr_tol = 0.3, s_tol = 0.05;
  cmd.Text("scene", &scene_name, "scene");
  // Steps beyond the stable limit are the point of this study: allowed up to 100 ms.
  cmd.NumberList("steps-ms", &steps_ms, "time steps to try", "ms", NumberRange::Positive(100));
  cmd.Number("step", &dl, "controller step dL", "mm", NumberRange::Positive(100));
  cmd.Number("dr-tol", &dr_tol, "tolerance on the mean radius", "mm", NumberRange::Closed(0, 100));
  cmd.Number("s-tol", &s_tol, "relative tolerance on the path length", "",
             NumberRange::Closed(0, 10));
  cmd.OutputDir("out", &out_dir, "output directory");
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  std::string error;
  ModelPtr base = LoadModel(ResolveScenePath(scene_name), &error);
  if (!base) {
    std::fprintf(stderr, "ssc stability: %s\n", error.c_str());
    return 1;
  }
  TrialConfig config;
  config.law.step_mm = dl;
  auto run = [&](int integrator, double dt) {
    mjModel* m = mj_copyModel(nullptr, base.get());
    m->opt.integrator = integrator;
    m->opt.timestep = dt;
    std::string e;
    TrialResult r = RunTrial(m, config, false, &e);
    mj_deleteModel(m);
    return r;
  };
  const TrialResult ref = run(mjINT_RK4, 0.0005);
  std::printf("reference (RK4, 0.5 ms): %s, r_mean %.2f mm, s %.1f mm\n", OutcomeName(ref.outcome),
              ref.metrics.r_mean_mm, ref.metrics.s_mm);
  const std::filesystem::path out = out_dir;
  std::ofstream csv(out / "stability.csv");
  if (!csv) {
    std::fprintf(stderr, "ssc stability: cannot write %s\n", (out / "stability.csv").c_str());
    return 1;
  }
  csv << "integrator,timestep_ms,outcome,r_mean_mm,s_mm,wall_s,stable,unchanged\n";
  const struct {
    int id;
    const char* name;
  } integrators[] = {{mjINT_EULER, "Euler"},
                     {mjINT_RK4, "RK4"},
                     {mjINT_IMPLICIT, "implicit"},
                     {mjINT_IMPLICITFAST, "implicitfast"}};
  std::printf("%-13s %8s %-11s %9s %8s %7s  stable unchanged\n", "integrator", "dt (ms)",
              "outcome", "r_mean", "s (mm)", "wall s");
  for (const auto& in : integrators) {
    double largest_ok = 0;
    for (double ms : steps_ms) {
      const TrialResult r = run(in.id, ms * 1e-3);
      const bool stable = r.outcome != Outcome::kUnstable;
      const bool unchanged = stable && r.outcome == ref.outcome &&
                             std::fabs(r.metrics.r_mean_mm - ref.metrics.r_mean_mm) <= dr_tol &&
                             std::fabs(r.metrics.s_mm - ref.metrics.s_mm) <= s_tol * ref.metrics.s_mm;
      if (unchanged) largest_ok = std::max(largest_ok, ms);
      std::printf("%-13s %8.2f %-11s %9.2f %8.1f %7.2f  %-6s %s\n", in.name, ms, OutcomeName(r.outcome),
                  r.metrics.r_mean_mm, r.metrics.s_mm, r.wall_time_s, stable ? "yes" : "NO",
                  unchanged ? "yes" : "no");
      csv << in.name << ',' << ms << ',' << OutcomeName(r.outcome) << ',' << r.metrics.r_mean_mm << ','
          << r.metrics.s_mm << ',' << r.wall_time_s << ',' << stable << ',' << unchanged << '\n';
    }
    std::printf("%s: largest time step with unchanged results: %.2f ms\n", in.name, largest_ok);
  }
  std::printf("wrote %s\n", (out / "stability.csv").c_str());
  return 0;
}

}  // namespace ssc
