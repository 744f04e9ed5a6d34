#include "studies/jobs/job_runner.h"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <numeric>

#include "studies/jobs/job_transport.h"
#include "studies/jobs/job_workers.h"

namespace ssc {
namespace job_runner_detail {
namespace {

using Clock = std::chrono::steady_clock;

volatile sig_atomic_t g_stop = 0;

extern "C" void OnStopSignal(int sig) {
  g_stop = 1;
  signal(sig, SIG_DFL);  // a second signal ends the process
}

// SIGINT/SIGTERM set the stop flag while a run is in progress.
class ScopedStopSignals {
 public:
  ScopedStopSignals() {
    g_stop = 0;
    struct sigaction sa;
    std::memset(&sa, 0, sizeof(sa));
    sa.sa_handler = OnStopSignal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~ScopedStopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  ScopedStopSignals(const ScopedStopSignals&) = delete;
  ScopedStopSignals& operator=(const ScopedStopSignals&) = delete;

 private:
  struct sigaction old_int_, old_term_;
};

// Rank 0: hands the jobs out in HandoutOrder to its own threads and, through `remote`, to the
// other ranks; delivers the results in that order (all at once, out of order, on a stop).
class Rank0Run {
 public:
  Rank0Run(const JobSet& jobs, const JobRunnerOptions& opt, const DeliverFn& deliver,
           JobRunStats* stats)
      : jobs_(jobs), opt_(opt), deliver_(deliver), stats_(stats), order_(HandoutOrder(jobs)) {
    stats_->skipped = jobs.count - order_.size();
    position_.assign(jobs.count, kNone);
    for (std::size_t p = 0; p < order_.size(); ++p) position_[order_[p]] = p;
    stats_->rank_busy_s.assign(static_cast<std::size_t>(stats_->ranks), 0.0);
  }

  void Run() {
    auto take = [this] { return Take(); };
    auto hand_in = [this](Finished f, int from_rank) { HandIn(std::move(f), from_rank); };
    const std::unique_ptr<RemoteRanks> remote = MakeRemoteRanks(stats_->ranks, opt_.threads);
    LocalWorkers workers(jobs_, opt_.threads, take);
    while (true) {
      for (Finished& f : workers.Collect(std::chrono::milliseconds(stats_->ranks > 1 ? 1 : 50))) {
        HandIn(std::move(f), 0);
      }
      remote->Poll(take, hand_in);
      if (g_stop) {
        // Keep every finished result now: out of order, but whole.
        stats_->interrupted = true;
        for (auto& [p, f] : buffer_) DeliverOne(f);
        buffer_.clear();
      }
      while (!buffer_.empty() && buffer_.begin()->first == next_delivery_) {
        DeliverOne(buffer_.begin()->second);
        buffer_.erase(buffer_.begin());
        ++next_delivery_;
      }
      // Interrupted: jobs still running on dead or stopping ranks are not waited for.
      const bool remote_done = g_stop || remote->Done();
      if (workers.AllExited() && remote_done && buffer_.empty()) break;
    }
  }

  // With results_on_all_ranks on several ranks: what rank 0 delivered, in order.
  std::vector<std::string> all_results;
  std::vector<std::size_t> delivered_order;

 private:
  std::size_t Take() {
    std::lock_guard<std::mutex> lock(handout_mutex_);
    if (g_stop || handed_ >= order_.size()) return kNone;
    return order_[handed_++];
  }
  void HandIn(Finished f, int from_rank) {
    stats_->rank_busy_s[static_cast<std::size_t>(from_rank)] += f.busy_s;
    stats_->longest_job_s = std::max(stats_->longest_job_s, f.busy_s);
    const std::size_t p = position_[f.index];
    buffer_.emplace(p, std::move(f));
  }
  void DeliverOne(const Finished& f) {
    deliver_(f.index, f.result);
    ++stats_->ran;
    if (opt_.results_on_all_ranks && stats_->ranks > 1) {
      all_results.push_back(f.result);
      delivered_order.push_back(f.index);
    }
  }

