#include "studies/controller_tune.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlopt.hpp>
#include <sstream>

#include "common/csv_cell.h"
#include "common/output_file.h"
#include "common/strict_number.h"
#include "studies/equivalence.h"
#include "studies/scores/map_scores.h"
#include "studies/statistics/intervals.h"
#include "studies/sweep_io.h"
#include "studies/trial_io.h"
#include "studies/trial_manifest.h"
#include "studies/unit_box_search.h"
#include "trial/trial_outcome.h"

namespace ssc {
namespace {

double* LawField(const std::string& key, TrialConfig* c) {
  if (key == "pref_pa") return &c->law.p_ref_pa;
  if (key == "beta") return &c->law.beta;
  if (key == "step_mm") return &c->law.step_mm;
  return nullptr;
}

// The law keys' valid ranges (as ssc sweep's --pref, --beta, --step take them).
std::array<double, 2> LawRange(const std::string& key) {
  if (key == "pref_pa") return {1e-6, 1e6};
  if (key == "beta") return {0, 100};
  return {kMinStepMm, kMaxStepMm};
}

std::string Num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

std::string Range(double lo, double hi) { return "[" + Num(lo) + ", " + Num(hi) + "]"; }

ControllerValues FullValues(const ControllerChoice& choice) {
  ControllerValues v = choice.values;
  if (const ControllerType* type = FindControllerType(choice.name); type && v.empty()) {
    for (const ControllerParamKey& k : type->keys) v.push_back(k.default_value);
  }
  return v;
}

std::string ChoiceText(const std::vector<TuneKey>& keys, const TrialConfig& c) {
  std::string text = c.controller.Text();
  for (const TuneKey& k : keys) {
    if (k.controller_index < 0) {
      text += " " + k.key + "=" + Num(*LawField(k.key, const_cast<TrialConfig*>(&c)));
    }
  }
  return text;
}

}  // namespace

bool ParseTuneSearch(const ControllerType& type, const std::string& text,
                     std::vector<TuneKey>* keys, std::string* error) {
  keys->clear();
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t eq = item.find('='), colon = item.find(':', eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || colon == std::string::npos) {
      *error = "'" + item + "': expected key=lo:hi";
      return false;
    }
    TuneKey k;
    k.key = item.substr(0, eq);
    std::array<double, 2> range{};
    for (std::size_t i = 0; i < type.keys.size(); ++i) {
      if (type.keys[i].key == k.key) {
        k.controller_index = static_cast<int>(i);
        range = {type.keys[i].min, type.keys[i].max};
      }
    }
    if (k.controller_index < 0) {
      if (std::find_if(kTuneLawKeys.begin(), kTuneLawKeys.end(),
                       [&](const char* law) { return k.key == law; }) == kTuneLawKeys.end()) {
        std::string known;
        for (const ControllerParamKey& c : type.keys) known += c.key + ", ";
        *error = "unknown key '" + k.key + "' for controller '" + type.name +
                 "' (its keys: " + known + "and the law's pref_pa, beta, step_mm)";
        return false;
      }
      range = LawRange(k.key);
    }
    for (const TuneKey& other : *keys) {
      if (other.key == k.key) {
        *error = "key '" + k.key + "' given twice";
        return false;
      }
    }
    const NumberRange within = NumberRange::Closed(range[0], range[1]);
    std::string number_error;
    if (!ParseNumber(item.substr(eq + 1, colon - eq - 1), within, &k.lo, &number_error) ||
        !ParseNumber(item.substr(colon + 1), within, &k.hi, &number_error) || !(k.lo < k.hi)) {
      *error = "key '" + k.key + "': '" + item.substr(eq + 1) +
               "' is not lo:hi with lo < hi, both numbers within " + Range(range[0], range[1]);
      return false;
    }
    if (k.controller_index >= 0 && type.keys[static_cast<std::size_t>(k.controller_index)].whole &&
        !(std::ceil(k.lo) < std::floor(k.hi))) {
      *error = "key '" + k.key + "' takes whole numbers: '" + item.substr(eq + 1) +
               "' holds fewer than two to search between";
      return false;
    }
    keys->push_back(k);
  }
  if (keys->empty()) {
    *error = "no key to search (key=lo:hi,...)";
    return false;
  }
  return true;
}

