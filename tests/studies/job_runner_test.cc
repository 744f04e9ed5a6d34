// The study job runner on threads (MPI runs are tested by tests/studies/mpi_sweep_test.sh):
// longest- first handout, every job delivered exactly once in handout order, resume by skip,
// interruption.
#include "studies/jobs/job_runner.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace ssc {
namespace {

TEST(JobRunnerTest, HandoutIsLongestFirstWithTiesInIndexOrderAndSkipsDoneJobs) {
  JobSet jobs;
  jobs.count = 6;
  const std::vector<double> cost = {1, 5, 3, 5, 2, 9};
  jobs.cost = [&](std::size_t i) { return cost[i]; };
  jobs.skip = [](std::size_t i) { return i == 2; };
  EXPECT_EQ(HandoutOrder(jobs), (std::vector<std::size_t>{5, 1, 3, 4, 0}));
  jobs.cost = nullptr;
  EXPECT_EQ(HandoutOrder(jobs), (std::vector<std::size_t>{0, 1, 3, 4, 5}));
}

TEST(JobRunnerTest, ThreadsDeliverEveryResultOnceInHandoutOrderFromOneThread) {
  JobSet jobs;
  jobs.count = 40;
  // Jobs with larger cost finish sooner here, so completion order differs from handout order.
  jobs.cost = [](std::size_t i) { return static_cast<double>(i % 7); };
  jobs.run = [](std::size_t i) {
    std::this_thread::sleep_for(std::chrono::microseconds(200 * (7 - i % 7)));
    return "job" + std::to_string(i);
  };
  JobRunnerOptions options;
  options.threads = 3;
  std::vector<std::size_t> delivered;
  std::set<std::thread::id> delivering_threads;
  const JobRunStats stats = RunJobs(jobs, options, [&](std::size_t i, const std::string& r) {
    EXPECT_EQ(r, "job" + std::to_string(i));
    delivered.push_back(i);
    delivering_threads.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(delivered, HandoutOrder(jobs));
  EXPECT_EQ(delivering_threads.size(), 1u);
  EXPECT_EQ(stats.ran, 40u);
  EXPECT_EQ(stats.skipped, 0u);
  EXPECT_FALSE(stats.interrupted);
  ASSERT_EQ(stats.rank_busy_s.size(), 1u);
  EXPECT_GT(stats.rank_busy_s[0], 0.0);
  EXPECT_DOUBLE_EQ(stats.BalanceMaxOverMean(), 1.0);
}

TEST(JobRunnerTest, InterruptionStartsNoNewJobAndKeepsEveryFinishedResult) {
  JobSet jobs;
  jobs.count = 50;
  std::atomic<int> started{0};
  jobs.run = [&](std::size_t i) {
    ++started;
    if (i == 5) raise(SIGINT);  // as if the user pressed Ctrl-C during job 5
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    return std::to_string(i);
  };
  JobRunnerOptions options;
  options.threads = 2;
  std::set<std::size_t> delivered;
  const JobRunStats stats = RunJobs(jobs, options, [&](std::size_t i, const std::string&) {
    EXPECT_TRUE(delivered.insert(i).second) << "delivered twice: " << i;
  });
  EXPECT_TRUE(stats.interrupted);
  // Every job that started finished and was delivered; the rest never started.
  EXPECT_EQ(static_cast<int>(delivered.size()), started.load());
  EXPECT_LT(started.load(), 50);
  EXPECT_TRUE(delivered.count(5));
  // The handler is gone afterwards: the default action is back.
  struct sigaction now;
  sigaction(SIGINT, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST(JobRunnerTest, CollectReturnsResultsByJobIndex) {
  JobSet jobs;
  jobs.count = 9;
  jobs.cost = [](std::size_t i) { return static_cast<double>(i % 3); };
  jobs.skip = [](std::size_t i) { return i == 4; };
  jobs.run = [](std::size_t i) { return std::string(i + 1, 'x'); };
  JobRunnerOptions options;
  options.threads = 2;
  JobRunStats stats;
  const std::vector<std::string> r = RunJobsCollect(jobs, options, &stats);
  ASSERT_EQ(r.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(r[i], i == 4 ? "" : std::string(i + 1, 'x'));
  EXPECT_EQ(stats.ran, 8u);
  EXPECT_EQ(stats.skipped, 1u);
}

TEST(JobRunnerTest, NothingToRunWhenEveryJobIsSkipped) {
  JobSet jobs;
  jobs.count = 3;
  jobs.skip = [](std::size_t) { return true; };
  jobs.run = [](std::size_t) -> std::string {
    ADD_FAILURE() << "ran a skipped job";
    return "";
  };
  JobRunnerOptions options;
  options.threads = 2;
  int delivered = 0;
  const JobRunStats stats =
      RunJobs(jobs, options, [&](std::size_t, const std::string&) { ++delivered; });
  EXPECT_EQ(delivered, 0);
  EXPECT_EQ(stats.skipped, 3u);
  EXPECT_EQ(stats.ran, 0u);
}

}  // namespace
}  // namespace ssc
