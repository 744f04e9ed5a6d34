#include "studies/wander_fit.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "calibration/nelder_mead.h"
#include "calibration/published_targets.h"
#include "runtime/guarded_trial.h"
#include "runtime/mujoco_model.h"
#include "runtime/trial.h"
#include "studies/loop_calibration.h"
#include "studies/tool_variants.h"

namespace ssc {

std::vector<WanderTarget> PublishedWanderTargets() {
  std::vector<WanderTarget> targets;
  for (const PublishedWander& w : kPublishedWander)
    targets.push_back({w.beta, w.sigma_r_mm, w.s_c});
  return targets;
}

bool FitWander(const std::string& scene, const std::vector<WanderTarget>& targets, double step_mm,
               const RobotEffectsParams& effects, int seeds, int max_evaluations, double noise0,
               double lag0, WanderFit* fit, std::string* error) {
  const auto variants = ToolModelVariants::Read(scene, error);
  if (!variants) return false;
  bool failed = false;
  std::vector<WanderTarget> last;
  auto text = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.6g", v);
    return std::string(buf);
  };
  auto evaluate = [&](double noise, double lag, std::vector<WanderTarget>* model) {
    ModelPtr m = variants->Compile({{{"noise_pa", text(noise)}, {"lag_ms", text(lag)}}, 0}, error);
    if (!m) {
      failed = true;
      return 1e300;
    }
    double cost = 0;
    model->clear();
    for (const WanderTarget& t : targets) {
      double sigma = 0, sc = 0;
      for (int k = 0; k < seeds; ++k) {
        TrialConfig c;
        c.law.beta = t.beta;
        c.law.step_mm = step_mm;
        c.effects = effects;
        c.seed = static_cast<std::uint64_t>(k + 1);
        const TrialResult r = RunGuardedTrial(m.get(), c);
        sigma += r.metrics.sigma_r_mm / seeds;
        sc += r.metrics.s_c / seeds;
      }
      model->push_back({t.beta, sigma, sc});
      if (t.sigma_r_mm >= 0) cost += std::pow((sigma - t.sigma_r_mm) / 0.2, 2);
      if (t.s_c >= -1) cost += std::pow((sc - t.s_c) / 0.05, 2);
    }
    return cost;
  };
  auto f = [&](const std::vector<double>& x) {
    return evaluate(std::exp(x[0]), std::exp(x[1]) - 1, &last);
  };
  const NelderMeadResult r =
      NelderMead(f, {std::log(noise0), std::log(lag0 + 1)}, {0.7, 0.7}, 1e-4, max_evaluations);
  if (failed) return false;
  fit->noise_pa = std::exp(r.x[0]);
  fit->lag_ms = std::exp(r.x[1]) - 1;
  fit->evaluations = r.evaluations;
  fit->cost = evaluate(fit->noise_pa, fit->lag_ms, &fit->model);
  return !failed;
}

std::string CalibrationParamsJson(const PneumaticFit& fit, const WanderFit* wander) {
  nlohmann::ordered_json j;
  j["cost"] = fit.cost;
  j["parameters"] = nlohmann::ordered_json::object();
  for (const FitParameter& q : fit.parameters) j["parameters"][q.key] = q.value;
  j["targets"] = nlohmann::ordered_json::object();
  for (const FitTarget& t : fit.targets) {
    j["targets"][t.name] = {{"published", t.target}, {"model", t.model}};
  }
  if (wander) {
    j["wander"] = {
        {"noise_pa", wander->noise_pa}, {"lag_ms", wander->lag_ms}, {"cost", wander->cost}};
  }
  return j.dump(2) + "\n";
}

std::string CalibratedToolXml(const ToolModelVariants& tool, const PneumaticFit& fit,
                              const WanderFit* wander, std::string* error) {
  PluginConfig config = FittedPluginConfig(fit);
  if (wander) {
    char value[32];
    std::snprintf(value, sizeof(value), "%.4g", wander->noise_pa);
    config["noise_pa"] = value;
    std::snprintf(value, sizeof(value), "%.4g", wander->lag_ms);
    config["lag_ms"] = value;
  }
  return tool.ToolXml({config, 0}, error);
}

}  // namespace ssc
