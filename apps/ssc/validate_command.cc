// ssc validate: the twin on every cell of a published success map, scored.

#include <algorithm>
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
#include "studies/success_map_fit.h"
#include "studies/validation.h"

namespace ssc {

int RunValidateCommand(int argc, char** argv) {
  cli::Command cmd("validate",
                   "Runs the twin on every cell of a published success map (N seeds per cell)\n"
                   "and scores it: class match with 3 trials per cell, expected agreement,\n"
                   "opposite cells, failure modes. Writes OUT/trials.csv (resumable),\n"
                   "OUT/cells.csv, OUT/validate.json and OUT/validate.png. Reports figures;\n"
                   "it does not pass or fail.");
  ValidateSpec spec;
  spec.map_path = SourceDir() + "/data/published/success_map_dl5.csv";
  spec.scene_name = DefaultScene();
  long seeds = 10, threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "out/validate";
  bool no_plot = false, no_progress = false, no_shared_approach = false;
  TrialSettings settings;
  cmd.Text("map", &spec.map_path, "published map CSV (step_mm,beta,pref_pa,successes_of_3)");
  cmd.Text("scene", &spec.scene_name, "scene (name under scenes/ or a path)");
  cmd.Integer("seeds", &seeds, "trials per cell (the first 3 give the class match)",
              NumberRange::Closed(3, 10000));
  cmd.Seed("seed", &spec.seed, "base seed, as ssc sweep --seed");
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory");
  cmd.Flag("no-plot", &no_plot, "skip the PNG figure");
  cmd.Flag("no-progress", &no_progress,
           "no progress (a bar on a terminal, a line per 5 % of the trials otherwise)");
  cmd.Flag("no-shared-approach", &no_shared_approach,
           "simulate every trial's approach itself (as ssc sweep --no-shared-approach)");
  AddControllerOptions(&cmd, &settings.controller, &settings.controller_params,
                       &spec.base.controller);
  AddTrialSettingOptions(&cmd, &spec.base, &settings);
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  spec.seeds = static_cast<int>(seeds);
  spec.threads = static_cast<int>(threads);
  spec.out_dir = out_dir;
  spec.share_approach = !no_shared_approach;

  // Every input before any output: the map and each cell's trial, then the scene.
  std::string error;
  std::vector<MapCell> cells;
  SweepSpec sweep;
  if (!PrepareValidation(spec, &cells, &sweep, &error)) {
    std::fprintf(stderr, "ssc validate: %s\n", error.c_str());
    cli::NoteInputError(error);
    return 1;
  }
  const std::string scene = ResolveScenePath(spec.scene_name);
  TrialConfig first = sweep.base;
  first.law.p_ref_pa = cells.front().pref_pa;
  first.law.beta = cells.front().beta;
  first.law.step_mm = cells.front().step_mm;
  ModelPtr model = LoadTrialScene(cmd, scene, first);
  if (!model) return 1;
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const bool rank0 = JobRunnerRank() == 0;
  TrialProgress progress("ssc validate", rank0 && !no_progress);
  MapScore score;
  SweepSummary summary;
  std::vector<MetricTarget> fig6;
  MapCeilings ceilings;
  if (!RunValidation(model.get(), spec, std::ref(progress), &score, &summary, &error, &fig6,
                     &ceilings)) {
    std::fprintf(stderr, "ssc validate: %s\n", error.c_str());
    return 1;
  }
  progress.Finish();
  if (!rank0) return 0;
  std::printf("%-6s %-5s %-7s %-9s %-6s %-9s %-8s %-8s %s\n", "dL_mm", "beta", "Pref_Pa",
              "published", "twin3", "p(N)", "P(class)", "surface", "failures");
  for (const CellScore& c : score.cells) {
    char surface[16] = "-";  // the smooth surface's rate, where one was fitted
    if (!std::isnan(c.surface_p)) std::snprintf(surface, sizeof surface, "%.2f", c.surface_p);
    std::printf("%-6g %-5g %-7g %-9s %-6s %2d/%-6d %-8.2f %-8s %s%s\n", c.cell.step_mm, c.cell.beta,
                c.cell.pref_pa, MapClassName(c.cell.published), MapClassName(c.twin_class),
                c.successes, c.trials, c.expected_agreement, surface, c.main_failure.c_str(),
                c.opposite ? "  OPPOSITE" : "");
  }
  std::printf("\n%d cells, %d seeds per cell (base seed %llu), %d trials run in %.1f s:\n",
              score.cells_scored, spec.seeds, static_cast<unsigned long long>(spec.seed),
              summary.ran, summary.wall_s);
  std::printf("  class match (3 trials/cell)   %.1f %%\n", 100 * score.class_match);
  std::printf("  expected agreement            %.3f (95 %% interval from the seeds %.3f-%.3f)\n",
              score.expected_agreement, score.agreement_interval[0], score.agreement_interval[1]);
  if (const std::string note = AgreementIntervalNote(score); !note.empty()) {
    std::printf("                                (%s)\n", note.c_str());
  }
  std::printf("  opposite cells                %d\n", score.opposite);
  std::printf(
      "what any twin can expect here (each published class is one draw of 3 robot trials;\n"
      "docs/fidelity.md, 'The ceiling'), by the prior on the robot's success rates:\n");
  std::printf("  %-46s %-8s %-8s %s\n", "prior", "re-run", "oracle",
              "P(class match >= goal) re-run / oracle");
  for (const MapCeiling& c : ceilings.priors) {
    char name[96];
    std::snprintf(name, sizeof name, "%s, Beta(%.2f, %.2f)", c.prior_name.c_str(), c.prior.a,
                  c.prior.b);
    std::printf("  %-46s %-8.3f %-8.3f %.3f / %.3f (goal %.0f %%)\n", name, c.rerun_agreement,
                c.oracle_agreement, c.rerun_reaches_goal, c.oracle_reaches_goal,
                100 * kClassMatchGoal);
  }
  for (const SurfaceCeiling& s : ceilings.surfaces) {
    if (!s.fitted) continue;
    char name[96];
    std::snprintf(name, sizeof name, "a smooth surface at dL %g mm (in sample)", s.step_mm);
    std::printf("  %-46s %-8.3f %-8.3f %.3f / %.3f\n", name, s.rerun_agreement, s.oracle_agreement,
                s.rerun_reaches_goal, s.oracle_reaches_goal);
    std::printf("  that surface fitted to the other cells predicts each at %.3f (leave-one-out)\n",
                s.loo_agreement);
  }
  bool header = false;
  for (const MetricTarget& t : fig6) {
    if (t.successes == 0) continue;  // its cell is not in this map, or never succeeded
    if (!header) {
      std::printf(
          "published Fig. 6 targets (mean over the successful trials +- its standard error):\n");
      header = true;
    }
    std::printf("  %-32s twin %7.3g +- %-7.2g (%2d trials)  published %7.3g  (tolerance %g)\n",
                t.name.c_str(), t.model, t.standard_error, t.successes, t.published, t.tolerance);
  }
  PrintApproachSharing(spec.share_approach, summary);
  std::printf("wrote %s/cells.csv, %s/validate.json\n", out_dir.c_str(), out_dir.c_str());
  if (!no_plot) {
    const std::string png = out_dir + "/validate.png";
    if (RunPlotScript("plot_validation.py", {out_dir + "/cells.csv", png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
