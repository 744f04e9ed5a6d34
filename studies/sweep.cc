#include "studies/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "common/counter_rng.h"
#include "common/strict_number.h"
#include "runtime/mujoco_model.h"
#include "studies/jobs/job_runner.h"
#include "studies/sweep_io.h"
#include "studies/trial_io.h"
#include "studies/trial_manifest.h"

namespace ssc {
namespace {

using Key = SweepGridKey;

Key MakeKey(double pref, double beta, double step, int repeat) {
  return MakeSweepGridKey(pref, beta, step, repeat);
}

// The options that define the rows: resuming with other ones would mix their rows silently.
SweepManifest MakeManifest(const mjModel* m, const SweepSpec& spec) {
  SweepManifest manifest = TrialManifest(m, spec.scene_name, spec.base);
  manifest["csv_columns"] = SweepCsvHeader();
  manifest["seed"] = std::to_string(spec.seed);
  return manifest;
}

}  // namespace

std::uint64_t TrialSeed(std::uint64_t base, double pref, double beta, double step, int repeat) {
  const Key k = MakeKey(pref, beta, step, repeat);
  std::uint64_t h = SplitMix64(base);
  // Each part of the key in turn, first to last.
  std::apply([&h](auto... part) { ((h = SplitMix64(h ^ static_cast<std::uint64_t>(part))), ...); },
             k);
  return h & ((std::uint64_t{1} << 53) - 1);
}

// Estimated simulated time of a trial, for the longest-first handout: a lap of the disk at
// about four step lengths per second (docs/trials.md) plus the approach and move.
double EstimatedTrialCost(const TrialConfig& c) {
  const double lap_mm = 2 * 3.14159265358979 * c.target.disk_radius_m * 1e3;
  return 5.0 + lap_mm / (4.0 * std::max(c.law.step_mm, 0.1));
}

namespace {

std::vector<std::array<double, 3>> GridPoints(const SweepSpec& spec) {
  std::vector<std::array<double, 3>> points = spec.points;
  if (points.empty()) {
    for (double pref : spec.pref_pa)
      for (double beta : spec.beta)
        for (double step : spec.step_mm) points.push_back({pref, beta, step});
  }
  return points;
}

TrialConfig PointConfig(const SweepSpec& spec, const std::array<double, 3>& point, int repeat) {
  TrialConfig c = spec.base;
  c.law.p_ref_pa = point[0];
  c.law.beta = point[1];
  c.law.step_mm = point[2];
  c.seed = TrialSeed(spec.seed, point[0], point[1], point[2], repeat);
  return c;
}

// Checks each resumed row against its key and the options; rewrites the CSV without the bad
// ones (named on stderr), so their trials run again.
bool DropBadRows(const SweepSpec& spec, SweepCsvContents* existing, std::string* error) {
  SweepRowExpectations expect;
  expect.scene = spec.scene_name;
  expect.seed_of = [&spec](const SweepRowKey& r) {
    return TrialSeed(spec.seed, r.pref_pa, r.beta, r.step_mm, r.repeat);
  };
  for (Outcome o : {Outcome::kSuccess, Outcome::kFailureOffEdge, Outcome::kFailureGrasp,
                    Outcome::kTimeout, Outcome::kUnstable, Outcome::kLostEdge}) {
    expect.outcomes.emplace_back(OutcomeName(o));
  }
  expect.success = OutcomeName(Outcome::kSuccess);
  const std::vector<SweepRowProblem> problems = DropImpossibleSweepRows(expect, existing);
  if (problems.empty()) return true;
  constexpr size_t kShown = 10;
  for (size_t i = 0; i < problems.size() && i < kShown; ++i) {
    const SweepRowProblem& p = problems[i];
    std::fprintf(
        stderr, "sweep: %s line %d (P_ref %s Pa, beta %s, step %s mm, repeat %d): %s; %s\n",
        spec.out_csv.c_str(), p.line, FormatNumber(p.row.pref_pa).c_str(),
        FormatNumber(p.row.beta).c_str(), FormatNumber(p.row.step_mm).c_str(), p.row.repeat,
        p.why.c_str(), p.kept_line > 0 ? "dropped" : "dropped, the trial runs again");
  }
  if (problems.size() > kShown) {
    std::fprintf(stderr, "sweep: %zu more rows of %s like these dropped\n",
                 problems.size() - kShown, spec.out_csv.c_str());
  }
  return RewriteSweepCsv(spec.out_csv, SweepCsvHeader(), existing->lines, error);
}

}  // namespace

std::string CheckSweepGrid(const SweepSpec& spec) {
  const std::vector<std::array<double, 3>> points = GridPoints(spec);
  if (points.empty() || spec.repeats < 1) {
    return "sweep grid is empty (need at least one P_ref, beta, step and repeat)";
  }
  if (spec.threads < 1 || spec.threads > 256) {
    return "threads = " + std::to_string(spec.threads) + " is out of range [1, 256]";
  }
  std::set<Key> seen;
  for (const auto& point : points) {
    for (double v : point) {
      if (!std::isfinite(v)) {
        return "sweep point P_ref " + FormatNumber(point[0]) + " Pa, beta " +
               FormatNumber(point[1]) + ", step " + FormatNumber(point[2]) +
               " mm: not a finite number";
      }
    }
    // A value listed twice would run its trials twice, as two rows for one key.
    if (!seen.insert(MakeKey(point[0], point[1], point[2], 0)).second) {
      return "sweep point P_ref " + FormatNumber(point[0]) + " Pa, beta " + FormatNumber(point[1]) +
             ", step " + FormatNumber(point[2]) + " mm is listed twice (each grid value once)";
    }
    if (const std::string e = PointConfig(spec, point, 0).Validate(); !e.empty()) {
      return "sweep point P_ref " + FormatNumber(point[0]) + " Pa, beta " + FormatNumber(point[1]) +
             ", step " + FormatNumber(point[2]) + " mm: " + e;
    }
  }
  return "";
}

bool RunSweep(const mjModel* m, const SweepSpec& spec,
              const std::function<void(const SweepProgress&)>& progress, SweepSummary* summary,
              std::string* error) {
  if (std::string e = CheckSweepGrid(spec); !e.empty()) {
    *error = e;
    return false;
  }
  if (spec.out_csv.empty()) {
    *error = "no output CSV given (out_csv is empty)";
    return false;
  }
  struct Job {
    TrialConfig config;
    int repeat;
  };
  // The whole grid, the same on every rank; only rank 0 reads the CSV to skip finished rows.
  std::vector<Job> jobs;
  for (const auto& point : GridPoints(spec)) {
    for (int rep = 0; rep < spec.repeats; ++rep)
      jobs.push_back({PointConfig(spec, point, rep), rep});
  }
  // A scene that cannot host a trial fails here, before any row, not as rows of "unstable".
  if (std::string setup_error; !CheckTrialSetup(m, jobs.front().config, &setup_error)) {
    *error = "scene '" + spec.scene_name + "' cannot run a trial: " + setup_error;
    return false;
  }
  const bool writer = JobRunnerRank() == 0;
  std::set<Key> done;
  SweepRowWriter out;
  SweepOutputLock lock;
  if (writer) {
    SweepCsvContents existing;
    if (!lock.Acquire(spec.out_csv, error) ||
        !LoadSweepCsvForResume(spec.out_csv, SweepCsvHeader(), &existing, error) ||
        !CheckOrWriteSweepManifest(spec.out_csv, !existing.rows.empty(), MakeManifest(m, spec),
                                   error) ||
        !DropBadRows(spec, &existing, error) || !out.Open(spec.out_csv, error)) {
      return false;
    }
    if (existing.dropped > 0) {
      std::fprintf(stderr,
                   "sweep: dropped %d torn or malformed line(s) from %s; those trials "
                   "run again\n",
                   existing.dropped, spec.out_csv.c_str());
    }
    for (const SweepRowKey& k : existing.rows) {
      done.insert(MakeKey(k.pref_pa, k.beta, k.step_mm, k.repeat));
    }
    if (!existing.has_header && !out.Append(SweepCsvHeader(), error)) return false;
  }

  JobSet set;
  set.count = jobs.size();
  set.cost = [&](std::size_t i) { return EstimatedTrialCost(jobs[i].config); };
  set.skip = [&](std::size_t i) {
    const ContourLawParams& k = jobs[i].config.law;
    return done.count(MakeKey(k.p_ref_pa, k.beta, k.step_mm, jobs[i].repeat)) > 0;
  };
  ApproachCache approaches(m);
  ApproachCache* cache = spec.share_approach ? &approaches : nullptr;
  set.run = [&](std::size_t i) {
    const TrialResult r = RunGuardedTrial(m, jobs[i].config, cache);
    return r.interrupted ? std::string()
                         : SweepCsvRow(spec.scene_name, jobs[i].config, jobs[i].repeat, r);
  };
  ScopedTrialErrorGuard guard;
  int skipped = 0, finished = 0;
  if (writer) {
    for (std::size_t i = 0; i < jobs.size(); ++i) skipped += set.skip(i) ? 1 : 0;
  }
  const auto t0 = std::chrono::steady_clock::now();
  JobRunnerOptions options;
  options.threads = spec.threads;
  std::string write_error;
  const JobRunStats stats = RunJobs(set, options, [&](std::size_t, const std::string& row) {
    if (row.empty() || !out.Append(row, &write_error)) return;  // empty: interrupted, no row
    ++finished;
    if (progress) {
      SweepProgress p;
      p.total = static_cast<int>(jobs.size());
      p.skipped = skipped;
      p.done = finished + skipped;
      p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      progress(p);
    }
  });
  summary->total = static_cast<int>(stats.total);
  summary->skipped = static_cast<int>(stats.skipped);
  summary->ran = static_cast<int>(stats.ran);
  summary->wall_s = stats.wall_s;
  summary->ranks = stats.ranks;
  summary->threads = stats.threads;
  summary->rank_busy_s = stats.rank_busy_s;
  summary->balance_max_over_mean = stats.BalanceMaxOverMean();
  summary->longest_trial_s = stats.longest_job_s;
  summary->interrupted = stats.interrupted;
  summary->approach = approaches.counts();
  if (cache != nullptr) summary->approach_unshareable = approaches.unshareable_reason();
  if (!write_error.empty()) {
    *error = write_error;
    return false;
  }
  return true;
}

}  // namespace ssc
