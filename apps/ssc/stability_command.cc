// ssc stability: for each integrator, the largest time step at which trials stay stable and
// their results unchanged within tolerance.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/trial_options.h"
#include "common/exit_codes.h"
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "runtime/trial.h"
#include "studies/stability_study.h"

namespace ssc {

namespace {

// The reference, then per integrator its rows and (when every trial finished) its largest step.
void PrintStabilityTable(const StabilityResult& result) {
  const StabilityRow& ref = result.reference;
  std::printf("reference (RK4, 0.5 ms): %s, r_mean %.2f mm, s %.1f mm\n", OutcomeName(ref.outcome),
              ref.r_mean_mm, ref.s_mm);
  std::printf("%-13s %8s %-11s %9s %8s %7s  stable unchanged\n", "integrator", "dt (ms)", "outcome",
              "r_mean", "s (mm)", "wall s");
  const std::vector<StabilityRow>& rows = result.rows;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const StabilityRow& r = rows[i];
    std::printf("%-13s %8.2f %-11s %9.2f %8.1f %7.2f  %-6s %s\n", r.integrator.c_str(),
                r.timestep_ms, OutcomeName(r.outcome), r.r_mean_mm, r.s_mm, r.wall_s,
                r.stable ? "yes" : "NO", r.unchanged ? "yes" : "no");
    if (i + 1 < rows.size() && rows[i + 1].integrator == r.integrator) continue;
    for (const auto& [name, largest_ms] : result.largest_unchanged_ms) {
      if (name != r.integrator) continue;
      if (std::isnan(largest_ms)) {
        std::printf("%s: no time step tried gave unchanged results\n", name.c_str());
      } else {
        std::printf("%s: largest time step with unchanged results: %.2f ms\n", name.c_str(),
                    largest_ms);
      }
    }
  }
}

}  // namespace

int RunStabilityCommand(int argc, char** argv) {
  cli::Command cmd(
      "stability",
      "Runs the same disk trial with every integrator over a range of time steps and\n"
      "reports, per integrator, the largest step at which the trial stays stable and its\n"
      "outcome, mean radius and path length stay within tolerance of a 0.5 ms RK4 reference.\n"
      "Writes OUT/stability.csv, and each trial as it finishes to OUT/stability_trials.csv:\n"
      "the same command run again resumes from it.");
  std::string scene_name = DefaultScene(), out_dir = "out/stability";
  std::vector<double> steps_ms = {0.5, 1, 2, 4, 8, 16};
  double dl = 5, dr_tol = 0.3, s_tol = 0.05;
  cmd.Text("scene", &scene_name, "scene");
  // Steps beyond the stable limit are the point of this study: allowed up to 100 ms.
  cmd.NumberList("steps-ms", &steps_ms, "time steps to try", "ms",
                 NumberRange::Closed(kSmallestTimestepS * 1e3, 100));
  cmd.Number("step", &dl, "controller step dL", "mm", NumberRange::Closed(kMinStepMm, kMaxStepMm));
  cmd.Number("dr-tol", &dr_tol, "tolerance on the mean radius", "mm", NumberRange::Closed(0, 100));
  cmd.Number("s-tol", &s_tol, "relative tolerance on the path length", "",
             NumberRange::Closed(0, 10));
  long threads = 2;
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory");
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  std::string error;
  ModelPtr base = LoadModel(ResolveScenePath(scene_name), &error);
  if (!base) {
    std::fprintf(stderr, "ssc stability: %s\n", error.c_str());
    cli::NoteInputError(error);
    return 1;
  }
  StabilitySpec spec;
  spec.config.law.step_mm = dl;
  spec.steps_ms = steps_ms;
  spec.dr_tol_mm = dr_tol;
  spec.s_tol = s_tol;
  spec.threads = static_cast<int>(threads);
  spec.scene_name = scene_name;
  spec.trials_csv = (std::filesystem::path(out_dir) / "stability_trials.csv").string();
  if (std::string e; !CheckTrialSetup(base.get(), spec.config, &e)) {
    std::fprintf(stderr, "ssc stability: %s: %s\n", scene_name.c_str(), e.c_str());
    cli::NoteExitCode(kExitBadData);  // a scene that loads but cannot hold this trial
    return 1;
  }
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const StabilityResult result = RunStabilityStudy(base.get(), spec);
  if (!result.error.empty()) {
    std::fprintf(stderr, "ssc stability: %s\n", result.error.c_str());
    return 1;
  }
  if (result.skipped > 0) {
    std::printf("%d of %d trials already in %s from an earlier run: kept, not run again\n",
                result.skipped, result.trials, spec.trials_csv.c_str());
  }
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "stability.csv";
  if (result.interrupted && result.reference.outcome == Outcome::kRunning) {
    std::fprintf(stderr,
                 "ssc stability: interrupted before the reference trial finished; no table "
                 "written (the finished trials are in %s: run the same command again to "
                 "resume)\n",
                 spec.trials_csv.c_str());
    return 130;
  }
  PrintStabilityTable(result);
  if (std::string e; !WriteWholeFile(csv.string(), StabilityCsv(result), &e)) {
    std::fprintf(stderr, "ssc stability: %s\n", e.c_str());
    return 1;
  }
  std::printf("wrote %s\n", csv.c_str());
  if (result.interrupted) {
    std::fprintf(stderr,
                 "ssc stability: interrupted after %zu of %d trials (the reference above, the "
                 "others in %s), without the largest steps (they need every trial; run the "
                 "same command again to resume)\n",
                 result.rows.size() + 1, result.trials, csv.c_str());
    return 130;
  }
  return 0;
}

}  // namespace ssc
