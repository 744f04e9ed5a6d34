// ssc calibrate: fit the pneumatic model to the published disk results.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "calibration/pneumatic_fit.h"
#include "studies/dynamic_calibration.h"
#include "runtime/mujoco_model.h"

namespace ssc {

int RunCalibrateCommand(int argc, char** argv) {
  cli::Command cmd(
      "calibrate",
      "Fits the pneumatic model (pump free flow, port area, jet area, lip roughness; log scale,\n"
      "Nelder-Mead) to the published disk results: the offsets inside an edge where the mean\n"
      "vacuum is 40, 100, 200 Pa (0.7, 2.5, 3.2 mm), the differential at 100 Pa (~200 Pa), the\n"
      "cup in air (< 5 Pa) and on a plate (> 10 kPa). Prints residuals, fitted values and\n"
      "sensitivities; writes OUT/params.json and OUT/ssc_tool_calibrated.xml (the tool model with\n"
      "the fitted config; point a scene's <model file=...> at it).");
  double scale = 1, wander_step = 5;
  long seeds = 2, evals = 30;
  bool wander = false;
  std::string out_dir = "out/calibrate";
  cmd.Number("start-scale", &scale, "multiply the four starting values by this (tests the fit)",
             "", NumberRange::Closed(1e-3, 1e3));
  cmd.Flag("wander", &wander, "also fit sensor noise and lag to the published sigma_r and s_c vs "
                              "beta (disk trials; about a minute)");
  cmd.Number("wander-step", &wander_step, "step dL of the wander trials (not published)", "mm",
             NumberRange::Positive(100));
  cmd.Integer("wander-seeds", &seeds, "trials per beta per evaluation", NumberRange::Closed(1, 100));
  cmd.Integer("wander-evals", &evals, "Nelder-Mead evaluations for the wander fit",
              NumberRange::Closed(3, 10000));
  cmd.OutputDir("out", &out_dir, "output directory");
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  PneumaticModel start;
  start.pneumatics.pump_free_flow_m3_s *= scale;
  start.pneumatics.port_area_m2 *= scale;
  start.pneumatics.jet_area_m2 *= scale;
  start.geometry.lip_roughness_gap_m *= scale;
  const PneumaticFit fit = FitPublishedTargets(start);
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

  const std::filesystem::path out = out_dir;
  std::ofstream js(out / "params.json");
  js << "{\"cost\": " << fit.cost << ", \"parameters\": {";
  for (size_t i = 0; i < fit.parameters.size(); ++i) {
    js << (i ? ", " : "") << '"' << fit.parameters[i].key << "\": " << fit.parameters[i].value;
  }
  js << "}, \"targets\": {";
  for (size_t i = 0; i < fit.targets.size(); ++i) {
    js << (i ? ", " : "") << '"' << fit.targets[i].name << "\": {\"published\": "
       << fit.targets[i].target << ", \"model\": " << fit.targets[i].model << "}";
  }
  js << "}}\n";
  // The tool model with the fitted config.
  std::string config;
  char line[160];
  for (const FitParameter& q : fit.parameters) {
    std::snprintf(line, sizeof(line), "\n        <config key=\"%s\" value=\"%.6g\"/>", q.key.c_str(),
                  q.value);
    config += line;
  }
  std::string error;
  const std::string xml = ToolModelWithConfig(config + "\n      ", &error);
  if (xml.empty()) {
    std::fprintf(stderr, "ssc calibrate: %s\n", error.c_str());
    return 1;
  }
  std::ofstream(out / "ssc_tool_calibrated.xml") << xml;
  std::printf("wrote %s and %s\n", (out / "params.json").c_str(),
              (out / "ssc_tool_calibrated.xml").c_str());
  if (wander) {
    const double step = wander_step;
    WanderFit w;
    const std::vector<WanderTarget> targets = PublishedWanderTargets();
    if (!FitWander(SourceDir() + "/scenes/disk_benchmark_gantry.xml", (out / "wander").string(),
                   targets, step, static_cast<int>(seeds), static_cast<int>(evals), 6.0, 20.0, &w,
                   &error)) {
      std::fprintf(stderr, "ssc calibrate: %s\n", error.c_str());
      return 1;
    }
    std::printf("\nwander fit (dL %.1f mm, %ld seeds, %d evaluations): noise_pa %.3g, lag_ms %.3g, "
                "cost %.3g\n", step, seeds, w.evaluations, w.noise_pa, w.lag_ms, w.cost);
    std::printf("%6s %18s %18s\n", "beta", "sigma_r mm (pub)", "s_c (pub)");
    for (size_t i = 0; i < targets.size(); ++i) {
      std::printf("%6.1f %8.2f (%5s) %8.3f (%5.2f)\n", targets[i].beta, w.model[i].sigma_r_mm,
                  targets[i].sigma_r_mm >= 0 ? std::to_string(targets[i].sigma_r_mm).substr(0, 4).c_str() : "-",
                  w.model[i].s_c, targets[i].s_c);
    }
    // The calibrated tool model with the sensor chain's fit too.
    std::snprintf(line, sizeof(line),
                  "\n        <config key=\"noise_pa\" value=\"%.4g\"/>"
                  "\n        <config key=\"lag_ms\" value=\"%.4g\"/>", w.noise_pa, w.lag_ms);
    const std::string with_wander = ToolModelWithConfig(config + line + "\n      ", &error);
    std::ofstream(out / "ssc_tool_calibrated.xml") << with_wander;
    std::ofstream(out / "params.json", std::ios::app)
        << "{\"wander\": {\"noise_pa\": " << w.noise_pa << ", \"lag_ms\": " << w.lag_ms
        << ", \"cost\": " << w.cost << "}}\n";
    std::printf("updated %s with noise_pa and lag_ms\n", (out / "ssc_tool_calibrated.xml").c_str());
  }
  return 0;
}

}  // namespace ssc
