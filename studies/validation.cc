#include "studies/validation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "common/input_file.h"
#include "common/output_file.h"
#include "common/strict_number.h"
#include "runtime/rig.h"
#include "studies/jobs/job_runner.h"
#include "studies/scores/metric_targets.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

std::string Trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

constexpr char kUtf8Bom[] = "\xEF\xBB\xBF";

std::vector<std::string> SplitComma(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(Trim(cell));
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// Whole-string finite number in [lo, hi] (the project's one strict reader).
bool ReadNumber(const std::string& text, double lo, double hi, double* v) {
  std::string ignored;
  return ParseNumber(text, NumberRange::Closed(lo, hi), v, &ignored);
}

using CellKey = std::tuple<long, long, long>;
CellKey KeyOf(double step, double beta, double pref) {
  return {std::lround(step * 1e6), std::lround(beta * 1e6), std::lround(pref * 1e6)};
}

// Outcomes per (step, beta, pref) and repeat from a sweep CSV.
bool ReadTrials(const std::string& path, std::map<CellKey, std::map<int, MapTrial>>* trials,
                std::string* error) {
  std::ifstream f(path);
  if (!f) {
    *error = path + ": cannot read";
    return false;
  }
  std::string line;
  if (!std::getline(f, line)) {
    *error = path + ": empty";
    return false;
  }
  const std::vector<std::string> header = SplitComma(line);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  for (const char* need :
       {"pref_pa", "beta", "step_mm", "repeat", "outcome", "dr_mm", "sigma_r_mm", "s_c"}) {
    if (!col.count(need)) {
      *error = path + ": header has no column '" + need + "'";
      return false;
    }
  }
  // A trial's path metrics (NaN when not a number: only successful trials' are used).
  auto metric = [](const std::string& text) {
    double v = 0;
    return ReadNumber(text, -1e9, 1e9, &v) ? v : std::numeric_limits<double>::quiet_NaN();
  };
  while (std::getline(f, line)) {
    const std::vector<std::string> c = SplitComma(line);
    if (c.size() <= col["outcome"] || c[col["outcome"]].empty()) continue;  // torn: rerun
    double pref = 0, beta = 0, step = 0, rep = 0;
    if (!ReadNumber(c[col["pref_pa"]], 0, 1e9, &pref) ||
        !ReadNumber(c[col["beta"]], 0, 1e9, &beta) ||
        !ReadNumber(c[col["step_mm"]], 0, 1e9, &step) ||
        !ReadNumber(c[col["repeat"]], 0, 1e9, &rep))
      continue;
    MapTrial t;
    t.outcome = c[col["outcome"]];
    t.dr_mm = metric(c[col["dr_mm"]]);
    t.sigma_r_mm = metric(c[col["sigma_r_mm"]]);
    t.s_c = metric(c[col["s_c"]]);
    (*trials)[KeyOf(step, beta, pref)][static_cast<int>(rep)] = t;
  }
  return true;
}

}  // namespace

