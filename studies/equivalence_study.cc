#include "studies/equivalence_study.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "studies/jobs/job_runner.h"
#include "studies/success_map_fit.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

std::vector<TargetMeasure> Measures(const std::vector<MetricTarget>& targets) {
  std::vector<TargetMeasure> out;
  for (const MetricTarget& t : targets) {
    out.push_back({t.name, t.published, t.tolerance, t.model, t.standard_error, t.successes});
  }
  return out;
}

std::vector<ArmCounts> Counts(const MapScore& score) {
  std::vector<ArmCounts> out;
  for (const CellScore& c : score.cells) out.push_back({c.successes, c.trials});
  return out;
}

std::string PluginText(const PluginConfig& plugin) {
  std::string text;
  for (const auto& [key, value] : plugin) text += (text.empty() ? "" : ",") + key + "=" + value;
  return text;
}

ValidateSpec ArmValidation(const EquivalenceSpec& spec, const EquivalenceArm& arm,
                           const std::string& folder) {
  ValidateSpec v;
  v.map_path = spec.map_path;
  v.scene_name = arm.scene_name;
  v.base = arm.base;
  v.seeds = spec.seeds;
  v.seed = arm.seed;
  v.threads = spec.threads;
  v.out_dir = spec.out_dir + "/" + folder;
  v.share_approach = spec.share_approach;
  return v;
}

nlohmann::json ArmJson(const EquivalenceArm& arm, const MapScore& score,
                       const SweepSummary& summary, const std::string& folder) {
  double busy_s = 0;
  for (double b : summary.rank_busy_s) busy_s += b;
  return {{"scene", arm.scene_name},
          {"plugin", PluginText(arm.plugin)},
          {"effects", FormatRobotEffects(arm.base.effects)},
          {"base_seed", arm.seed},
          {"trials_dir", folder},
          {"expected_agreement", score.expected_agreement},
          {"expected_agreement_interval", score.agreement_interval},
          {"class_match", score.class_match},
          {"opposite_cells", score.opposite},
          {"trials_run", summary.ran},
          {"wall_s", summary.wall_s},
          {"trial_busy_s", busy_s}};
}

bool WriteFiles(const EquivalenceSpec& spec, const EquivalenceRun& run, std::string* error) {
  const Equivalence& e = run.result;
  const std::string csv = spec.out_dir + "/equivalence.csv";
  std::ofstream c(csv);
  c.precision(10);
  c << "step_mm,beta,pref_pa,published,successes_reference,trials_reference,"
       "successes_candidate,trials_candidate,rate_reference,rate_candidate,"
       "agreement_reference,agreement_candidate,fisher_p,differs,false_alarm_chance\n";
  for (const CellDifference& d : e.cells) {
    c << d.cell.step_mm << ',' << d.cell.beta << ',' << d.cell.pref_pa << ','
      << MapClassName(d.cell.published) << ',' << d.a.successes << ',' << d.a.trials << ','
      << d.b.successes << ',' << d.b.trials << ',' << d.rate_a << ',' << d.rate_b << ','
      << d.agreement_a << ',' << d.agreement_b << ',' << d.p_value << ',' << (d.differs ? 1 : 0)
      << ',' << d.false_alarm_chance << '\n';
  }
  if (!c) {
    *error = csv + ": write failed";
    return false;
  }
  // JSON has no NaN: a target that cannot be measured is null.
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json j;
  j["map"] = spec.map_path;
  j["seeds_per_cell"] = spec.seeds;
  j["alpha"] = e.differing.alpha;
  j["reference"] = ArmJson(spec.reference, run.reference_score, run.reference_summary, "reference");
  j["candidate"] = ArmJson(spec.candidate, run.candidate_score, run.candidate_summary, "candidate");
  j["cells"] = {{"cells", e.differing.cells},
                {"differing", e.differing.differing},
                {"expected_by_chance", e.differing.expected_by_chance},
                {"nominal_by_chance", e.differing.nominal_by_chance},
                {"p_at_least", e.differing.p_at_least}};
  j["success_shift"] = {{"reference_successes", e.shift.successes_a},
                        {"reference_trials", e.shift.trials_a},
                        {"candidate_successes", e.shift.successes_b},
                        {"candidate_trials", e.shift.trials_b},
                        {"cmh_p", e.shift.p_value}};
  j["score"] = {{"reference", e.score.a},
                {"candidate", e.score.b},
                {"difference", e.score.difference},
                {"difference_interval", e.score.interval},
                {"posterior_p", e.score.p_value}};
  j["fig6_targets"] = nlohmann::json::array();
  for (const TargetDifference& t : e.targets) {
    j["fig6_targets"].push_back({{"name", t.name},
                                 {"published", t.published},
                                 {"tolerance", t.tolerance},
                                 {"reference", number(t.a.mean)},
                                 {"reference_standard_error", number(t.a.standard_error)},
                                 {"reference_successes", t.a.n},
                                 {"candidate", number(t.b.mean)},
                                 {"candidate_standard_error", number(t.b.standard_error)},
                                 {"candidate_successes", t.b.n},
                                 {"difference", number(t.difference)},
                                 {"difference_standard_error", number(t.standard_error)},
                                 {"welch_p", number(t.p_value)},
                                 {"differs", t.differs}});
  }
  j["targets"] = {{"tested", e.targets_tested},
                  {"differing", e.targets_differing},
                  {"p_at_least", e.targets_p_at_least}};
  j["verdict"] = {{"views", e.views},
                  {"level_per_view", e.differing.alpha / e.views},
                  {"cells_beyond_chance", e.cells_beyond_chance},
                  {"shift_differs", e.shift_differs},
                  {"score_differs", e.score_differs},
                  {"targets_beyond_chance", e.targets_beyond_chance},
                  {"same", e.same}};
  const std::string json_path = spec.out_dir + "/equivalence.json";
  std::ofstream js(json_path);
  js << j.dump(2) << '\n';
  if (!js) {
    *error = json_path + ": write failed";
    return false;
  }
  return true;
}

}  // namespace

