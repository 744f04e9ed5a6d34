// ssc calibrate: fit the pneumatic model to the published disk results. The fits live in
// studies/ (the static fit and its closed loop: loop_calibration, the sensor chain's wander:
// wander_fit, the loop and the robot effects: success_map_fit); this file parses and prints.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/trial_options.h"
#include "calibration/pneumatic_fit.h"
#include "common/output_file.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/loop_calibration.h"
#include "studies/success_map_fit.h"
#include "studies/sweep.h"
#include "studies/tool_variants.h"
#include "studies/validation.h"
#include "studies/wander_fit.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

int Fail(const std::string& error) {
  std::fprintf(stderr, "ssc calibrate: %s\n", error.c_str());
  return 1;
}

void PrintLine(const std::string& line) {
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

// Whole or not at all (common/output_file.h): a full disk leaves the previous file, never a
// partial one.
bool WriteText(const std::filesystem::path& path, const std::string& text) {
  std::string error;
  if (WriteWholeFile(path.string(), text, &error)) return true;
  std::fprintf(stderr, "ssc calibrate: %s\n", error.c_str());
  return false;
}

// A log of finished lines that survives an interrupted fit: each line is added by rewriting the
// whole file (a few kB; an evaluation takes seconds), so the file always holds every line
// finished so far and never a partial one. The first write error is kept for the end.
class FinishedLinesLog {
 public:
  explicit FinishedLinesLog(std::filesystem::path path) : path_(std::move(path)) {}
  void Add(const std::string& line) {
    text_ += line;
    text_ += '\n';
    if (error_.empty()) WriteWholeFile(path_.string(), text_, &error_);
  }
  const std::string& error() const { return error_; }

 private:
  std::filesystem::path path_;
  std::string text_, error_;
};

std::string DynamicKeysHelp() {
  std::string s;
  for (const auto& p : DynamicParameters())
    s += std::string(s.empty() ? "" : ", ") + p.key + " [" + std::to_string(p.min).substr(0, 4) +
         ", " + std::to_string(p.max).substr(0, 4) + "] " + p.unit;
  return "comma-separated parameters to fit (" + s + ")";
}

void PrintDynamicFit(const DynamicFitSpec& spec, const DynamicFitResult& fit) {
  std::printf("\ndynamic fit: %d evaluations, %.0f s; cost %.4g (start %.4g)\n", fit.evaluations,
              fit.wall_s, fit.cost, fit.start_cost);
  for (std::size_t i = 0; i < spec.keys.size(); ++i)
    std::printf("  %-16s %.4g\n", spec.keys[i].c_str(), fit.values[i]);
  std::printf("map (%d seeds/cell): class match %.1f %%, expected agreement %.3f, opposite %d\n",
              spec.seeds, 100 * fit.score.class_match, fit.score.expected_agreement,
              fit.score.opposite);
  std::printf("%-32s %10s %10s\n", "target", "published", "twin");
  for (const MetricTarget& t : fit.targets)
    std::printf("%-32s %10.3g %10.3g\n", t.name.c_str(), t.published, t.model);
}

// --dynamic: the loop and the robot effects against the success map (studies/success_map_fit).
int CalibrateDynamic(cli::Command& cmd, const DynamicFitSpec& spec, const std::string& scene,
                     std::uint64_t holdout_seed, const std::string& out_dir) {
  std::string error;
  ModelPtr model = LoadModel(ResolveScenePath(scene), &error);
  if (!model) {
    cli::NoteInputError(error);
    return Fail(error);
  }
  if (std::string e; !CheckTrialSetup(model.get(), spec.base, &e)) return Fail(e);
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const std::filesystem::path out = out_dir;
  FinishedLinesLog evals_log(out / "dynamic_evals.txt");
  DynamicFitResult fit;
  auto log_line = [&evals_log](const std::string& line) {
    PrintLine(line);
    evals_log.Add(line);
  };
  if (!FitDynamic(model.get(), spec, log_line, &fit, &error)) return Fail(error);
  if (!evals_log.error().empty()) return Fail(evals_log.error());
  PrintDynamicFit(spec, fit);
  if (holdout_seed > 0) {
    HeldOutScores held;
    if (!ScoreOnHeldOutSeeds(model.get(), spec, fit.best, holdout_seed, &held, &error))
      return Fail(error);
    char line[300];
    std::snprintf(line, sizeof(line),
                  "held-out seeds (base seed %llu, %d seeds/cell): start cost %.4g (agreement "
                  "%.3f, opposite %d), best cost %.4g (agreement %.3f, opposite %d)",
                  static_cast<unsigned long long>(held.seed), spec.seeds, held.start_cost,
                  held.start.expected_agreement, held.start.opposite, held.best_cost,
                  held.best.expected_agreement, held.best.opposite);
    std::printf("%s\n", line);
    evals_log.Add(line);
    if (!evals_log.error().empty()) return Fail(evals_log.error());
  }
  std::printf("as options: --period %.4g --smoothing %.4g --effects %s\n",
              fit.best.control_period_s, fit.best.servo.smoothing_s,
              FormatRobotEffects(fit.best.effects).c_str());
  return 0;
}

void PrintStaticFit(const PneumaticFit& fit) {
  std::printf("%-26s %10s %10s %9s\n", "target", "published", "model", "residual");
  for (const FitTarget& t : fit.targets) {
    std::printf("%-26s %10.3g %10.3g %9.2f  %s\n", t.name.c_str(), t.target, t.model, t.residual(),
                t.unit.c_str());
  }
  std::printf("\n%-22s %12s %14s\n", "parameter", "fitted", "d2cost/dlog2");
  for (const FitParameter& q : fit.parameters) {
    std::printf("%-22s %12.5g %14.3g\n", q.key.c_str(), q.value, q.sensitivity);
  }
  std::printf("cost %.4g after %d evaluations\n", fit.cost, fit.evaluations);
}

// --closed-loop N: the static fit whose loop rides at the published depths
// (studies/loop_calibration).
bool FitClosedLoop(const LoopCalibrationSpec& spec, PneumaticFit* fit, std::string* error) {
  LoopCalibrationResult loop;
  if (!CalibrateClosedLoop(spec, PrintLine, &loop, error)) return false;
  const LoopCalibrationIteration& best = loop.iterations[static_cast<std::size_t>(loop.best)];
  const StaticDepthPressures& depth_pa = best.depth_pa;
  *fit = best.fit;
  std::printf(
      "closed loop: iteration %d kept (rms depth error %.2f mm); static targets %.1f / "
      "%.1f / %.1f Pa at %.1f / %.1f / %.1f mm\n\n",
      loop.best + 1, loop.RmsDepthErrorMm(loop.best), depth_pa[0], depth_pa[1], depth_pa[2],
      kDepthTargetOffsetMm[0], kDepthTargetOffsetMm[1], kDepthTargetOffsetMm[2]);
  return true;
}

struct WanderOptions {
  bool on = false;
  double step_mm = 5;
  long seeds = 2, evals = 30;
};

// --wander: the sensor chain's noise and lag against the published wander (studies/wander_fit);
// rewrites the calibrated tool and params.json with them.
int CalibrateWander(const WanderOptions& o, const std::string& scene,
                    const RobotEffectsParams& effects, const ToolModelVariants& tool,
                    const PneumaticFit& fit, const std::filesystem::path& out) {
  std::string error;
  WanderFit w;
  const std::vector<WanderTarget> targets = PublishedWanderTargets();
  if (!FitWander(ResolveScenePath(scene), targets, o.step_mm, effects, static_cast<int>(o.seeds),
                 static_cast<int>(o.evals), 6.0, 20.0, &w, &error)) {
    return Fail(error);
  }
  std::printf(
      "\nwander fit (dL %.1f mm, %ld seeds, %d evaluations): noise_pa %.3g, lag_ms %.3g, "
      "cost %.3g\n",
      o.step_mm, o.seeds, w.evaluations, w.noise_pa, w.lag_ms, w.cost);
  std::printf("%6s %18s %18s\n", "beta", "sigma_r mm (pub)", "s_c (pub)");
  for (size_t i = 0; i < targets.size(); ++i) {
    std::printf("%6.1f %8.2f (%5s) %8.3f (%5.2f)\n", targets[i].beta, w.model[i].sigma_r_mm,
                targets[i].sigma_r_mm >= 0
                    ? std::to_string(targets[i].sigma_r_mm).substr(0, 4).c_str()
                    : "-",
                w.model[i].s_c, targets[i].s_c);
  }
  const std::string tuned = CalibratedToolXml(tool, fit, &w, &error);
  if (tuned.empty()) return Fail(error);
  if (!WriteText(out / "ssc_tool_calibrated.xml", tuned) ||
      !WriteText(out / "params.json", CalibrationParamsJson(fit, &w))) {
    return 1;
  }
  std::printf("updated %s with noise_pa and lag_ms\n", (out / "ssc_tool_calibrated.xml").c_str());
  return 0;
}

}  // namespace