bool ReadPublishedMap(const std::string& path, std::vector<MapCell>* cells, std::string* error) {
  cells->clear();
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    *error = path + ": " + why + " (the published map)";
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = path + ": cannot open the published map";
    return false;
  }
  {
    std::string head(4096, '\0');
    f.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<size_t>(f.gcount()));
    if (const std::string why = NonTextReason(head); !why.empty()) {
      *error = path + ": " + why + " (the published map is a UTF-8 CSV step_mm,beta,pref_pa," +
               "successes_of_3)";
      return false;
    }
    f.clear();
    f.seekg(0);
  }
  std::string line;
  int line_no = 0;
  const std::vector<std::string> expected = {"step_mm", "beta", "pref_pa", "successes_of_3"};
  std::set<CellKey> seen;
  while (std::getline(f, line)) {
    ++line_no;
    // A spreadsheet's UTF-8 byte-order mark before the header (line ends: Trim drops the \r of
    // CRLF).
    if (line_no == 1 && line.rfind(kUtf8Bom, 0) == 0) line.erase(0, sizeof(kUtf8Bom) - 1);
    if (Trim(line).empty()) continue;
    const std::vector<std::string> c = SplitComma(line);
    auto where = [&](int column) {
      return path + ":" + std::to_string(line_no) + ": column " + std::to_string(column + 1);
    };
    if (line_no == 1) {
      if (c != expected) {
        *error = path + ":1: header must be 'step_mm,beta,pref_pa,successes_of_3', got '" +
                 ShownText(Trim(line)) + "'";
        return false;
      }
      continue;
    }
    if (c.size() != 4) {
      *error = path + ":" + std::to_string(line_no) + ": expected 4 fields, got " +
               std::to_string(c.size());
      return false;
    }
    MapCell cell;
    if (!ReadNumber(c[0], kMinStepMm, kMaxStepMm, &cell.step_mm)) {
      *error = where(0) + ": step_mm '" + ShownText(c[0]) + "' must be a number in [" +
               FormatNumber(kMinStepMm) + ", " + FormatNumber(kMaxStepMm) +
               "] mm (below: metres given as mm?)";
      return false;
    }
    if (!ReadNumber(c[1], 0, 100, &cell.beta)) {
      *error = where(1) + ": beta '" + ShownText(c[1]) + "' must be a number in [0, 100]";
      return false;
    }
    if (!ReadNumber(c[2], 1e-3, 1e6, &cell.pref_pa)) {
      *error = where(2) + ": pref_pa '" + ShownText(c[2]) + "' must be a number in [0.001, 1e6] Pa";
      return false;
    }
    if (!ParseMapClass(c[3], &cell.published)) {
      *error = where(3) + ": successes_of_3 '" + ShownText(c[3]) + "' must be 3, 2 or <=1";
      return false;
    }
    if (!seen.insert(KeyOf(cell.step_mm, cell.beta, cell.pref_pa)).second) {
      *error = path + ":" + std::to_string(line_no) + ": the cell step " + c[0] + ", beta " + c[1] +
               ", P_ref " + c[2] + " appears twice";
      return false;
    }
    cells->push_back(cell);
  }
  if (line_no == 0) {
    *error = path + ": empty (expected the header step_mm,beta,pref_pa,successes_of_3)";
    return false;
  }
  if (cells->empty()) {
    *error = path + ": no cells";
    return false;
  }
  return true;
}

bool PrepareValidation(const ValidateSpec& spec, std::vector<MapCell>* cells, SweepSpec* sweep,
                       std::string* error) {
  if (!ReadPublishedMap(spec.map_path, cells, error)) return false;
  if (spec.seeds < 3) {
    *error = "seeds = " + std::to_string(spec.seeds) + " is out of range [3, 10000]";
    return false;
  }
  *sweep = SweepSpec();
  sweep->scene_name = spec.scene_name;
  sweep->base = spec.base;
  for (const MapCell& c : *cells) sweep->points.push_back({c.pref_pa, c.beta, c.step_mm});
  sweep->repeats = spec.seeds;
  sweep->seed = spec.seed;
  sweep->threads = spec.threads;
  sweep->out_csv = spec.out_dir + "/trials.csv";
  sweep->share_approach = spec.share_approach;
  if (std::string e = CheckSweepGrid(*sweep); !e.empty()) {
    *error = spec.map_path + ": " + e;
    return false;
  }
  return true;
}