  const JobSet& jobs_;
  const JobRunnerOptions& opt_;
  const DeliverFn& deliver_;
  JobRunStats* stats_;
  const std::vector<std::size_t> order_;
  std::vector<std::size_t> position_;
  std::mutex handout_mutex_;
  std::size_t handed_ = 0;
  std::map<std::size_t, Finished> buffer_;  // finished, by handout position
  std::size_t next_delivery_ = 0;
};

}  // namespace

bool StopRequested() { return g_stop != 0; }

LocalWorkers::LocalWorkers(const JobSet& jobs, int threads, std::function<std::size_t()> take)
    : jobs_(jobs), take_(std::move(take)) {
  for (int t = 0; t < threads; ++t) pool_.emplace_back([this] { Work(); });
}

LocalWorkers::~LocalWorkers() {
  for (std::thread& t : pool_) t.join();
}

std::deque<Finished> LocalWorkers::Collect(std::chrono::microseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  cv_.wait_for(lock, timeout, [this] { return !finished_.empty() || AllExitedLocked(); });
  std::deque<Finished> out;
  out.swap(finished_);
  return out;
}

bool LocalWorkers::AllExited() {
  std::lock_guard<std::mutex> lock(mutex_);
  return AllExitedLocked() && finished_.empty();
}

void LocalWorkers::Work() {
  for (std::size_t i = take_(); i != kNone; i = take_()) {
    const auto t0 = Clock::now();
    std::string result;
    try {
      result = jobs_.run(i);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "job runner: job %zu threw: %s\n", i, e.what());
      std::abort();
    }
    const double busy = std::chrono::duration<double>(Clock::now() - t0).count();
    std::lock_guard<std::mutex> lock(mutex_);
    finished_.push_back({i, std::move(result), busy});
    cv_.notify_all();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++exited_;
  cv_.notify_all();
}

}  // namespace job_runner_detail

using job_runner_detail::Rank0Run;

double JobRunStats::BalanceMaxOverMean() const {
  if (rank_busy_s.empty()) return 1;
  const double sum = std::accumulate(rank_busy_s.begin(), rank_busy_s.end(), 0.0);
  const double mean = sum / static_cast<double>(rank_busy_s.size());
  return mean > 0 ? *std::max_element(rank_busy_s.begin(), rank_busy_s.end()) / mean : 1;
}

std::vector<std::size_t> HandoutOrder(const JobSet& jobs) {
  std::vector<std::size_t> order;
  std::vector<double> cost(jobs.count, 0.0);
  for (std::size_t i = 0; i < jobs.count; ++i) {
    if (jobs.skip && jobs.skip(i)) continue;
    order.push_back(i);
    if (jobs.cost) cost[i] = jobs.cost(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

JobRunStats RunJobs(const JobSet& jobs, const JobRunnerOptions& options, const DeliverFn& deliver) {
  JobRunStats stats;
  stats.total = jobs.count;
  stats.threads = std::max(1, options.threads);
  stats.ranks = JobRunnerRankCount();
  const int rank = JobRunnerRank();
  JobRunnerOptions opt = options;
  opt.threads = stats.threads;
  const auto t0 = job_runner_detail::Clock::now();
  job_runner_detail::ScopedStopSignals signals;

  std::vector<std::string> all_results;
  std::vector<std::size_t> delivered_order;
  if (rank != 0) {
    job_runner_detail::RunWorkerRank(jobs, opt.threads, &stats);
  } else {
    Rank0Run run(jobs, opt, deliver, &stats);
    run.Run();
    all_results = std::move(run.all_results);
    delivered_order = std::move(run.delivered_order);
  }
  stats.wall_s = std::chrono::duration<double>(job_runner_detail::Clock::now() - t0).count();
  if (stats.ranks > 1 && opt.results_on_all_ranks && !stats.interrupted) {
    job_runner_detail::ShareResults(delivered_order, all_results, deliver);
  }
  return stats;
}

std::vector<std::string> RunJobsCollect(const JobSet& jobs, const JobRunnerOptions& options,
                                        JobRunStats* stats) {
  std::vector<std::string> results(jobs.count);
  const JobRunStats s =
      RunJobs(jobs, options, [&](std::size_t i, const std::string& r) { results[i] = r; });
  if (stats) *stats = s;
  return results;
}

}  // namespace ssc
