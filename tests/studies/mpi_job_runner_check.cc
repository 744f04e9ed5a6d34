// Run by tests/studies/mpi_sweep_test.sh under mpirun: the job runner across ranks with results on
// every rank (what a calibration objective evaluated in lock-step on all ranks needs). Exit 0 when
// every rank holds every job's result; 1 otherwise.
#include <cstdio>
#include <string>

#include "studies/jobs/job_runner.h"

int main(int argc, char** argv) {
  ssc::InitJobRunnerMpi(&argc, &argv);
  const int rank = ssc::JobRunnerRank();
  ssc::JobSet jobs;
  jobs.count = 37;
  jobs.cost = [](std::size_t i) { return static_cast<double>((i * 7) % 11); };
  jobs.run = [](std::size_t i) { return "r" + std::to_string(i * i); };
  ssc::JobRunnerOptions options;
  options.threads = 2;
  options.results_on_all_ranks = true;
  ssc::JobRunStats stats;
  const std::vector<std::string> results = ssc::RunJobsCollect(jobs, options, &stats);
  int bad = 0;
  for (std::size_t i = 0; i < jobs.count; ++i) bad += results[i] != "r" + std::to_string(i * i);
  if (rank == 0) {
    int ran = static_cast<int>(stats.ran);
    std::printf("ranks %d, results %d, balance %.3f\n", stats.ranks, ran,
                stats.BalanceMaxOverMean());
    if (ran != 37 || stats.ranks < 2) bad += 1;
  }
  if (bad) std::fprintf(stderr, "rank %d: %d results wrong or missing\n", rank, bad);
  ssc::FinalizeJobRunnerMpi(bad != 0);
  return bad ? 1 : 0;
}