bool RunValidation(const mjModel* m, const ValidateSpec& spec,
                   const std::function<void(const SweepProgress&)>& progress, MapScore* score,
                   SweepSummary* summary, std::string* error, std::vector<MetricTarget>* fig6,
                   MapCeilings* ceilings) {
  std::vector<MapCell> cells;
  SweepSpec sweep;
  if (!PrepareValidation(spec, &cells, &sweep, error)) return false;
  if (!RunSweep(m, sweep, progress, summary, error)) return false;
  if (JobRunnerRank() != 0) return true;
  if (summary->interrupted) {
    *error = "interrupted: finished trials are in " + sweep.out_csv + "; run again to resume";
    return false;
  }

  std::map<CellKey, std::map<int, MapTrial>> read;
  if (!ReadTrials(sweep.out_csv, &read, error)) return false;
  std::vector<CellTrials> trials(cells.size());
  std::vector<std::vector<MapTrial>> results(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto& rows = read[KeyOf(cells[i].step_mm, cells[i].beta, cells[i].pref_pa)];
    for (int r = 0; r < spec.seeds; ++r) {
      const auto it = rows.find(r);
      if (it == rows.end()) {
        *error = sweep.out_csv + ": repeat " + std::to_string(r) + " of a cell is missing";
        return false;
      }
      trials[i].outcomes.push_back(it->second.outcome);
      results[i].push_back(it->second);
    }
  }
  if (!ScoreMap(cells, trials, score, error)) return false;
  // The published Fig. 6 targets the map's cells measure (successful trials only).
  std::vector<MetricTarget> targets = PublishedMetricTargets();
  MeasureMetricTargets(cells, results, &targets);

  // What any twin can expect against these published classes (studies/map_ceiling.h).
  MapCeilings ceiling_list;
  if (!ComputeMapCeilings(cells, kClassMatchGoal, &ceiling_list, error)) {
    *error = spec.map_path + ": " + *error;
    return false;
  }
  const std::vector<double> surface_p = SurfaceRatesOfMap(cells, ceiling_list);
  for (std::size_t i = 0; i < surface_p.size(); ++i) score->cells[i].surface_p = surface_p[i];
  const std::string cells_csv = spec.out_dir + "/cells.csv";
  OutputFile cells_file(cells_csv);
  std::ostream& c = cells_file.stream();
  c << "step_mm,beta,pref_pa,published,twin_class,successes_of_3,successes,trials,p_success,"
       "p_low,p_high,expected_agreement,opposite,failure_I,failure_II,timeout,unstable,"
       "main_failure,surface_p\n";
  for (const CellScore& s : score->cells) {
    c << s.cell.step_mm << ',' << s.cell.beta << ',' << s.cell.pref_pa << ','
      << MapClassName(s.cell.published) << ',' << MapClassName(s.twin_class) << ','
      << s.successes_of_3 << ',' << s.successes << ',' << s.trials << ',' << s.p_success << ','
      << s.p_interval[0] << ',' << s.p_interval[1] << ',' << s.expected_agreement << ','
      << (s.opposite ? 1 : 0) << ',' << s.failure_off_edge << ',' << s.failure_grasp << ','
      << s.timeout << ',' << s.unstable << ',' << s.main_failure << ',' << s.surface_p << '\n';
  }
  if (!cells_file.Commit(error)) return false;
  nlohmann::json j;
  j["map"] = spec.map_path;
  j["scene"] = spec.scene_name;
  j["default_scene"] = DefaultScene();
  j["seeds_per_cell"] = spec.seeds;
  j["base_seed"] = spec.seed;
  j["effects"] = FormatRobotEffects(spec.base.effects);
  if (!spec.base.controller.IsPublished()) j["controller"] = spec.base.controller.Text();
  j["control_period_s"] = spec.base.control_period_s;
  j["servo_smoothing_s"] = spec.base.servo.smoothing_s;
  j["servo_damping"] = spec.base.servo.damping;
  j["cells"] = score->cells_scored;
  j["class_match"] = score->class_match;
  j["expected_agreement"] = score->expected_agreement;
  j["expected_agreement_interval"] = score->agreement_interval;
  j["opposite_cells"] = score->opposite;
  j["log_loss"] = score->log_loss;
  j["ceilings"] = nlohmann::json::array();
  for (const MapCeiling& ceiling : ceiling_list.priors) {
    j["ceilings"].push_back({{"prior", ceiling.prior_name},
                             {"prior_a", ceiling.prior.a},
                             {"prior_b", ceiling.prior.b},
                             {"rerun_agreement", ceiling.rerun_agreement},
                             {"oracle_agreement", ceiling.oracle_agreement},
                             {"class_match_goal", kClassMatchGoal},
                             {"rerun_reaches_goal", ceiling.rerun_reaches_goal},
                             {"oracle_reaches_goal", ceiling.oracle_reaches_goal}});
  }
  j["surface_ceilings"] = nlohmann::json::array();
  for (const SurfaceCeiling& s : ceiling_list.surfaces) {
    if (!s.fitted) continue;
    j["surface_ceilings"].push_back({{"step_mm", s.step_mm},
                                     {"weights", s.weights},
                                     {"negative_log_likelihood", s.negative_log_likelihood},
                                     {"rerun_agreement", s.rerun_agreement},
                                     {"oracle_agreement", s.oracle_agreement},
                                     {"loo_agreement", s.loo_agreement},
                                     {"class_match_goal", kClassMatchGoal},
                                     {"rerun_reaches_goal", s.rerun_reaches_goal},
                                     {"oracle_reaches_goal", s.oracle_reaches_goal}});
  }
  j["fig6_targets"] = nlohmann::json::array();
  for (const MetricTarget& t : targets) {
    if (t.successes == 0) continue;
    j["fig6_targets"].push_back({{"name", t.name},
                                 {"published", t.published},
                                 {"tolerance", t.tolerance},
                                 {"twin", t.model},
                                 {"twin_standard_error", t.standard_error},
                                 {"successes", t.successes}});
  }
  j["wall_s"] = summary->wall_s;
  if (!WriteWholeFile(spec.out_dir + "/validate.json", j.dump(2) + "\n", error)) return false;
  if (fig6) *fig6 = targets;
  if (ceilings) *ceilings = ceiling_list;
  return true;
}

