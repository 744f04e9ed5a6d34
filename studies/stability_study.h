// ssc stability as a library function: the same disk trial with every integrator over a range
// of time steps, against a 0.5 ms RK4 reference; per integrator, the largest step at which the
// trial stays stable and its outcome, mean radius and path length stay within tolerance.
// Trials run on the job runner (studies/jobs/job_runner.h).
#ifndef SSC_STUDIES_STABILITY_STUDY_H_
#define SSC_STUDIES_STABILITY_STUDY_H_

#include <string>
#include <vector>

#include "runtime/trial.h"

namespace ssc {

struct StabilitySpec {
  TrialConfig config;      // the trial (e.g. dL 5 mm)
  std::string scene_name;  // recorded beside the trials file
  // Each trial as it finishes (StabilityTrialsHeader()): the same study run again resumes from
  // it as a sweep does (studies/sweep_io.h, ResumableTable); "": none kept.
  std::string trials_csv;
  std::vector<double> steps_ms = {0.5, 1, 2, 4, 8, 16};
  double dr_tol_mm = 0.3, s_tol = 0.05;  // mean radius (mm), path length (relative)
  int threads = 1;
};

struct StabilityRow {
  std::string integrator;
  double timestep_ms = 0;
  Outcome outcome = Outcome::kRunning;
  double r_mean_mm = 0, s_mm = 0, wall_s = 0;
  bool stable = false, unchanged = false;
};

struct StabilityResult {
  StabilityRow reference;          // RK4, 0.5 ms
  std::vector<StabilityRow> rows;  // integrator by integrator, steps in the given order
  // Per integrator with a step run: NaN when none of its steps kept the results unchanged.
  std::vector<std::pair<std::string, double>> largest_unchanged_ms;
  // SIGINT/SIGTERM (studies/jobs/job_runner.h): `rows` holds the finished trials, judged when the
  // reference finished (none otherwise); largest_unchanged_ms is empty (it needs every step).
  bool interrupted = false;
  int trials = 0;     // asked for, with the reference
  int skipped = 0;    // found in trials_csv from an earlier run, not run again
  std::string error;  // the trials file could not be resumed or written (nothing else is valid)
};

StabilityResult RunStabilityStudy(const mjModel* model, const StabilitySpec& spec);

// integrator,timestep_ms,outcome,r_mean_mm,s_mm,wall_s,stable,unchanged
std::string StabilityCsv(const StabilityResult& result);

// The trials file's header: trial (reference or step), integrator, timestep_ms, outcome,
// r_mean_mm, s_mm, wall_s, the numbers in full precision.
std::string StabilityTrialsHeader();

}  // namespace ssc

#endif  // SSC_STUDIES_STABILITY_STUDY_H_
