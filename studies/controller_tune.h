// `ssc tune`: a derivative-free search (NLopt) of a controller's parameters on the twin for the
// fastest following that keeps a success rate. Each evaluation is a small sweep: the same seeds
// at every point (common random numbers, so two points differ by their parameters, not their
// draws), the robot effects of the base config. The score is the mean follow speed of the
// successful trials, less a penalty per unit of success rate below the target; every evaluation
// is kept, and the speed-success Pareto front of all of them (and of the reference controllers run
// on the same seeds) is what the chart shows.
#ifndef SSC_STUDIES_CONTROLLER_TUNE_H_
#define SSC_STUDIES_CONTROLLER_TUNE_H_

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "controller/controller_registry.h"
#include "studies/sweep.h"

namespace ssc {

// One searched parameter: a key of the controller's table, or of the law (pref_pa, beta,
// step_mm), between lo and hi.
struct TuneKey {
  std::string key;
  double lo = 0, hi = 0;
  int controller_index = -1;  // index in the controller's keys; -1: a law key
};

// The law's keys a search may vary besides the controller's.
inline constexpr std::array<const char*, 3> kTuneLawKeys = {"pref_pa", "beta", "step_mm"};

// Parses "key=lo:hi,..." against `type`'s keys and the law's: each key known and given once,
// lo < hi, both within the key's range. False + *error naming the key and its range.
bool ParseTuneSearch(const ControllerType& type, const std::string& text,
                     std::vector<TuneKey>* keys, std::string* error);

// "" when the box of `keys` (with the controller's other keys at `base`'s values) holds a point
// that keeps every rule between the controller's keys (ControllerType::orders), else why not,
// naming each rule broken, its keys and their ranges. Exact: the rules order pairs of keys, so
// tightening each key's range along them until nothing moves leaves a range empty exactly when
// no point keeps them all.
std::string CheckTuneBox(const std::vector<TuneKey>& keys, const ControllerChoice& base);

// Every search key's value as `config` holds it (the controller's values or the law's).
std::vector<double> TuneValues(const std::vector<TuneKey>& keys, const TrialConfig& config);
// `config` with the search keys set to `values` (one per key).
TrialConfig WithTuneValues(const std::vector<TuneKey>& keys, const std::vector<double>& values,
                           TrialConfig config);

// Below the target success rate each unit of shortfall costs this much speed: a point 10 % short
// scores 100 mm/s less, more than any speed on the disk makes up for.
inline constexpr double kTuneShortfallPenaltyMmS = 1000.0;

// The search's score (maximised): the mean speed of the successful trials, mm/s (0 without any),
// less kTuneShortfallPenaltyMmS x (min_success - successes / trials) when the rate is below it.
double TuneScore(int successes, int trials, double mean_speed_mm_s, double min_success);

// The indices of the points no other point beats in both speed and success (higher is better in
// each; a point equal to another in both is kept once, the first), in order of rising speed.
std::vector<std::size_t> ParetoFront(const std::vector<std::array<double, 2>>& speed_success);

// What one evaluation gave.
struct TuneEvaluation {
  std::string label;           // "eval N", or a reference controller's name
  std::string controller;      // ControllerChoice::Text() plus the law's keys searched
  std::vector<double> values;  // the searched keys' values (empty for a reference)
  int trials = 0, successes = 0;
  std::array<double, 2> success_ci{};  // Wilson 95 %
  double speed_mm_s = 0;               // mean over the successful trials
  double speed_ci_mm_s = 0;            // half-width, t 95 % (0 with fewer than 2 successes)
  double score = 0;
  bool pareto = false;
  // Why the point was not run ("" when it ran): it breaks a rule between the controller's keys.
  // Such a point has no trials, scores the worst a run point can (TuneScore with no success) for
  // the optimiser, and is never the best nor on the Pareto front.
  std::string refused;
};

struct TuneSpec {
  SweepSpec sweep;  // scene, base config (controller and its values), one P_ref/beta/dL, seed
  std::vector<TuneKey> keys;
  int seeds = 6;         // trials per evaluation
  int evaluations = 12;  // NLopt's budget (the start point included)
  double min_success = 0.9;
  std::string algorithm = "bobyqa";  // or "sbplx", "cobyla"
  std::string out_dir;               // evals/<label>/sweep.csv, tune.csv, tune.json
  // Run on the same seeds and placed on the chart (e.g. the published law, the defaults).
  std::vector<std::pair<std::string, TrialConfig>> references;
};

struct TuneResult {
  std::vector<TuneEvaluation> evaluations;  // the references first, then the search in order
  int best = -1;    // index of the best search evaluation by score (-1: none ran)
  int refused = 0;  // search points not run (TuneEvaluation::refused)
  double wall_s = 0;
};

// Runs the references and the search; writes tune.csv (one row per evaluation). `log` gets one
// line per evaluation. False + *error, before anything runs, when CheckTuneBox refuses the box;
// on I/O or an invalid point.
bool RunTune(const mjModel* m, const TuneSpec& spec,
             const std::function<void(const std::string&)>& log, TuneResult* result,
             std::string* error);

// tune.csv's header and the row of one evaluation (values of the keys searched, blank for a
// reference; a refused point's rate, intervals and speed blank; the last column, outcome, is
// "ran" or "refused: " and why).
std::string TuneCsvHeader(const std::vector<TuneKey>& keys);
std::string TuneCsvRow(const TuneEvaluation& e, std::size_t keys);

}  // namespace ssc

#endif  // SSC_STUDIES_CONTROLLER_TUNE_H_
