// ssc objects: write every test object's scenes and run the contour-following trial on each.
#include <cstdio>
#include <filesystem>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "runtime/rig.h"
#include "studies/object_study.h"
#include "studies/object_trials.h"

namespace ssc {

int RunObjectsCommand(int argc, char** argv) {
  cli::Command cmd(
      "objects",
      "Writes the scenes of the published test objects (disks and holes 2-14 mm, the 35 mm\n"
      "disk, corners every 15 deg, volute, semicircle and semi-square strips, variable fillet)\n"
      "and runs the contour-following trial on each; writes OUT/objects.csv (one row per\n"
      "object and seed), OUT/fillet_profile.csv and OUT/objects.png. The same command run\n"
      "again resumes: the trials whose rows are in OUT/objects.csv are not run again.");
  // The objects' tier when none is named: the default scene's kind, as ssc view takes it.
  std::string names = "all", out_dir = "out/objects";
  std::string kind = ObjectSceneKindName(ObjectSceneKindOfTier(RigTierFor(RigUse::kTrial)));
  long seeds = 1, threads = std::max(1u, std::thread::hardware_concurrency());
  std::uint64_t seed = 1;
  ContourLawParams law;
  law.step_mm = 0.5;
  bool write_only = false, no_plot = false;
  cmd.Text("objects", &names,
           "comma-separated object names (e.g. disk_d06,hole_d10,corner_a090) or all");
  cmd.Integer("seeds", &seeds, "trials per object (seeds base, base+1, ...)",
              NumberRange::Closed(1, 1000));
  cmd.Seed("seed", &seed, "base seed");
  cmd.Choice("scene-kind", &kind,
             "'gantry' (light, for tables), 'arm' (the UR-10 scenes), 'flex' (the gantry with "
             "the deformable skirt lip) or 'auto' (per object and step: flex where the two tiers "
             "disagree, gantry where they agree; docs/flex_objects.md)",
             {"gantry", "arm", "flex", "auto"});
  AddLawOptions(&cmd, &law);
  ObjectStudySpec spec;
  std::string effects_text = "default";
  AddEffectsOption(&cmd, "robot effects (docs/fidelity.md)", &effects_text, &spec.effects);
  std::string controller_name = "published", controller_params;
  AddControllerOptions(&cmd, &controller_name, &controller_params, &spec.controller);
  cmd.Number("stall-mm", &spec.stall.stall_mm,
             "stalled: the furthest point reached along the edge moves on by no more than this "
             "over --stall-window",
             "mm", NumberRange::Positive(1000));
  cmd.Number("stall-window", &spec.stall.window_s,
             "the stall rule's window, simulated (0: off, such a trial runs to its time limit)",
             "s", NumberRange::Closed(0, 3600));
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory (scenes in OUT/scenes)");
  cmd.Flag("write-only", &write_only, "only write the scenes");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Check([&law]() { return law.Validate(); });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  if (std::string e; !ObjectsByNames(names, &spec.objects, &e)) return cmd.Fail("--objects: " + e);
  spec.seeds = static_cast<int>(seeds);
  spec.seed = seed;
  if (std::string e; !ObjectSceneKindByName(kind, &spec.scene_kind, &e)) return cmd.Fail(e);
  spec.law = law;
  spec.threads = static_cast<int>(threads);
  spec.out_dir = out_dir;
  spec.write_only = write_only;
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  ObjectStudySummary summary;
  std::string error;
  const bool ok = RunObjectStudy(
      spec,
      [](const std::string& line) {
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
      },
      &summary, &error);
  if (!ok) {
    std::fprintf(stderr, "ssc objects: %s\n", error.c_str());
    return 1;
  }
  const std::filesystem::path out = out_dir;
  std::printf("wrote %zu objects' scenes into %s\n", spec.objects.size(), (out / "scenes").c_str());
  if (write_only) return 0;
  if (summary.skipped > 0) {
    std::printf("%d of %d trials already in %s from an earlier run: kept, not run again\n",
                summary.skipped, summary.trials, summary.table_csv.c_str());
  }
  if (summary.interrupted) {
    std::fprintf(stderr,
                 "ssc objects: interrupted; %d of %d trials finished, their rows are in %s (run "
                 "the same command again to resume)\n",
                 summary.finished, summary.trials, summary.table_csv.c_str());
    return 130;
  }
  std::printf("wrote %s\n", summary.table_csv.c_str());
  if (!summary.fillet_line.empty()) {
    std::printf("%s; wrote %s\n", summary.fillet_line.c_str(), summary.fillet_profile_csv.c_str());
  }
  if (!no_plot) {
    const std::string png = (out / "objects.png").string();
    if (RunPlotScript("plot_objects.py", {summary.table_csv, summary.paths_dir, png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
