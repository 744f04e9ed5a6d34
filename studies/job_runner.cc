#include "studies/job_runner.h"

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <numeric>
#include <thread>

#ifdef SSC_HAVE_MPI
#include <mpi.h>
#endif

namespace ssc {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

volatile sig_atomic_t g_stop = 0;
bool g_mpi_active = false;

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

struct Finished {
  std::size_t index;
  std::string result;
  double busy_s;
};

// Worker threads of one rank: `take` gives the next job index (kNone: stop); results queue up
// for the rank's main thread.
class LocalWorkers {
 public:
  LocalWorkers(const JobSet& jobs, int threads, std::function<std::size_t()> take)
      : jobs_(jobs), take_(std::move(take)) {
    for (int t = 0; t < threads; ++t) pool_.emplace_back([this] { Work(); });
  }
  ~LocalWorkers() {
    for (std::thread& t : pool_) t.join();
  }
  LocalWorkers(const LocalWorkers&) = delete;
  LocalWorkers& operator=(const LocalWorkers&) = delete;

  // Waits up to `timeout` for results; moves them out.
  std::deque<Finished> Collect(std::chrono::microseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait_for(lock, timeout, [this] { return !finished_.empty() || AllExitedLocked(); });
    std::deque<Finished> out;
    out.swap(finished_);
    return out;
  }
  bool AllExited() {
    std::lock_guard<std::mutex> lock(mutex_);
    return AllExitedLocked() && finished_.empty();
  }

