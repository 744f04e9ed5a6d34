// ssc tune: NLopt searches a controller's parameters on the twin for speed at a success rate;
// every evaluation in tune.csv, the speed-success chart in pareto.png (studies/controller_tune.h).

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/controller_tune.h"

namespace ssc {
namespace {

// The search when none is given, for the controllers that have one.
std::string DefaultSearch(const std::string& controller) {
  if (controller == "fast") return "step_max_mm=7.5:14,step_min_mm=3:10,strength_pa=0:300";
  if (controller == "published") return "pref_pa=60:200,beta=1:4,step_mm=4:10";
  return "";
}

}  // namespace

int RunTuneCommand(int argc, char** argv) {
  cli::Command cmd("tune",
                   "Searches a controller's parameters on the twin (NLopt, derivative-free) for "
                   "the highest\nmean follow speed on the disk at a success rate: each "
                   "evaluation runs the same seeds\nwith the robot effects on. Writes "
                   "OUT/tune.csv (every evaluation and the reference\ncontrollers, with 95 % "
                   "intervals and the Pareto front) and OUT/pareto.png.");
  TuneSpec spec;
  spec.sweep.scene_name = DefaultScene();
  spec.sweep.base.law.p_ref_pa = 100;
  spec.sweep.base.law.beta = 2;
  spec.sweep.base.law.step_mm = 7.5;
  std::string search, references = "published", out_dir = "out/tune";
  long seeds = spec.seeds, evaluations = spec.evaluations, threads = 2;
  bool no_plot = false;
  TrialSettings settings;
  cmd.Text("scene", &spec.sweep.scene_name, "scene (name under scenes/ or a path)");
  AddLawOptions(&cmd, &spec.sweep.base.law);
  AddControllerOptions(&cmd, &settings.controller, &settings.controller_params,
                       &spec.sweep.base.controller);
  cmd.Text("search", &search,
           "the keys searched, key=lo:hi,... (the controller's keys and the law's pref_pa, "
           "beta, step_mm); default for fast: " +
               DefaultSearch("fast") + "; for published: " + DefaultSearch("published"));
  cmd.Seed("seed", &spec.sweep.seed, "base seed of the trials");
  cmd.Integer("seeds", &seeds, "trials per evaluation (the same seeds at every point)",
              NumberRange::Closed(1, 1000));
  cmd.Integer("evals", &evaluations, "evaluations of the search (its budget)",
              NumberRange::Closed(1, 1000));
  cmd.Number("min-success", &spec.min_success,
             "success rate to keep: each 1 % below it costs 10 mm/s of score", "",
             NumberRange::Closed(0, 1));
  cmd.Choice("algorithm", &spec.algorithm, "NLopt's derivative-free algorithm",
             {"bobyqa", "sbplx", "cobyla"});
  cmd.Text("reference", &references,
           "controllers run on the same seeds at their defaults and drawn on the chart "
           "(comma-separated names, or 'none')");
  cmd.OutputDir("out", &out_dir, "output directory (tune.csv, pareto.png, evals/)");
  cmd.Flag("no-plot", &no_plot, "skip the PNG chart");
  AddThreadsOption(&cmd, &threads);
  AddTrialSettingOptions(&cmd, &spec.sweep.base, &settings);
  cmd.Check([&]() -> std::string {
    const ControllerType* type = FindControllerType(settings.controller);
    if (!type) return "";  // AddControllerOptions' check names it
    if (search.empty()) search = DefaultSearch(settings.controller);
    if (search.empty()) {
      return "--search: give the keys to search for controller '" + settings.controller +
             "' (key=lo:hi,...)";
    }
    std::string error;
    if (!ParseTuneSearch(*type, search, &spec.keys, &error)) return "--search: " + error;
    // AddControllerOptions' check, registered earlier, has set the base controller's values.
    if (error = CheckTuneBox(spec.keys, spec.sweep.base.controller); !error.empty())
      return "--search: " + error;
    spec.references.clear();
    if (references != "none") {
      std::stringstream names(references);
      std::string name;
      while (std::getline(names, name, ',')) {
        TrialConfig c = spec.sweep.base;
        if (!ParseControllerChoice(name, "", &c.controller, &error)) return "--reference: " + error;
        spec.references.push_back({name, c});
      }
    }
    return "";
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  spec.seeds = static_cast<int>(seeds);
  spec.evaluations = static_cast<int>(evaluations);
  spec.sweep.threads = static_cast<int>(threads);
  spec.out_dir = out_dir;
  const std::string scene = ResolveScenePath(spec.sweep.scene_name);
  ModelPtr model = LoadTrialScene(cmd, scene, spec.sweep.base);
  if (!model) return 1;
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  TuneResult result;
  std::string error;
  auto log = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  if (!RunTune(model.get(), spec, log, &result, &error)) {
    std::fprintf(stderr, "ssc tune: %s\n", error.c_str());
    return 1;
  }
  const std::filesystem::path out = out_dir;
  std::printf("tune: %zu evaluations x %d seeds in %.1f s wall; wrote %s\n",
              result.evaluations.size(), spec.seeds, result.wall_s,
              (out / "tune.csv").string().c_str());
  if (result.refused > 0) {
    std::printf(
        "refused: %d of the search's points broke a rule between the controller's keys (not "
        "run, scored as infeasible; outcome in tune.csv)\n",
        result.refused);
  }
  if (result.best >= 0) {
    const TuneEvaluation& b = result.evaluations[static_cast<std::size_t>(result.best)];
    std::printf("best score: %s, %d/%d success, %.1f mm/s: %s\n", b.label.c_str(), b.successes,
                b.trials, b.speed_mm_s, b.controller.c_str());
  }
  if (!no_plot) {
    const std::string png = (out / "pareto.png").string();
    std::ostringstream target;
    target << spec.min_success;
    if (RunPlotScript("plot_tune.py", {(out / "tune.csv").string(), png, target.str()})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
