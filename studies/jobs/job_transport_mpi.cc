// The job runner's transport between MPI ranks (studies/jobs/job_transport.h): rank 0 hands out one
// job per request and receives every result; built when CMake finds MPI.
#include <mpi.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <mutex>

#include "studies/jobs/job_transport.h"

namespace ssc {
namespace job_runner_detail {
namespace {

bool g_mpi_active = false;

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

class MpiRemoteRanks : public RemoteRanks {
 public:
  MpiRemoteRanks(int ranks, int threads) : ranks_(ranks), remote_slots_((ranks - 1) * threads) {}

  void Poll(const std::function<std::size_t()>& take,
            const std::function<void(Finished, int)>& hand_in) override {
    if (ranks_ <= 1) return;
    int flag = 1;
    while (flag) {
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (!flag) break;
      if (st.MPI_TAG == kTagRequest) {
        MPI_Recv(nullptr, 0, MPI_BYTE, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        Answer(st.MPI_SOURCE, take);
      } else if (st.MPI_TAG == kTagResult) {
        hand_in(UnpackResult(ReceiveBytes(st)), st.MPI_SOURCE);
        --remote_running_;
        Answer(st.MPI_SOURCE, take);
      } else {
        ReceiveBytes(st);  // not ours: drop
      }
    }
  }

  bool Done() const override { return remote_running_ == 0 && ends_sent_ == remote_slots_; }

 private:
  void Answer(int to, const std::function<std::size_t()>& take) {
    const std::size_t next = take();
    if (next == kNone)
      ++ends_sent_;
    else
      ++remote_running_;
    SendJob(to, next);
  }

  int ranks_, remote_slots_;
  int ends_sent_ = 0, remote_running_ = 0;
};

}  // namespace

std::unique_ptr<RemoteRanks> MakeRemoteRanks(int ranks, int threads) {
  return std::make_unique<MpiRemoteRanks>(ranks, threads);
}

void RunWorkerRank(const JobSet& jobs, int threads, JobRunStats* stats) {
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
  for (int t = 0; t < threads; ++t) {
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagRequest, MPI_COMM_WORLD);
  }
  double busy = 0;
  {
    LocalWorkers workers(jobs, threads, take);
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
      if (StopRequested() && !stopped) {  // end every thread after its current job
        stopped = true;
        stats->interrupted = true;
        std::lock_guard<std::mutex> lock(queue_mutex);
        for (auto& v : queue) v = -1;
        for (int t = ends; t < threads; ++t) queue.push_back(-1);
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
      if ((ends == threads || stopped) && workers.AllExited()) break;
    }
  }
  stats->rank_busy_s = {busy};
}

void ShareResults(const std::vector<std::size_t>& indices, const std::vector<std::string>& results,
                  const DeliverFn& deliver) {
  const int rank = JobRunnerRank();
  // Rank 0 sends [count][index, length]... then the bytes.
  std::vector<std::uint64_t> head;
  std::string body;
  if (rank == 0) {
    head.push_back(results.size());
    for (std::size_t k = 0; k < results.size(); ++k) {
      head.push_back(indices[k]);
      head.push_back(results[k].size());
      body += results[k];
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

}  // namespace job_runner_detail

void InitJobRunnerMpi(int* argc, char*** argv) {
  // Open MPI's launcher sets these; a plain start stays a single process without MPI.
  const bool launched =
      std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
  if (!launched) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  job_runner_detail::g_mpi_active = true;
}

void FinalizeJobRunnerMpi(bool abort) {
  if (!job_runner_detail::g_mpi_active) return;
  job_runner_detail::g_mpi_active = false;
  if (abort) {
    MPI_Abort(MPI_COMM_WORLD, 1);
  } else {
    MPI_Finalize();
  }
}

int JobRunnerRank() {
  int r = 0;
  if (job_runner_detail::g_mpi_active) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int JobRunnerRankCount() {
  int n = 1;
  if (job_runner_detail::g_mpi_active) MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

}  // namespace ssc
