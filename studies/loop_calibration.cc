#include "studies/loop_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "studies/validation.h"

namespace ssc {
namespace {
constexpr double kMaxStaticCost = 4.0;
}  // namespace

PluginConfig FittedPluginConfig(const PneumaticFit& fit) {
  PluginConfig config;
  char value[32];
  for (const FitParameter& p : fit.parameters) {
    std::snprintf(value, sizeof(value), "%.6g", p.value);
    config[p.key] = value;
  }
  return config;
}

double LoopCalibrationResult::RmsDepthErrorMm(int i) const {
  const LoopCalibrationIteration& it = iterations.at(static_cast<std::size_t>(i));
  double s = 0;
  for (int k = 0; k < 3; ++k) s += std::pow(-it.loop_dr_mm[k] - kDepthTargetOffsetMm[k], 2);
  return std::sqrt(s / 3);
}

bool CalibrateClosedLoop(const LoopCalibrationSpec& spec,
                         const std::function<void(const std::string&)>& progress,
                         LoopCalibrationResult* result, std::string* error) {
  const auto variants = ToolModelVariants::Read(spec.scene_path, error);
  if (!variants) return false;
  std::vector<MapCell> cells;
  for (double p : kDepthTargetPrefPa) cells.push_back({5.0, 1.5, p, MapClass::kThreeOfThree});
  result->iterations.clear();
  StaticDepthPressures q = kOpenLoopDepthPressures;
  PneumaticModel start = spec.start;
  for (int it = 0; it < std::max(1, spec.iterations); ++it) {
    LoopCalibrationIteration step;
    step.depth_pa = q;
    step.fit = FitPublishedTargets(start, q);
    ModelPtr m = variants->Compile({FittedPluginConfig(step.fit), 0}, error);
    if (!m) return false;
    std::vector<std::vector<MapTrial>> trials;
    if (!RunMapTrials(m.get(), cells, spec.base, spec.seeds, 1, spec.threads, &trials, error)) {
      return false;
    }
    for (int k = 0; k < 3; ++k) {
      double sum_ok = 0, sum_all = 0;
      int ok = 0;
      for (const MapTrial& t : trials[static_cast<std::size_t>(k)]) {
        sum_all += t.dr_mm;
        if (t.outcome == "success") {
          sum_ok += t.dr_mm;
          ++ok;
        }
      }
      step.loop_successes[k] = ok;
      step.loop_dr_mm[k] = ok > 0 ? sum_ok / ok : sum_all / std::max(1, spec.seeds);
    }
    result->iterations.push_back(step);
    const int i = static_cast<int>(result->iterations.size()) - 1;
    if (step.fit.cost <= kMaxStaticCost &&
        result->RmsDepthErrorMm(i) < result->RmsDepthErrorMm(result->best)) {
      result->best = i;
    }
    char line[400];
    std::snprintf(line, sizeof(line),
                  "iteration %d: static targets %.1f / %.1f / %.1f Pa (static fit cost %.3g); "
                  "loop dr %.2f / %.2f / %.2f mm (successes %d/%d/%d of %d); rms %.2f mm",
                  i + 1, q[0], q[1], q[2], step.fit.cost, step.loop_dr_mm[0], step.loop_dr_mm[1],
                  step.loop_dr_mm[2], step.loop_successes[0], step.loop_successes[1],
                  step.loop_successes[2], spec.seeds, result->RmsDepthErrorMm(i));
    if (progress) progress(line);
    // A static curve the pneumatic model cannot draw (cost well above the open-loop fit's ~0.4):
    // the loop's depths are out of this model's reach; keep the best iteration so far.
    if (step.fit.cost > kMaxStaticCost) {
      if (progress)
        progress("static fit cost above " + std::to_string(kMaxStaticCost).substr(0, 3) +
                 ": the pneumatic model cannot draw that curve; stopping");
      break;
    }
    q = NextDepthPressures(step.fit.model, q, step.loop_dr_mm);
    start = step.fit.model;  // warm start
  }
  return true;
}

}  // namespace ssc