std::string CheckTuneBox(const std::vector<TuneKey>& keys, const ControllerChoice& base) {
  const ControllerType* type = base.custom ? nullptr : FindControllerType(base.name);
  if (type == nullptr || type->orders.empty()) return "";
  const ControllerValues values = FullValues(base);
  std::vector<double> lo = values, hi = values;
  std::vector<bool> searched(values.size(), false);
  for (const TuneKey& k : keys) {
    if (k.controller_index < 0) continue;
    const auto i = static_cast<std::size_t>(k.controller_index);
    lo[i] = k.lo;
    hi[i] = k.hi;
    searched[i] = true;
  }
  const std::vector<double> box_lo = lo, box_hi = hi;
  // lower <= upper lifts upper's least value to lower's and drops lower's greatest to upper's; a
  // chain of rules is settled after as many passes as there are rules.
  for (std::size_t pass = 0; pass <= type->orders.size(); ++pass) {
    for (const ControllerKeyOrder& o : type->orders) {
      lo[o.upper] = std::max(lo[o.upper], lo[o.lower]);
      hi[o.lower] = std::min(hi[o.lower], hi[o.upper]);
    }
  }
  bool empty = false;
  for (std::size_t i = 0; i < lo.size(); ++i) empty = empty || lo[i] > hi[i];
  if (!empty) return "";
  auto range = [&](std::size_t i) {
    const std::string& key = type->keys[i].key;
    return searched[i] ? key + " in " + Range(box_lo[i], box_hi[i])
                       : key + " = " + Num(values[i]) + " (not searched: the base value)";
  };
  std::string rules;
  auto add = [&](const ControllerKeyOrder& o) {
    rules += (rules.empty() ? "" : "; ") + KeyOrderText(*type, o) + " with " + range(o.lower) +
             " and " + range(o.upper);
  };
  for (const ControllerKeyOrder& o : type->orders)
    if (box_lo[o.lower] > box_hi[o.upper]) add(o);
  if (rules.empty()) {  // no single rule is broken everywhere: the chain of them is
    for (const ControllerKeyOrder& o : type->orders) add(o);
  }
  return "no point of the search box keeps controller " + type->name + "'s rule: " + rules;
}

std::vector<double> TuneValues(const std::vector<TuneKey>& keys, const TrialConfig& config) {
  const ControllerValues all = FullValues(config.controller);
  std::vector<double> v;
  for (const TuneKey& k : keys) {
    v.push_back(k.controller_index >= 0 ? all[static_cast<std::size_t>(k.controller_index)]
                                        : *LawField(k.key, const_cast<TrialConfig*>(&config)));
  }
  return v;
}

TrialConfig WithTuneValues(const std::vector<TuneKey>& keys, const std::vector<double>& values,
                           TrialConfig config) {
  config.controller.values = FullValues(config.controller);
  for (std::size_t i = 0; i < keys.size() && i < values.size(); ++i) {
    if (keys[i].controller_index >= 0) {
      config.controller.values[static_cast<std::size_t>(keys[i].controller_index)] = values[i];
    } else {
      *LawField(keys[i].key, &config) = values[i];
    }
  }
  return config;
}

double TuneScore(int successes, int trials, double mean_speed_mm_s, double min_success) {
  if (trials <= 0) return -kTuneShortfallPenaltyMmS * min_success;
  const double rate = static_cast<double>(successes) / trials;
  const double speed = successes > 0 && std::isfinite(mean_speed_mm_s) ? mean_speed_mm_s : 0.0;
  return speed - kTuneShortfallPenaltyMmS * std::max(0.0, min_success - rate);
}