 private:
  bool AllExitedLocked() const { return exited_ == static_cast<int>(pool_.size()); }
  void Work() {
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

  const JobSet& jobs_;
  std::function<std::size_t()> take_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<Finished> finished_;
  int exited_ = 0;
  std::vector<std::thread> pool_;
};

#ifdef SSC_HAVE_MPI
enum Tag : int { kTagRequest = 1, kTagResult = 2, kTagJob = 3, kTagAll = 4 };

std::string PackResult(const Finished& f) {
  std::string bytes(sizeof(std::uint64_t) + sizeof(double), '\0');
  const std::uint64_t index = f.index;
  std::memcpy(&bytes[0], &index, sizeof(index));
  std::memcpy(&bytes[sizeof(index)], &f.busy_s, sizeof(double));
  return bytes + f.result;
}

Finished UnpackResult(const std::string& bytes) {
  Finished f;
  std::uint64_t index = 0;
  std::memcpy(&index, bytes.data(), sizeof(index));
  std::memcpy(&f.busy_s, bytes.data() + sizeof(index), sizeof(double));
  f.index = static_cast<std::size_t>(index);
  f.result = bytes.substr(sizeof(index) + sizeof(double));
  return f;
}

std::string ReceiveBytes(const MPI_Status& probed) {
  int n = 0;
  MPI_Get_count(&probed, MPI_BYTE, &n);
  std::string bytes(static_cast<std::size_t>(n), '\0');
  MPI_Recv(n ? &bytes[0] : nullptr, n, MPI_BYTE, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return bytes;
}

void SendJob(int rank, std::size_t index) {
  const std::int64_t v = index == kNone ? -1 : static_cast<std::int64_t>(index);
  MPI_Send(&v, 1, MPI_INT64_T, rank, kTagJob, MPI_COMM_WORLD);
}

// A rank other than 0: asks rank 0 for one job per thread, runs them, sends each result back
// (a result asks for the next job); a -1 job ends one thread.
void RunWorkerRank(const JobSet& jobs, const JobRunnerOptions& options, JobRunStats* stats) {
  std::mutex queue_mutex;
  std::condition_variable queue_cv;
  std::deque<std::int64_t> queue;
  auto take = [&]() -> std::size_t {
    std::unique_lock<std::mutex> lock(queue_mutex);
    queue_cv.wait(lock, [&] { return !queue.empty(); });
    const std::int64_t v = queue.front();
    queue.pop_front();
    return v < 0 ? kNone : static_cast<std::size_t>(v);
  };
  for (int t = 0; t < options.threads; ++t) {
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagRequest, MPI_COMM_WORLD);
  }
  double busy = 0;
  {
    LocalWorkers workers(jobs, options.threads, take);
    int ends = 0;
    bool stopped = false;
    while (true) {
      int flag = 1;
      while (flag) {
        MPI_Status st;
        MPI_Iprobe(0, kTagJob, MPI_COMM_WORLD, &flag, &st);
        if (!flag) break;
        std::int64_t v = 0;
        MPI_Recv(&v, 1, MPI_INT64_T, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (v < 0) ++ends;
        std::lock_guard<std::mutex> lock(queue_mutex);
        queue.push_back(stopped ? -1 : v);
        queue_cv.notify_all();
      }
      if (g_stop && !stopped) {  // end every thread after its current job
        stopped = true;
        stats->interrupted = true;
        std::lock_guard<std::mutex> lock(queue_mutex);
        for (auto& v : queue) v = -1;
        for (int t = ends; t < options.threads; ++t) queue.push_back(-1);
        queue_cv.notify_all();
      }
      for (const Finished& f : workers.Collect(std::chrono::milliseconds(1))) {
        busy += f.busy_s;
        stats->longest_job_s = std::max(stats->longest_job_s, f.busy_s);
        ++stats->ran;
        if (stopped) continue;
        const std::string bytes = PackResult(f);
        MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kTagResult,
                 MPI_COMM_WORLD);
      }
      if ((ends == options.threads || stopped) && workers.AllExited()) break;
    }
  }
  stats->rank_busy_s = {busy};
}
#endif  // SSC_HAVE_MPI

}  // namespace

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
  const auto t0 = Clock::now();
  ScopedStopSignals signals;

#ifdef SSC_HAVE_MPI
  if (rank != 0) {
    RunWorkerRank(jobs, opt, &stats);
  }
#endif
  std::vector<std::string> all_results;  // rank 0, for results_on_all_ranks
  std::vector<std::size_t> delivered_order;
  if (rank == 0) {
    const std::vector<std::size_t> order = HandoutOrder(jobs);
    stats.skipped = jobs.count - order.size();
    std::vector<std::size_t> position(jobs.count, kNone);
    for (std::size_t p = 0; p < order.size(); ++p) position[order[p]] = p;

    std::mutex handout_mutex;
    std::size_t handed = 0;
    auto take = [&]() -> std::size_t {
      std::lock_guard<std::mutex> lock(handout_mutex);
      if (g_stop || handed >= order.size()) return kNone;
      return order[handed++];
    };
    stats.rank_busy_s.assign(static_cast<std::size_t>(stats.ranks), 0.0);
    std::map<std::size_t, Finished> buffer;  // finished, by handout position
    std::size_t next_delivery = 0;
    auto hand_in = [&](Finished f, int from_rank) {
      stats.rank_busy_s[static_cast<std::size_t>(from_rank)] += f.busy_s;
      stats.longest_job_s = std::max(stats.longest_job_s, f.busy_s);
      const std::size_t p = position[f.index];
      buffer.emplace(p, std::move(f));
    };
    auto deliver_one = [&](const Finished& f) {
      deliver(f.index, f.result);
      ++stats.ran;
      if (opt.results_on_all_ranks && stats.ranks > 1) {
        all_results.push_back(f.result);
        delivered_order.push_back(f.index);
      }
    };
#ifdef SSC_HAVE_MPI
    const int remote_slots = (stats.ranks - 1) * opt.threads;
    int ends_sent = 0, remote_running = 0;
    auto answer_request = [&](int to) {
      const std::size_t next = take();
      if (next == kNone)
        ++ends_sent;
      else
        ++remote_running;
      SendJob(to, next);
    };
#endif
    {
      LocalWorkers workers(jobs, opt.threads, take);
      while (true) {
        for (Finished& f : workers.Collect(std::chrono::milliseconds(stats.ranks > 1 ? 1 : 50))) {
          hand_in(std::move(f), 0);
        }
#ifdef SSC_HAVE_MPI
        if (stats.ranks > 1) {
          int flag = 1;
          while (flag) {
            MPI_Status st;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
            if (!flag) break;
            if (st.MPI_TAG == kTagRequest) {
              MPI_Recv(nullptr, 0, MPI_BYTE, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD,
                       MPI_STATUS_IGNORE);
              answer_request(st.MPI_SOURCE);
            } else if (st.MPI_TAG == kTagResult) {
              hand_in(UnpackResult(ReceiveBytes(st)), st.MPI_SOURCE);
              --remote_running;
              answer_request(st.MPI_SOURCE);
            } else {
              ReceiveBytes(st);  // not ours: drop
            }
          }
        }
#endif
        if (g_stop) {
          // Keep every finished result now: out of order, but whole.
          stats.interrupted = true;
          for (auto& [p, f] : buffer) deliver_one(f);
          buffer.clear();
        }
        while (!buffer.empty() && buffer.begin()->first == next_delivery) {
          deliver_one(buffer.begin()->second);
          buffer.erase(buffer.begin());
          ++next_delivery;
        }
        // Interrupted: jobs still running on dead or stopping ranks are not waited for.
        bool remote_done = true;
#ifdef SSC_HAVE_MPI
        remote_done = g_stop || (remote_running == 0 && ends_sent == remote_slots);
#endif
        if (workers.AllExited() && remote_done && buffer.empty()) break;
      }
    }
  }
  stats.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();

#ifdef SSC_HAVE_MPI
  if (stats.ranks > 1 && opt.results_on_all_ranks && !stats.interrupted) {
    // Rank 0 sends [count][index, length]... then the bytes.
    std::vector<std::uint64_t> head;
    std::string body;
    if (rank == 0) {
      head.push_back(all_results.size());
      for (std::size_t k = 0; k < all_results.size(); ++k) {
        head.push_back(delivered_order[k]);
        head.push_back(all_results[k].size());
        body += all_results[k];
      }
    }
    std::uint64_t sizes[2] = {head.size(), body.size()};
    MPI_Bcast(sizes, 2, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    head.resize(sizes[0]);
    body.resize(sizes[1]);
    MPI_Bcast(head.data(), static_cast<int>(sizes[0]), MPI_UINT64_T, 0, MPI_COMM_WORLD);
    if (sizes[1]) MPI_Bcast(&body[0], static_cast<int>(sizes[1]), MPI_CHAR, 0, MPI_COMM_WORLD);
    if (rank != 0) {
      std::size_t at = 0;
      for (std::uint64_t k = 0; k < head[0]; ++k) {
        const std::size_t index = head[1 + 2 * k], len = head[2 + 2 * k];
        deliver(index, body.substr(at, len));
        at += len;
      }
    }
  }
#endif
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

bool JobRunnerHasMpi() {
#ifdef SSC_HAVE_MPI
  return true;
#else
  return false;
#endif
}

void InitJobRunnerMpi(int* argc, char*** argv) {
#ifdef SSC_HAVE_MPI
  // Open MPI's launcher sets these; a plain start stays a single process without MPI.
  const bool launched =
      std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
  if (!launched) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  g_mpi_active = true;
#else
  (void)argc;
  (void)argv;
#endif
}

void FinalizeJobRunnerMpi(bool abort) {
#ifdef SSC_HAVE_MPI
  if (!g_mpi_active) return;
  g_mpi_active = false;
  if (abort) {
    MPI_Abort(MPI_COMM_WORLD, 1);
  } else {
    MPI_Finalize();
  }
#else
  (void)abort;
#endif
}

int JobRunnerRank() {
#ifdef SSC_HAVE_MPI
  if (g_mpi_active) {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
  }
#endif
  return 0;
}

int JobRunnerRankCount() {
#ifdef SSC_HAVE_MPI
  if (g_mpi_active) {
    int n = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
  }
#endif
  return 1;
}

}  // namespace ssc