bool RunMapTrials(const mjModel* m, const std::vector<MapCell>& cells, const TrialConfig& base,
                  int seeds, std::uint64_t seed, int threads,
                  std::vector<std::vector<MapTrial>>* results, std::string* error) {
  struct Job {
    std::size_t cell;
    TrialConfig config;
  };
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (int r = 0; r < seeds; ++r) {
      Job job{i, base};
      job.config.law.p_ref_pa = cells[i].pref_pa;
      job.config.law.beta = cells[i].beta;
      job.config.law.step_mm = cells[i].step_mm;
      job.config.seed = TrialSeed(seed, cells[i].pref_pa, cells[i].beta, cells[i].step_mm, r);
      if (const std::string e = job.config.Validate(); !e.empty()) {
        *error = "map trial: " + e;
        return false;
      }
      jobs.push_back(job);
    }
  }
  if (!jobs.empty() && !CheckTrialSetup(m, jobs.front().config, error)) {
    *error = "the scene cannot run a trial: " + *error;
    return false;
  }
  results->assign(cells.size(), std::vector<MapTrial>(static_cast<std::size_t>(seeds)));
  JobSet set;
  set.count = jobs.size();
  set.cost = [&](std::size_t i) { return EstimatedTrialCost(jobs[i].config); };
  ApproachCache approaches(m);  // rows as without it, to the bit
  set.run = [&](std::size_t i) {
    const TrialResult r = RunGuardedTrial(m, jobs[i].config, &approaches);
    std::ostringstream os;
    os.precision(17);
    os << OutcomeName(r.outcome) << ' ' << r.metrics.dr_mm << ' ' << r.metrics.sigma_r_mm << ' '
       << r.metrics.s_c;
    return os.str();
  };
  ScopedTrialErrorGuard guard;
  JobRunnerOptions options;
  options.threads = threads;
  options.results_on_all_ranks = true;
  const JobRunStats stats = RunJobs(set, options, [&](std::size_t i, const std::string& row) {
    MapTrial t;
    std::istringstream is(row);
    is >> t.outcome >> t.dr_mm >> t.sigma_r_mm >> t.s_c;
    const std::size_t rep = i % static_cast<std::size_t>(seeds);
    (*results)[jobs[i].cell][rep] = t;
  });
  if (stats.interrupted) {
    *error = "interrupted";
    return false;
  }
  return true;
}

}  // namespace ssc