std::vector<std::size_t> ParetoFront(const std::vector<std::array<double, 2>>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      if (j == i) continue;
      const bool no_worse = points[j][0] >= points[i][0] && points[j][1] >= points[i][1];
      const bool better = points[j][0] > points[i][0] || points[j][1] > points[i][1];
      // An equal point earlier in the list stands for both.
      dominated = no_worse && (better || j < i);
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(),
            [&](std::size_t a, std::size_t b) { return points[a][0] < points[b][0]; });
  return front;
}

std::string TuneCsvHeader(const std::vector<TuneKey>& keys) {
  std::string h = "label,controller";
  for (const TuneKey& k : keys) h += "," + k.key;
  return h +
         ",trials,successes,success_rate,success_lo,success_hi,speed_mm_s,speed_ci_mm_s,score,"
         "pareto,outcome";
}

std::string TuneCsvRow(const TuneEvaluation& e, std::size_t keys) {
  std::ostringstream os;
  os << e.label << ',' << CsvCell(e.controller);
  for (std::size_t i = 0; i < keys; ++i) os << ',' << (i < e.values.size() ? Num(e.values[i]) : "");
  os << ',' << e.trials << ',' << e.successes << ',';
  if (e.refused.empty()) {
    os << Num(e.trials ? static_cast<double>(e.successes) / e.trials : 0) << ','
       << Num(e.success_ci[0]) << ',' << Num(e.success_ci[1]) << ',' << Num(e.speed_mm_s) << ','
       << Num(e.speed_ci_mm_s);
  } else {
    os << ",,,,";
  }
  os << ',' << Num(e.score) << ',' << (e.pareto ? 1 : 0) << ',';
  if (e.refused.empty()) {
    os << "ran";
  } else {
    os << CsvCell("refused: " + e.refused);
  }
  return os.str();
}

