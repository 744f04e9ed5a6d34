// The job runner's transport when the build has no MPI (studies/jobs/job_transport.h): one rank, so
// there is nobody to reach.
#include <cstdlib>

#include "studies/jobs/job_transport.h"

namespace ssc {
namespace job_runner_detail {
namespace {

class NoRemoteRanks : public RemoteRanks {
 public:
  void Poll(const std::function<std::size_t()>&,
            const std::function<void(Finished, int)>&) override {}
  bool Done() const override { return true; }
};

}  // namespace

std::unique_ptr<RemoteRanks> MakeRemoteRanks(int, int) { return std::make_unique<NoRemoteRanks>(); }

// Never called: without MPI every process is rank 0.
void RunWorkerRank(const JobSet&, int, JobRunStats*) { std::abort(); }

void ShareResults(const std::vector<std::size_t>&, const std::vector<std::string>&,
                  const DeliverFn&) {}

}  // namespace job_runner_detail

void InitJobRunnerMpi(int*, char***) {}
void FinalizeJobRunnerMpi(bool) {}
int JobRunnerRank() { return 0; }
int JobRunnerRankCount() { return 1; }

}  // namespace ssc
