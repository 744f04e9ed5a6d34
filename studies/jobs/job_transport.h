// How the job runner (studies/jobs/job_runner.h) reaches the other ranks: MPI when the build found
// it (job_transport_mpi.cc), a single rank otherwise (job_transport_local.cc).
// studies/CMakeLists.txt compiles exactly one of the two.
#ifndef SSC_STUDIES_JOBS_JOB_TRANSPORT_H_
#define SSC_STUDIES_JOBS_JOB_TRANSPORT_H_

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "studies/jobs/job_runner.h"
#include "studies/jobs/job_workers.h"

namespace ssc {
namespace job_runner_detail {

// A rank other than 0: asks rank 0 for one job per thread, runs them on `threads` workers and
// sends each result back (a result asks for the next job), until every thread was told to end
// or a stop was requested. Fills stats->ran, longest_job_s, rank_busy_s, interrupted.
void RunWorkerRank(const JobSet& jobs, int threads, JobRunStats* stats);

// Rank 0's side of the other ranks: answers their requests for jobs and takes their results in.
class RemoteRanks {
 public:
  virtual ~RemoteRanks() = default;
  // Handles every message waiting now: `take` gives the job to hand out (kNone: none left, which
  // ends that worker thread); `hand_in` receives a result and the rank it came from.
  virtual void Poll(const std::function<std::size_t()>& take,
                    const std::function<void(Finished, int)>& hand_in) = 0;
  // Every remote thread was told to end and none still runs a job.
  virtual bool Done() const = 0;
};
// `ranks` ranks in all (rank 0 included), `threads` workers on each.
std::unique_ptr<RemoteRanks> MakeRemoteRanks(int ranks, int threads);

// After a run with results_on_all_ranks: rank 0's results, in its delivery order (`indices`),
// reach `deliver` on every other rank. Collective; a no-op on one rank.
void ShareResults(const std::vector<std::size_t>& indices, const std::vector<std::string>& results,
                  const DeliverFn& deliver);

}  // namespace job_runner_detail
}  // namespace ssc

#endif  // SSC_STUDIES_JOBS_JOB_TRANSPORT_H_
