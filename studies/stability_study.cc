#include "studies/stability_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "studies/job_runner.h"

namespace ssc {
namespace {

struct Integrator {
  int id;
  const char* name;
};
constexpr Integrator kIntegrators[] = {{mjINT_EULER, "Euler"},
                                       {mjINT_RK4, "RK4"},
                                       {mjINT_IMPLICIT, "implicit"},
                                       {mjINT_IMPLICITFAST, "implicitfast"}};

}  // namespace

StabilityResult RunStabilityStudy(const mjModel* model, const StabilitySpec& spec) {
  // Job 0: the reference; then integrator by integrator, step by step.
  struct Job {
    Integrator integrator;
    double ms;
  };
  std::vector<Job> jobs = {{{mjINT_RK4, "RK4"}, 0.5}};
  for (const Integrator& in : kIntegrators) {
    for (double ms : spec.steps_ms) jobs.push_back({in, ms});
  }
  JobSet set;
  set.count = jobs.size();
  set.cost = [&](std::size_t i) { return 1 / jobs[i].ms; };  // smaller steps take longer
  set.run = [&](std::size_t i) {
    mjModel* m = mj_copyModel(nullptr, model);
    m->opt.integrator = jobs[i].integrator.id;
    m->opt.timestep = jobs[i].ms * 1e-3;
    std::string e;
    const TrialResult r = RunTrial(m, spec.config, false, &e);
    mj_deleteModel(m);
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%d %.17g %.17g %.17g", static_cast<int>(r.outcome),
                  r.metrics.r_mean_mm, r.metrics.s_mm, r.wall_time_s);
    return std::string(buf);
  };
  JobRunnerOptions options;
  options.threads = std::max(1, spec.threads);
  JobRunStats stats;
  const std::vector<std::string> out = RunJobsCollect(set, options, &stats);
  auto row = [&](std::size_t i) {
    StabilityRow r;
    r.integrator = jobs[i].integrator.name;
    r.timestep_ms = jobs[i].ms;
    int outcome = 0;
    std::istringstream(out[i]) >> outcome >> r.r_mean_mm >> r.s_mm >> r.wall_s;
    r.outcome = static_cast<Outcome>(outcome);
    r.stable = r.outcome != Outcome::kUnstable;
    return r;
  };
  StabilityResult result;
  result.trials = static_cast<int>(jobs.size());
  if (out.size() != jobs.size()) return result;  // not rank 0 under MPI
  result.interrupted = stats.interrupted;
  // An interrupted run leaves jobs without a result: rows only for finished ones, and only when
  // the reference they are judged against finished.
  if (out[0].empty()) return result;
  result.reference = row(0);
  const StabilityRow& ref = result.reference;
  for (const Integrator& in : kIntegrators) {
    double largest_ok = 0;
    for (std::size_t i = 1; i < jobs.size(); ++i) {
      if (jobs[i].integrator.id != in.id || out[i].empty()) continue;
      StabilityRow r = row(i);
      r.unchanged = r.stable && r.outcome == ref.outcome &&
                    std::fabs(r.r_mean_mm - ref.r_mean_mm) <= spec.dr_tol_mm &&
                    std::fabs(r.s_mm - ref.s_mm) <= spec.s_tol * ref.s_mm;
      if (r.unchanged) largest_ok = std::max(largest_ok, r.timestep_ms);
      result.rows.push_back(r);
    }
    if (!result.interrupted) result.largest_unchanged_ms.emplace_back(in.name, largest_ok);
  }
  return result;
}

std::string StabilityCsv(const StabilityResult& result) {
  std::ostringstream csv;
  csv << "integrator,timestep_ms,outcome,r_mean_mm,s_mm,wall_s,stable,unchanged\n";
  for (const StabilityRow& r : result.rows) {
    csv << r.integrator << ',' << r.timestep_ms << ',' << OutcomeName(r.outcome) << ','
        << r.r_mean_mm << ',' << r.s_mm << ',' << r.wall_s << ',' << r.stable << ',' << r.unchanged
        << '\n';
  }
  return csv.str();
}

}  // namespace ssc
