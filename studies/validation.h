// `ssc validate`: the twin on every cell of a published success map, scored
// (studies/scores/map_scores.h). Trials run through the sweep (studies/sweep.h: the job runner,
// threads and MPI ranks, rows flushed as trials end, resumable) with the sweep's seeds, so the
// first three repeats of a cell are exactly the rows `ssc sweep --seed S` gives for it.
#ifndef SSC_STUDIES_VALIDATION_H_
#define SSC_STUDIES_VALIDATION_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runtime/trial.h"
#include "studies/map_ceiling.h"
#include "studies/scores/map_scores.h"
#include "studies/sweep.h"

namespace ssc {

// Reads a published map: CSV with the header `step_mm,beta,pref_pa,successes_of_3` and one row
// per cell (class "3", "2" or "<=1"). Errors name the file, line, column and the valid range.
bool ReadPublishedMap(const std::string& path, std::vector<MapCell>* cells, std::string* error);

struct ValidateSpec {
  std::string map_path;
  std::string scene_name;
  TrialConfig base;        // everything but P_ref, beta, step and seed
  int seeds = 10;          // trials per cell (>= 3: the first 3 give the class match)
  std::uint64_t seed = 1;  // base seed, as `ssc sweep --seed`
  int threads = 1;
  std::string out_dir;         // trials.csv (resumable), cells.csv, validate.json
  bool share_approach = true;  // as SweepSpec::share_approach
};

// Reads the map and checks every cell's trial config (with spec.base) without running or
// writing anything; fills the cells and the sweep RunValidation runs. RunValidation calls it.
bool PrepareValidation(const ValidateSpec& spec, std::vector<MapCell>* cells, SweepSpec* sweep,
                       std::string* error);

struct MetricTarget;  // studies/scores/metric_targets.h

// Runs and scores. Rank 0 writes the files and fills *score (and, when given, *fig6: the
// published Fig. 6 targets measured on the map's cells, in validate.json too); other ranks only
// run trials.
bool RunValidation(const mjModel* m, const ValidateSpec& spec,
                   const std::function<void(const SweepProgress&)>& progress, MapScore* score,
                   SweepSummary* summary, std::string* error,
                   std::vector<MetricTarget>* fig6 = nullptr, MapCeilings* ceilings = nullptr);

// Runs `seeds` trials of each cell with `base` (seeds as the sweep's). Rank 0 gets the results
// (MPI: every rank, since an optimiser runs in lock-step on all ranks).
bool RunMapTrials(const mjModel* m, const std::vector<MapCell>& cells, const TrialConfig& base,
                  int seeds, std::uint64_t seed, int threads,
                  std::vector<std::vector<MapTrial>>* results, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_VALIDATION_H_
