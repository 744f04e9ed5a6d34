// Writing trials: the per-trial CSV log, the JSON summary, and the sweep CSV row.
#ifndef SSC_STUDIES_TRIAL_IO_H_
#define SSC_STUDIES_TRIAL_IO_H_

#include <string>

#include "runtime/trial.h"

namespace ssc {

// time, tool x/y/z, P1-P4, mean P, dPx, dPy, c_f, step vector, F/T normal force, phase.
bool WriteTrialLogCsv(const std::string& path, const TrialResult& result, std::string* error);

// Parameters, seed, outcome, metrics, model and MuJoCo version.
bool WriteTrialSummaryJson(const std::string& path, const std::string& scene,
                           const TrialConfig& config, const TrialResult& result,
                           std::string* error);

// The sweep table: header and one row per trial; columns name their units.
std::string SweepCsvHeader();
std::string SweepCsvRow(const std::string& scene, const TrialConfig& config, int repeat,
                        const TrialResult& result);

}  // namespace ssc

#endif  // SSC_STUDIES_TRIAL_IO_H_
