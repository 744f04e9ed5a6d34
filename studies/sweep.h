// Parameter sweeps: a grid of P_ref x beta x step x repeats, run by the job runner
// (studies/jobs/job_runner.h: threads, and MPI ranks under mpirun), one CSV row per trial appended
// and flushed by rank 0 as each trial ends (in the runner's handout order). Re-running the same
// sweep resumes: rows already in the CSV (same pref, beta, step, repeat) are skipped. Seeds depend
// only on the base seed and the grid point, so any thread count gives the same rows.
#ifndef SSC_STUDIES_SWEEP_H_
#define SSC_STUDIES_SWEEP_H_

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runtime/approach_cache.h"
#include "runtime/guarded_trial.h"
#include "runtime/trial.h"

namespace ssc {

struct SweepSpec {
  std::string scene_name;  // written into each row
  TrialConfig base;        // everything but P_ref, beta, step, seed
  std::vector<double> pref_pa, beta, step_mm;
  // Explicit grid points (P_ref Pa, beta, step mm), e.g. a published map's cells; when set,
  // they replace the product of the three lists above.
  std::vector<std::array<double, 3>> points;
  int repeats = 3;
  std::uint64_t seed = 1;
  int threads = 1;
  std::string out_csv;
  // Simulate each distinct approach once and start the other trials from it
  // (runtime/approach_cache.h); the rows are the same either way.
  bool share_approach = true;
};

struct SweepProgress {
  int done = 0, total = 0, skipped = 0;
  double elapsed_s = 0;
};

struct SweepSummary {
  int total = 0, skipped = 0, ran = 0;
  double wall_s = 0;
  int ranks = 1, threads = 1;
  std::vector<double> rank_busy_s;   // trial time summed per rank (rank 0's view)
  double balance_max_over_mean = 1;  // max / mean of rank_busy_s
  double longest_trial_s = 0;
  bool interrupted = false;  // SIGINT/SIGTERM: finished rows kept, re-run to resume
  // The shared approach on this rank (all zero when off): approaches simulated, trials resumed
  // from one, trials run from scratch because sharing is impossible (and why).
  ApproachCache::Counts approach;
  std::string approach_unshareable;
};

// Seed of one grid point (stable across thread counts and runs).
std::uint64_t TrialSeed(std::uint64_t base, double pref, double beta, double step, int repeat);

// Estimated simulated time of a trial (for the longest-first handout).
double EstimatedTrialCost(const TrialConfig& c);

// Runs the sweep on `m` (shared read-only by the threads). Collective under MPI: every rank
// calls it; rank 0 writes the CSV. `progress` (optional) is called on rank 0 after each row. False
// + *error on I/O or spec errors; trial failures, instabilities and MuJoCo errors are rows, not
// errors.
// The spec's grid without running it: every point's trial config valid, at least one point and
// one repeat. "" or the first problem, naming the point. RunSweep checks it first.
std::string CheckSweepGrid(const SweepSpec& spec);

bool RunSweep(const mjModel* m, const SweepSpec& spec,
              const std::function<void(const SweepProgress&)>& progress, SweepSummary* summary,
              std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_SWEEP_H_
