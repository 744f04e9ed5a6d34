// One runner for every study that runs many independent trials (sweeps, object maps, validation
// maps, calibration objectives): a list of jobs in, one result per job out.
//
// Jobs are handed out longest-first (by an estimated cost) to worker threads and, when the
// program was built with MPI and started under mpirun, to the threads of every rank; rank 0
// hands out the work (dynamically, one job per free worker) and receives every result. Results
// reach `deliver` on rank 0 one at a time, from one thread, in the handout order (cost
// descending, then index): a threaded run and an MPI run of the same jobs deliver the same
// results in the same order, each as soon as the jobs handed out before it have finished.
//
// Interruption (SIGINT/SIGTERM while running): no new job starts, every finished result is
// delivered at once (out of order), jobs already running on rank 0 finish and are delivered;
// the stats say `interrupted`. A second signal ends the process the default way.
#ifndef SSC_STUDIES_JOBS_JOB_RUNNER_H_
#define SSC_STUDIES_JOBS_JOB_RUNNER_H_

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace ssc {

struct JobSet {
  std::size_t count = 0;  // jobs 0 .. count-1: the same list on every rank
  // Estimated relative cost of a job (e.g. simulated seconds); unset: all equal (index order).
  std::function<double(std::size_t)> cost;
  // True for a job already done (resume). Asked on rank 0 only, so only rank 0 reads old output.
  std::function<bool(std::size_t)> skip;
  // Runs one job on any rank and any thread; the result as bytes (a CSV row, a serialised
  // struct). Must not throw.
  std::function<std::string(std::size_t)> run;
};

struct JobRunnerOptions {
  int threads = 1;  // worker threads on each rank, >= 1
  // MPI: every rank receives all results at the end (studies whose next step depends on them
  // on every rank, e.g. an optimiser that runs in lock-step on all ranks).
  bool results_on_all_ranks = false;
};

struct JobRunStats {
  std::size_t total = 0, skipped = 0, ran = 0;  // ran = delivered results
  int ranks = 1, threads = 1;
  double wall_s = 0;
  std::vector<double> rank_busy_s;  // sum of job run times on each rank (thread-seconds)
  double longest_job_s = 0;
  bool interrupted = false;
  // Load balance: max / mean of rank busy time (1 = perfect).
  double BalanceMaxOverMean() const;
};

// Called on rank 0 only, one result at a time from one thread.
using DeliverFn = std::function<void(std::size_t index, const std::string& result)>;

// Runs every job that `skip` does not exclude. Collective under MPI: every rank calls it with
// the same JobSet.count and options. `deliver` runs on rank 0 (and, with results_on_all_ranks,
// on every rank after all jobs finished, in the same order).
JobRunStats RunJobs(const JobSet& jobs, const JobRunnerOptions& options, const DeliverFn& deliver);

// The same, collecting the results by job index (empty for skipped jobs): on rank 0, and on
// every rank with options.results_on_all_ranks (e.g. an objective summed on every rank).
std::vector<std::string> RunJobsCollect(const JobSet& jobs, const JobRunnerOptions& options,
                                        JobRunStats* stats = nullptr);

// The handout order: indices not skipped, cost descending, ties by index. Exposed for tests.
std::vector<std::size_t> HandoutOrder(const JobSet& jobs);

// MPI plumbing, all no-ops without MPI. InitJobRunnerMpi starts MPI only when the process was
// launched by mpirun (so a plain `ssc ...` never pays for or depends on MPI start-up).
void InitJobRunnerMpi(int* argc, char*** argv);
void FinalizeJobRunnerMpi(bool abort);
int JobRunnerRank();       // 0 without MPI
int JobRunnerRankCount();  // 1 without MPI

}  // namespace ssc

#endif  // SSC_STUDIES_JOBS_JOB_RUNNER_H_