namespace {

// One evaluation: the sweep of `seeds` trials at `config`, read back.
bool Evaluate(const mjModel* m, const TuneSpec& spec, const TrialConfig& config,
              const std::string& label, TuneEvaluation* e, std::string* error) {
  namespace fs = std::filesystem;
  SweepSpec sweep = spec.sweep;
  sweep.base = config;
  sweep.pref_pa = {config.law.p_ref_pa};
  sweep.beta = {config.law.beta};
  sweep.step_mm = {config.law.step_mm};
  sweep.points.clear();
  sweep.repeats = spec.seeds;
  std::string dir_name = label;
  std::replace(dir_name.begin(), dir_name.end(), ' ', '_');
  const fs::path dir = fs::path(spec.out_dir) / "evals" / dir_name;
  std::error_code ec;
  fs::create_directories(dir, ec);
  // The folder is this search's (RunTune holds its lock and checked tune.json): an earlier run
  // of the same search made the same points, so its rows resume as a sweep's do.
  sweep.out_csv = (dir / "sweep.csv").string();
  if (const std::string bad = CheckSweepGrid(sweep); !bad.empty()) {
    *error = label + ": " + bad;
    return false;
  }
  SweepSummary summary;
  if (!RunSweep(m, sweep, nullptr, &summary, error)) return false;
  if (summary.interrupted) {
    *error = "interrupted";
    return false;
  }
  std::ifstream in(sweep.out_csv);
  std::stringstream text;
  text << in.rdbuf();
  const SweepCsvContents rows = ParseSweepCsv(text.str(), SweepCsvHeader());
  std::vector<double> speeds;
  e->label = label;
  e->trials = static_cast<int>(rows.rows.size());
  if (e->trials != spec.seeds) {
    *error = label + ": " + sweep.out_csv + " holds " + std::to_string(e->trials) +
             " trials where the evaluation ran " + std::to_string(spec.seeds) +
             ": the folder changed under the search";
    return false;
  }
  for (const SweepRowKey& r : rows.rows) {
    if (r.outcome == OutcomeName(Outcome::kSuccess) && r.duration_s > 0) {
      speeds.push_back(r.s_mm / r.duration_s);
    }
  }
  e->successes = static_cast<int>(speeds.size());
  const std::array<double, 2> ci = WilsonInterval(e->successes, e->trials);
  e->success_ci = ci;
  double sum = 0;
  for (double v : speeds) sum += v;
  e->speed_mm_s = speeds.empty() ? 0 : sum / static_cast<double>(speeds.size());
  if (speeds.size() > 1) {
    double ss = 0;
    for (double v : speeds) ss += (v - e->speed_mm_s) * (v - e->speed_mm_s);
    const double n = static_cast<double>(speeds.size());
    e->speed_ci_mm_s = StudentT95(n - 1) * std::sqrt(ss / (n - 1) / n);
  }
  e->score = TuneScore(e->successes, e->trials, e->speed_mm_s, spec.min_success);
  return true;
}

// What defines a search's results: the trials' options and the search's own.
SweepManifest TuneManifest(const mjModel* m, const TuneSpec& spec) {
  SweepManifest manifest = TrialManifest(m, spec.sweep.scene_name, spec.sweep.base);
  manifest["seed"] = std::to_string(spec.sweep.seed);
  manifest["controller"] = spec.sweep.base.controller.Text();
  std::string box, references;
  for (const TuneKey& k : spec.keys) box += k.key + "=" + Num(k.lo) + ":" + Num(k.hi) + ",";
  for (const auto& [name, config] : spec.references)
    references += name + "=" + config.controller.Text() + ";";
  manifest["search"] = box;
  manifest["references"] = references;
  manifest["seeds"] = std::to_string(spec.seeds);
  manifest["evaluations"] = std::to_string(spec.evaluations);
  manifest["min_success"] = Num(spec.min_success);
  manifest["algorithm"] = spec.algorithm;
  return manifest;
}

// Takes the output folder before anything in it is touched: its lock (one search at a time) and
// tune.json (an earlier search with other options is refused, naming them, and loses nothing).
bool OwnTuneFolder(const mjModel* m, const TuneSpec& spec, SweepOutputLock* lock,
                   std::string* error) {
  namespace fs = std::filesystem;
  const std::string table = (fs::path(spec.out_dir) / "tune.csv").string();
  if (!lock->Acquire(table, error)) return false;
  std::error_code ec;
  const bool has_results =
      fs::exists(table, ec) || fs::exists(fs::path(spec.out_dir) / "evals", ec);
  if (!CheckOrWriteSweepManifest(table, has_results, TuneManifest(m, spec), error)) {
    return false;
  }
  return true;
}

std::string EvaluationLine(const TuneEvaluation& e, const std::vector<TuneKey>& keys) {
  std::ostringstream os;
  os.precision(3);
  if (!e.refused.empty()) {
    os << e.label << ": refused, not run (" << e.refused << "), score " << e.score;
  } else {
    os << e.label << ": " << e.successes << "/" << e.trials << " success, " << e.speed_mm_s
       << " mm/s, score " << e.score;
  }
  for (std::size_t i = 0; i < e.values.size() && i < keys.size(); ++i)
    os << ' ' << keys[i].key << '=' << e.values[i];
  if (e.values.empty()) os << ' ' << e.controller;
  return os.str();
}

}  // namespace

