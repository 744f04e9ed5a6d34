// Inside the job runner (studies/jobs/job_runner.h): the worker threads of one rank, and the link
// to the other ranks (job_transport.h). Not for studies' own use.
#ifndef SSC_STUDIES_JOBS_JOB_WORKERS_H_
#define SSC_STUDIES_JOBS_JOB_WORKERS_H_

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "studies/jobs/job_runner.h"

namespace ssc {
namespace job_runner_detail {

inline constexpr std::size_t kNone = static_cast<std::size_t>(-1);  // no job: stop

// True after SIGINT/SIGTERM during a run (the runner's signal handler sets it).
bool StopRequested();

struct Finished {
  std::size_t index;
  std::string result;
  double busy_s;
};

// Worker threads of one rank: `take` gives the next job index (kNone: stop); results queue up
// for the rank's main thread.
class LocalWorkers {
 public:
  LocalWorkers(const JobSet& jobs, int threads, std::function<std::size_t()> take);
  ~LocalWorkers();
  LocalWorkers(const LocalWorkers&) = delete;
  LocalWorkers& operator=(const LocalWorkers&) = delete;

  // Waits up to `timeout` for results; moves them out.
  std::deque<Finished> Collect(std::chrono::microseconds timeout);
  bool AllExited();

 private:
  bool AllExitedLocked() const { return exited_ == static_cast<int>(pool_.size()); }
  void Work();

  const JobSet& jobs_;
  std::function<std::size_t()> take_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<Finished> finished_;
  int exited_ = 0;
  std::vector<std::thread> pool_;
};

}  // namespace job_runner_detail
}  // namespace ssc

#endif  // SSC_STUDIES_JOBS_JOB_WORKERS_H_