int RunCalibrateCommand(int argc, char** argv) {
  cli::Command cmd(
      "calibrate",
      "Fits the pneumatic model (pump free flow, port area, jet area, lip roughness; log scale,\n"
      "Nelder-Mead) to the published disk results: the offsets inside an edge where the mean\n"
      "vacuum is 40, 100, 200 Pa (0.7, 2.5, 3.2 mm), the differential at 100 Pa (~200 Pa), the\n"
      "cup in air (< 5 Pa) and on a plate (> 10 kPa). Prints residuals, fitted values and\n"
      "sensitivities; writes OUT/params.json and OUT/ssc_tool_calibrated.xml (the tool model with\n"
      "the fitted config; point a scene's <model file=...> at it).");
  double scale = 1;
  WanderOptions wander;
  std::string out_dir = "out/calibrate";
  cmd.Number("start-scale", &scale, "multiply the four starting values by this (tests the fit)", "",
             NumberRange::Closed(1e-3, 1e3));
  cmd.Flag("wander", &wander.on,
           "also fit sensor noise and lag to the published sigma_r and s_c vs "
           "beta (disk trials; about a minute)");
  cmd.Number("wander-step", &wander.step_mm, "step dL of the wander trials (not published)", "mm",
             NumberRange::Closed(kMinStepMm, kMaxStepMm));
  cmd.Integer("wander-seeds", &wander.seeds, "trials per beta per evaluation",
              NumberRange::Closed(1, 100));
  cmd.Integer("wander-evals", &wander.evals, "Nelder-Mead evaluations for the wander fit",
              NumberRange::Closed(3, 10000));
  bool dynamic = false;
  long dyn_evals = 40, dyn_seeds = 3, dyn_threads = 2;
  std::string dyn_keys = "period_s,smoothing_s,pose_delay_s,tilt_decades,drift_relative";
  std::string dyn_algorithm = "bobyqa";
  std::string dyn_map = SourceDir() + "/data/published/success_map_dl5.csv";
  TrialConfig dyn_base;
  TrialSettings settings;
  cmd.Flag("dynamic", &dynamic,
           "fit the real loop and the robot effects (docs/fidelity.md) to the published success "
           "map at dL 5 mm and the Fig. 6 targets, on --scene; skips the static fit");
  cmd.Text("dynamic-keys", &dyn_keys, DynamicKeysHelp());
  cmd.Integer("dynamic-evals", &dyn_evals, "evaluation budget (each runs seeds x cells trials)",
              NumberRange::Closed(1, 100000));
  cmd.Integer("dynamic-seeds", &dyn_seeds, "trials per cell per evaluation (common seeds)",
              NumberRange::Closed(3, 1000));
  AddThreadsOption(&cmd, &dyn_threads);
  cmd.Choice("dynamic-algorithm", &dyn_algorithm, "NLopt algorithm", {"bobyqa", "sbplx"});
  cmd.Text("map", &dyn_map, "training map for --dynamic");
  long holdout_seed = 2;
  cmd.Integer("holdout-seed", &holdout_seed,
              "after --dynamic, score the start and the best point again on this base seed, which "
              "the fit never saw (a fit on common seeds also fits their noise); 0 = skip",
              NumberRange::Closed(0, 1e15));
  double dyn_weight = 0.02;
  cmd.Number("dynamic-metric-weight", &dyn_weight,
             "weight of the Fig. 6 targets against the map's log-loss", "",
             NumberRange::Closed(0, 100));
  std::string scene = DefaultScene();
  cmd.Text("scene", &scene,
           "disk scene for --dynamic, --closed-loop and --wander (name under scenes/ or a path; "
           "the default of every command unless given)");
  long loop_iterations = 0, loop_seeds = 10;
  cmd.Integer("closed-loop", &loop_iterations,
              "fit the static curve so that the twin's own loop (beta 1.5, dL 5 mm, --scene, "
              "--effects) rides at the published depths: this many iterations of static fit + "
              "loop trials (0 = the open-loop fit: the static probe reads P_ref there)",
              NumberRange::Closed(0, 50));
  cmd.Integer("closed-loop-seeds", &loop_seeds, "trials per P_ref per closed-loop iteration",
              NumberRange::Closed(1, 1000));
  std::vector<double> depth_list(kOpenLoopDepthPressures.begin(), kOpenLoopDepthPressures.end());
  cmd.NumberList("depth-pa", &depth_list,
                 "static mean vacuum the straight-edge probe must read at the published depths "
                 "0.7, 2.5, 3.2 mm (three values; the open-loop reading is P_ref there; "
                 "--closed-loop finds them)",
                 "Pa", NumberRange::Positive(1e5));
  cmd.OutputDir("out", &out_dir, "output directory");
  AddTrialSettingOptions(&cmd, &dyn_base, &settings);
  std::vector<std::string> keys;
  cmd.Check([&]() -> std::string {
    if (depth_list.size() != 3) return "--depth-pa: three values (Pa at 0.7, 2.5, 3.2 mm)";
    if (loop_iterations > 0 && cmd.Given("depth-pa"))
      return "--depth-pa and --closed-loop: give one (--closed-loop finds the pressures)";
    if (!(depth_list[0] < depth_list[1] && depth_list[1] < depth_list[2]))
      return "--depth-pa: the values must rise with depth (the covered cup reads more vacuum)";
    if (!dynamic) return "";
    std::string e;
    if (!ParseNameList(dyn_keys, &keys, &e)) return "--dynamic-keys: " + e;
    e = CheckDynamicKeys(keys);
    return e.empty() ? "" : "--dynamic-keys: " + e;
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  if (dynamic) {
    DynamicFitSpec spec;
    spec.base = dyn_base;
    if (std::string error; !ReadDynamicFitCells(dyn_map, &spec.cells, &error)) return Fail(error);
    spec.keys = keys;
    spec.seeds = static_cast<int>(dyn_seeds);
    spec.threads = static_cast<int>(dyn_threads);
    spec.max_evaluations = static_cast<int>(dyn_evals);
    spec.algorithm = dyn_algorithm;
    spec.metric_weight = dyn_weight;
    return CalibrateDynamic(cmd, spec, scene, static_cast<std::uint64_t>(holdout_seed), out_dir);
  }
  // The tool model the fitted config goes into, read before any output is made.
  std::string error;
  const auto tool = ToolModelVariants::Read(SourceDir() + "/models/ssc_tool.xml", &error);
  if (!tool) return Fail(error);
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const std::filesystem::path out = out_dir;
  const PneumaticModel start = ScaledFitStart(scale);
  PneumaticFit fit;
  if (loop_iterations > 0) {
    LoopCalibrationSpec spec;
    spec.start = start;
    spec.scene_path = ResolveScenePath(scene);
    spec.base = dyn_base;
    spec.seeds = static_cast<int>(loop_seeds);
    spec.iterations = static_cast<int>(loop_iterations);
    spec.threads = static_cast<int>(dyn_threads);
    if (!FitClosedLoop(spec, &fit, &error)) return Fail(error);
  } else {
    fit = FitPublishedTargets(start, {depth_list[0], depth_list[1], depth_list[2]});
  }
  PrintStaticFit(fit);
  if (!WriteText(out / "params.json", CalibrationParamsJson(fit, nullptr))) return 1;
  const std::string xml = CalibratedToolXml(*tool, fit, nullptr, &error);
  if (xml.empty()) return Fail(error);
  if (!WriteText(out / "ssc_tool_calibrated.xml", xml)) return 1;
  std::printf("wrote %s and %s\n", (out / "params.json").c_str(),
              (out / "ssc_tool_calibrated.xml").c_str());
  if (wander.on) return CalibrateWander(wander, scene, dyn_base.effects, *tool, fit, out);
  return 0;
}

}  // namespace ssc