ModelPtr LoadArmModel(const EquivalenceArm& arm, std::string* error) {
  const std::string path = ResolveScenePath(arm.scene_name);
  ModelPtr m =
      arm.plugin.empty() ? LoadModel(path, error) : ToolModelVariant(path, arm.plugin, error);
  if (!m) *error = arm.scene_name + ": " + *error;
  return m;
}

bool RunEquivalence(const EquivalenceSpec& spec,
                    const std::function<void(int, const SweepProgress&)>& progress,
                    EquivalenceRun* run, std::string* error) {
  const std::array<const EquivalenceArm*, 2> arms = {&spec.reference, &spec.candidate};
  const std::array<std::string, 2> folders = {"reference", "candidate"};
  // Every input of both arms before any trial: the map, each cell's config, the models.
  std::array<ModelPtr, 2> models;
  std::vector<MapCell> cells;
  for (int i = 0; i < 2; ++i) {
    SweepSpec sweep;
    if (!PrepareValidation(ArmValidation(spec, *arms[i], folders[i]), &cells, &sweep, error))
      return false;
    models[i] = LoadArmModel(*arms[i], error);
    if (!models[i]) return false;
    TrialConfig first = sweep.base;
    first.law.p_ref_pa = cells.front().pref_pa;
    first.law.beta = cells.front().beta;
    first.law.step_mm = cells.front().step_mm;
    if (std::string e; !CheckTrialSetup(models[i].get(), first, &e)) {
      *error = arms[i]->scene_name + ": " + e;
      return false;
    }
  }
  std::array<MapScore*, 2> scores = {&run->reference_score, &run->candidate_score};
  std::array<SweepSummary*, 2> summaries = {&run->reference_summary, &run->candidate_summary};
  std::array<std::vector<MetricTarget>, 2> targets;
  for (int i = 0; i < 2; ++i) {
    const ValidateSpec v = ArmValidation(spec, *arms[i], folders[i]);
    std::error_code ec;
    std::filesystem::create_directories(v.out_dir, ec);
    if (ec) {
      *error = v.out_dir + ": cannot create: " + ec.message();
      return false;
    }
    auto arm_progress = [&progress, i](const SweepProgress& p) {
      if (progress) progress(i, p);
    };
    if (!RunValidation(models[i].get(), v, arm_progress, scores[i], summaries[i], error,
                       &targets[i])) {
      *error = folders[i] + " (" + arms[i]->scene_name + "): " + *error;
      return false;
    }
  }
  if (JobRunnerRank() != 0) return true;
  if (!CompareArms(cells, Counts(*scores[0]), Counts(*scores[1]), Measures(targets[0]),
                   Measures(targets[1]), spec.options, &run->result, error)) {
    return false;
  }
  return WriteFiles(spec, *run, error);
}

}  // namespace ssc
