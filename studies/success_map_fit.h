// `ssc calibrate --dynamic`: fits the robot effects (trial/robot_effects.h) and the
// real loop's timing GLOBALLY to the published success map at dL 5 mm together with the Fig. 6
// targets (dr against P_ref; sigma_r and s_c against beta). No per-cell parameters, no outcome
// tables: each parameter is physical, with a unit and a range argued from the hardware
// (docs/fidelity.md). The objective uses the same seeds in every evaluation (common random
// numbers; the sweep's seeds, never chosen to match). NLopt (BOBYQA, or Sbplx) on the unit cube.
#ifndef SSC_STUDIES_SUCCESS_MAP_FIT_H_
#define SSC_STUDIES_SUCCESS_MAP_FIT_H_

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "runtime/trial.h"
#include "studies/scores/map_scores.h"
#include "studies/scores/metric_targets.h"
#include "studies/validation.h"

namespace ssc {

// A fitted parameter: where it lives in the trial config, its unit and the range the fit searches.
struct DynamicParameter {
  const char* key;
  const char* unit;
  double min, max;
  double* (*trial_field)(TrialConfig*);  // the loop's own parameters
  const EffectKey* effect;               // or a robot effect's key (its table holds the range)
  double* field(TrialConfig* c) const {
    return effect ? effect->field(&c->effects) : trial_field(c);
  }
};
// Every parameter the dynamic fit may move: period, servo smoothing and damping, then each
// effect key with a fit range (EffectKeys()).
const std::vector<DynamicParameter>& DynamicParameters();
// "" when `keys` name at least one parameter, each a DynamicParameters() key, none twice; else
// the problem, listing the valid keys.
std::string CheckDynamicKeys(const std::vector<std::string>& keys);

struct DynamicFitSpec {
  TrialConfig base;               // the starting point (its values are the start)
  std::vector<std::string> keys;  // parameters to fit (DynamicParameters keys)
  std::vector<MapCell> cells;     // the training map
  int seeds = 3;                  // trials per cell per evaluation
  std::uint64_t seed = 1;
  int threads = 1;
  int max_evaluations = 40;
  // cost = map log-loss + weight * mean(min((res/tol)^2, 25)): the map leads, the Fig. 6
  // targets break ties and pull the wander toward the published size.
  double metric_weight = 0.02;
  std::string algorithm = "bobyqa";  // or "sbplx"
};

// The fit's cells: the map at `map_path` (ReadPublishedMap) and the published outcomes beside it
// (PublishedOutcomeCells) that the map does not hold.
bool ReadDynamicFitCells(const std::string& map_path, std::vector<MapCell>* cells,
                         std::string* error);

struct DynamicFitResult {
  TrialConfig best;
  std::vector<double> values;  // fitted values of spec.keys
  double cost = 0, start_cost = 0;
  MapScore score;                     // of the best point (its seeds)
  std::vector<MetricTarget> targets;  // at the best point
  int evaluations = 0;
  double wall_s = 0;
};

// One evaluation (also used to report the start and the best point).
bool EvaluateDynamic(const mjModel* m, const DynamicFitSpec& spec, const TrialConfig& config,
                     double* cost, MapScore* score, std::vector<MetricTarget>* targets,
                     std::string* error);

// `log` (optional) gets one line per evaluation.
bool FitDynamic(const mjModel* m, const DynamicFitSpec& spec,
                const std::function<void(const std::string&)>& log, DynamicFitResult* result,
                std::string* error);

// A fit's start and best point scored again on seeds the fit never saw (a fit on common seeds
// also fits their noise): base seed `holdout_seed`, or the next one when it is the fit's own.
struct HeldOutScores {
  std::uint64_t seed = 0;
  double start_cost = 0, best_cost = 0;
  MapScore start, best;
};
bool ScoreOnHeldOutSeeds(const mjModel* m, const DynamicFitSpec& spec, const TrialConfig& best,
                         std::uint64_t holdout_seed, HeldOutScores* scores, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_SUCCESS_MAP_FIT_H_
