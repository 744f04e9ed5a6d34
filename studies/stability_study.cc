#include "studies/stability_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string_view>

#include "common/strict_number.h"
#include "runtime/guarded_trial.h"
#include "studies/jobs/job_runner.h"
#include "studies/sweep_io.h"
#include "studies/trial_manifest.h"

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

struct Job {
  Integrator integrator;
  double ms;
};

std::string Full(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

std::string JobKey(bool reference, const std::string& integrator, double ms) {
  return std::string(reference ? "reference " : "step ") + integrator + " " + Full(ms);
}

// A metric cell as the study writes it (%.17g): a number, or a non-finite value for a trial
// that has no such metric (a failed trial's r_mean is nan), which the strict reader refuses.
bool MetricCell(std::string_view text) {
  for (const char* non_finite : {"nan", "-nan", "inf", "-inf"}) {
    if (text == non_finite) return true;
  }
  double v = 0;
  std::string error;
  return ParseNumber(text, NumberRange(), &v, &error);
}

// A row of an earlier run: its key when it can be a finished trial of this study.
std::string CheckTrialRow(const std::vector<std::string_view>& f, std::string* why) {
  const std::string trial(f[0]), integrator(f[1]), outcome(f[3]);
  bool known = false;
  for (const Integrator& in : kIntegrators) known = known || integrator == in.name;
  bool finished = false;
  for (int o = static_cast<int>(Outcome::kSuccess);
       o <= static_cast<int>(Outcome::kControllerFault); ++o) {
    finished = finished || outcome == OutcomeName(static_cast<Outcome>(o));
  }
  double ms = 0;
  std::string number_error;
  if (trial != "reference" && trial != "step") {
    *why = "trial '" + trial + "' is neither reference nor step";
  } else if (!known) {
    *why = "integrator '" + integrator + "' is not one of the study's";
  } else if (!ParseNumber(f[2], NumberRange::Positive(), &ms, &number_error)) {
    *why = "timestep_ms '" + std::string(f[2]) + "' is not a positive number";
  } else if (!finished) {
    *why = "outcome '" + outcome + "' is not a finished trial's";
  } else if (!MetricCell(f[4]) || !MetricCell(f[5]) || !MetricCell(f[6])) {
    *why = "a metric cell is not a number";
  } else {
    return JobKey(trial == "reference", integrator, ms);
  }
  return "";
}

// The job's result ("outcome r_mean s wall", as run() gives it) from its trials-file row.
std::string ResultOfRow(const std::string& row) {
  std::vector<std::string> f;
  std::stringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
  int outcome = 0;
  for (int o = 0; o <= static_cast<int>(Outcome::kControllerFault); ++o) {
    if (f[3] == OutcomeName(static_cast<Outcome>(o))) outcome = o;
  }
  return std::to_string(outcome) + " " + f[4] + " " + f[5] + " " + f[6];
}

// The trials-file row of a job's result.
std::string RowOfResult(std::size_t i, const Job& job, const std::string& result) {
  int outcome = 0;
  std::string r, s, wall;
  std::istringstream(result) >> outcome >> r >> s >> wall;
  return std::string(i == 0 ? "reference" : "step") + "," + job.integrator.name + "," +
         Full(job.ms) + "," + OutcomeName(static_cast<Outcome>(outcome)) + "," + r + "," + s + "," +
         wall;
}

}  // namespace

std::string StabilityTrialsHeader() {
  return "trial,integrator,timestep_ms,outcome,r_mean_mm,s_mm,wall_s";
}

StabilityResult RunStabilityStudy(const mjModel* model, const StabilitySpec& spec) {
  // Job 0: the reference; then integrator by integrator, step by step.
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
    const TrialResult r = RunGuardedTrial(m, spec.config);
    mj_deleteModel(m);
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%d %.17g %.17g %.17g", static_cast<int>(r.outcome),
                  r.metrics.r_mean_mm, r.metrics.s_mm, r.wall_time_s);
    return std::string(buf);
  };
  StabilityResult result;
  result.trials = static_cast<int>(jobs.size());
  const bool writer = JobRunnerRank() == 0;
  std::vector<std::string> out(jobs.size());
  ResumableTable table;
  if (writer && !spec.trials_csv.empty()) {
    SweepManifest manifest = TrialManifest(model, spec.scene_name, spec.config);
    manifest["csv_columns"] = StabilityTrialsHeader();
    manifest["seed"] = std::to_string(spec.config.seed);
    manifest["pref_pa"] = FormatNumber(spec.config.law.p_ref_pa);
    manifest["beta"] = FormatNumber(spec.config.law.beta);
    manifest["step_mm"] = FormatNumber(spec.config.law.step_mm);
    if (!table.Open(spec.trials_csv, StabilityTrialsHeader(), manifest, CheckTrialRow,
                    "ssc stability", &result.error)) {
      return result;
    }
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      const std::string kept = table.Kept(JobKey(i == 0, jobs[i].integrator.name, jobs[i].ms));
      if (kept.empty()) continue;
      out[i] = ResultOfRow(kept);
      ++result.skipped;
    }
  }
  set.skip = [&](std::size_t i) { return !out[i].empty(); };
  JobRunnerOptions options;
  options.threads = std::max(1, spec.threads);
  ScopedTrialErrorGuard guard;  // a MuJoCo error ends its trial as unstable, not the study
  const JobRunStats stats = RunJobs(set, options, [&](std::size_t i, const std::string& r) {
    out[i] = r;
    if (!spec.trials_csv.empty() && result.error.empty()) {
      table.Append(RowOfResult(i, jobs[i], r), &result.error);
    }
  });
  if (!result.error.empty()) return result;
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
  if (!writer) return result;  // not rank 0 under MPI
  result.interrupted = stats.interrupted;
  // An interrupted run leaves jobs without a result: rows only for finished ones, and only when
  // the reference they are judged against finished.
  if (out[0].empty()) return result;
  result.reference = row(0);
  const StabilityRow& ref = result.reference;
  for (const Integrator& in : kIntegrators) {
    double largest_ok = std::numeric_limits<double>::quiet_NaN();  // none unchanged yet
    double smallest_ms = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < jobs.size(); ++i) {
      if (jobs[i].integrator.id != in.id || out[i].empty()) continue;
      StabilityRow r = row(i);
      r.unchanged = r.stable && r.outcome == ref.outcome &&
                    std::fabs(r.r_mean_mm - ref.r_mean_mm) <= spec.dr_tol_mm &&
                    std::fabs(r.s_mm - ref.s_mm) <= spec.s_tol * ref.s_mm;
      if (r.unchanged && !(largest_ok >= r.timestep_ms)) largest_ok = r.timestep_ms;
      smallest_ms = std::min(smallest_ms, r.timestep_ms);
      result.rows.push_back(r);
    }
    // An integrator none of whose steps ran has nothing to judge.
    if (!result.interrupted && std::isfinite(smallest_ms))
      result.largest_unchanged_ms.emplace_back(in.name, largest_ok);
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
