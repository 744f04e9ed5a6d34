#include "studies/success_map_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <sstream>

#include "calibration/published_targets.h"
#include "studies/unit_box_search.h"
#include "studies/validation.h"

namespace ssc {

const std::vector<DynamicParameter>& DynamicParameters() {
  static const std::vector<DynamicParameter> kParams = [] {
    std::vector<DynamicParameter> params = {
        {"period_s", "s", 0.20, 0.30, [](TrialConfig* c) { return &c->control_period_s; }, nullptr},
        {"smoothing_s", "s", 0.03, 0.25, [](TrialConfig* c) { return &c->servo.smoothing_s; },
         nullptr},
        {"servo_damping", "1", 0.2, 1.0, [](TrialConfig* c) { return &c->servo.damping; }, nullptr},
    };
    for (const EffectKey& k : EffectKeys()) {
      if (k.fit_max > k.fit_min)
        params.push_back({k.key, k.unit, k.fit_min, k.fit_max, nullptr, &k});
    }
    return params;
  }();
  return kParams;
}

namespace {

const DynamicParameter* FindParameter(const std::string& key) {
  for (const DynamicParameter& p : DynamicParameters())
    if (key == p.key) return &p;
  return nullptr;
}

}  // namespace

bool EvaluateDynamic(const mjModel* m, const DynamicFitSpec& spec, const TrialConfig& config,
                     double* cost, MapScore* score, std::vector<MetricTarget>* targets,
                     std::string* error) {
  std::vector<MapCell> cells = spec.cells;
  *targets = PublishedMetricTargets();
  // The metric targets' cells must be run too (they are in the dL 5 mm map; add any missing).
  for (const MetricTarget& t : *targets) {
    bool found = false;
    for (const MapCell& c : cells)
      found |= c.step_mm == 5.0 && c.beta == t.beta && c.pref_pa == t.pref_pa;
    if (!found) cells.push_back({5.0, t.beta, t.pref_pa, MapClass::kThreeOfThree});
  }
  std::vector<std::vector<MapTrial>> results;
  if (!RunMapTrials(m, cells, config, spec.seeds, spec.seed, spec.threads, &results, error))
    return false;
  std::vector<CellTrials> trials(spec.cells.size());
  for (std::size_t i = 0; i < spec.cells.size(); ++i)
    for (const MapTrial& t : results[i]) trials[i].outcomes.push_back(t.outcome);
  if (!ScoreMap(spec.cells, trials, score, error)) return false;
  MeasureMetricTargets(cells, results, targets);
  double metric_cost = 0;
  for (const MetricTarget& t : *targets) {
    // No successful trial: the target cannot be measured; charge a large but finite residual.
    const double res = t.successes > 0 ? (t.model - t.published) / t.tolerance : 5.0;
    metric_cost +=
        std::min(res * res, 25.0);  // capped: one hopeless target cannot outweigh the map
  }
  metric_cost /= static_cast<double>(targets->size());
  *cost = score->log_loss + spec.metric_weight * metric_cost;
  return true;
}

std::string CheckDynamicKeys(const std::vector<std::string>& keys) {
  if (keys.empty()) return "no parameters to fit";
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (FindParameter(keys[i]) == nullptr) {
      std::string names;
      for (const DynamicParameter& q : DynamicParameters())
        names += std::string(names.empty() ? "" : ", ") + q.key;
      return "unknown parameter '" + keys[i] + "' (parameters: " + names + ")";
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (keys[j] == keys[i]) return "parameter '" + keys[i] + "' is listed twice";
    }
  }
  return "";
}

bool FitDynamic(const mjModel* m, const DynamicFitSpec& spec,
                const std::function<void(const std::string&)>& log, DynamicFitResult* result,
                std::string* error) {
  if (const std::string e = CheckDynamicKeys(spec.keys); !e.empty()) {
    *error = "dynamic fit: " + e;
    return false;
  }
  std::vector<const DynamicParameter*> params;
  for (const std::string& k : spec.keys) params.push_back(FindParameter(k));
  const auto t0 = std::chrono::steady_clock::now();
  TrialConfig start = spec.base;
  std::vector<double> x0(params.size());
  for (std::size_t i = 0; i < params.size(); ++i) {
    const double v = *params[i]->field(&start);
    x0[i] = std::clamp((v - params[i]->min) / (params[i]->max - params[i]->min), 0.0, 1.0);
  }
  auto config_at = [&](const std::vector<double>& x) {
    TrialConfig c = spec.base;
    for (std::size_t i = 0; i < params.size(); ++i)
      *params[i]->field(&c) =
          params[i]->min + std::clamp(x[i], 0.0, 1.0) * (params[i]->max - params[i]->min);
    return c;
  };
  int evaluations = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<double> best_x = x0;
  std::string eval_error;
  auto objective = [&](const std::vector<double>& x) {
    const TrialConfig c = config_at(x);
    if (const std::string e = c.Validate(); !e.empty()) return 50.0;  // outside joint limits
    double cost = 0;
    MapScore score;
    std::vector<MetricTarget> targets;
    if (!EvaluateDynamic(m, spec, c, &cost, &score, &targets, &eval_error)) {
      throw nlopt::forced_stop();
    }
    ++evaluations;
    if (evaluations == 1) result->start_cost = cost;
    if (cost < best_cost) {
      best_cost = cost;
      best_x = x;
    }
    if (log) {
      std::ostringstream os;
      os.precision(4);
      os << "eval " << evaluations << ": cost " << cost << " (class match "
         << 100 * score.class_match << " %, agreement " << score.expected_agreement << ", opposite "
         << score.opposite << ")";
      for (std::size_t i = 0; i < params.size(); ++i)
        os << ' ' << params[i]->key << '=' << *params[i]->field(const_cast<TrialConfig*>(&c));
      log(os.str());
    }
    return cost;
  };
  if (!MinimiseOnUnitBox({spec.algorithm, spec.max_evaluations, 0.25}, x0, objective)) {
    *error = "dynamic fit: " + eval_error;
    return false;
  }
  result->best = config_at(best_x);
  result->values.clear();
  for (const DynamicParameter* p : params) result->values.push_back(*p->field(&result->best));
  result->evaluations = evaluations;
  if (!EvaluateDynamic(m, spec, result->best, &result->cost, &result->score, &result->targets,
                       error))
    return false;
  result->wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

bool ReadDynamicFitCells(const std::string& map_path, std::vector<MapCell>* cells,
                         std::string* error) {
  if (!ReadPublishedMap(map_path, cells, error)) return false;
  for (const MapCell& c : PublishedOutcomeCells()) {
    bool in_map = false;
    for (const MapCell& m : *cells)
      in_map |= m.step_mm == c.step_mm && m.beta == c.beta && m.pref_pa == c.pref_pa;
    if (!in_map) cells->push_back(c);
  }
  return true;
}

bool ScoreOnHeldOutSeeds(const mjModel* m, const DynamicFitSpec& spec, const TrialConfig& best,
                         std::uint64_t holdout_seed, HeldOutScores* scores, std::string* error) {
  DynamicFitSpec held = spec;
  held.seed = holdout_seed == spec.seed ? holdout_seed + 1 : holdout_seed;
  scores->seed = held.seed;
  std::vector<MetricTarget> unused;
  return EvaluateDynamic(m, held, spec.base, &scores->start_cost, &scores->start, &unused, error) &&
         EvaluateDynamic(m, held, best, &scores->best_cost, &scores->best, &unused, error);
}

}  // namespace ssc