bool RunTune(const mjModel* m, const TuneSpec& spec,
             const std::function<void(const std::string&)>& log, TuneResult* result,
             std::string* error) {
  const auto t0 = std::chrono::steady_clock::now();
  result->evaluations.clear();
  result->best = -1;
  result->refused = 0;
  if (const std::string why = CheckTuneBox(spec.keys, spec.sweep.base.controller); !why.empty()) {
    *error = why;
    return false;
  }
  SweepOutputLock lock;
  if (!OwnTuneFolder(m, spec, &lock, error)) return false;
  for (const auto& [name, config] : spec.references) {
    TuneEvaluation e;
    if (!Evaluate(m, spec, config, name, &e, error)) return false;
    e.controller = config.controller.Text();
    if (log) log(EvaluationLine(e, spec.keys));
    result->evaluations.push_back(e);
  }
  const std::size_t n = spec.keys.size();
  const ControllerType* type = FindControllerType(spec.sweep.base.controller.name);
  // A count or a switch is searched on its whole numbers: the point is rounded to one.
  auto to_values = [&](const std::vector<double>& x) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) {
      const TuneKey& k = spec.keys[i];
      v[i] = k.lo + std::clamp(x[i], 0.0, 1.0) * (k.hi - k.lo);
      if (type && k.controller_index >= 0 &&
          type->keys[static_cast<std::size_t>(k.controller_index)].whole)
        v[i] = std::clamp(std::round(v[i]), std::ceil(k.lo), std::floor(k.hi));
    }
    return v;
  };
  // The start: the base config's values, clamped into the search box.
  std::vector<double> x0(n);
  const std::vector<double> start = TuneValues(spec.keys, spec.sweep.base);
  for (std::size_t i = 0; i < n; ++i) {
    x0[i] =
        std::clamp((start[i] - spec.keys[i].lo) / (spec.keys[i].hi - spec.keys[i].lo), 0.0, 1.0);
  }
  std::string eval_error;
  int count = 0;
  double best_score = -std::numeric_limits<double>::infinity();
  auto objective = [&](const std::vector<double>& x) {
    if (count >= spec.evaluations) throw nlopt::forced_stop();
    const std::vector<double> values = to_values(x);
    const TrialConfig config = WithTuneValues(spec.keys, values, spec.sweep.base);
    TuneEvaluation e;
    const std::string label = "eval " + std::to_string(++count);
    // A point breaking a rule between the controller's keys is neither run nor moved into the
    // rule (the optimiser would be scoring a point it did not ask for): it is infeasible.
    if (std::string why = config.controller.Validate(); !why.empty()) {
      e.label = label;
      e.refused = why;
      e.score = TuneScore(0, spec.seeds, 0, spec.min_success);
      ++result->refused;
    } else if (!Evaluate(m, spec, config, label, &e, &eval_error)) {
      throw nlopt::forced_stop();
    }
    e.values = values;
    e.controller = ChoiceText(spec.keys, config);
    if (log) log(EvaluationLine(e, spec.keys));
    result->evaluations.push_back(e);
    if (e.refused.empty() && e.score > best_score) {
      best_score = e.score;
      result->best = static_cast<int>(result->evaluations.size()) - 1;
    }
    return -e.score;
  };
  if (!MinimiseOnUnitBox({spec.algorithm, spec.evaluations, 0.25}, x0, objective) &&
      !eval_error.empty()) {
    *error = eval_error;
    return false;
  }
  std::vector<std::array<double, 2>> points;
  std::vector<std::size_t> ran;
  for (std::size_t i = 0; i < result->evaluations.size(); ++i) {
    const TuneEvaluation& e = result->evaluations[i];
    if (!e.refused.empty()) continue;
    ran.push_back(i);
    points.push_back({e.speed_mm_s, e.trials ? static_cast<double>(e.successes) / e.trials : 0});
  }
  for (std::size_t i : ParetoFront(points)) result->evaluations[ran[i]].pareto = true;
  OutputFile csv((std::filesystem::path(spec.out_dir) / "tune.csv").string());
  csv.stream() << TuneCsvHeader(spec.keys) << '\n';
  for (const TuneEvaluation& e : result->evaluations) csv.stream() << TuneCsvRow(e, n) << '\n';
  if (!csv.Commit(error)) return false;
  result->wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

}  // namespace ssc
