// The lab's merged MATLAB file (DataLog_<YYYY>_<MMDD>_<HHMMSS>_<appendTxt>.mat, written by
// SciPy's savemat from the per-topic CSVs read with pandas), read and written with matio
// (Debian's libmatio; never a hand-written MAT parser):
//
//   <name>_columnName  char matrix: the CSV header's names, one per row, space-padded
//   <name>_data        N x k numeric: the CSV's rows (double; pwm_data may be int64), the
//                      first column the ns stamp stored as a double (about 256 ns resolution)
//   script arguments   each its own variable: Pref, beta, d_lat (m), diskRadius (mm),
//                      start_offset (m), P_lims, alpha_beta, success, Fz_set,
//                      edgeFollowing_history (N x 11 cell array or numeric matrix)
//
// Streams are recognised by the topic and field names in *_columnName (topic_csv.h), not by
// the variable names; other variables are ignored. Errors give the matrix row and column as
// line and column and name the variable.
#ifndef SSC_ROBOTLOG_MAT_LOG_H_
#define SSC_ROBOTLOG_MAT_LOG_H_

#include <string>

#include "robotlog/log_types.h"

namespace ssc {

// Reads and checks (ValidateRobotLog) a merged log, with the script's arguments when present.
bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* error);

enum class MatVersion { kMat5, kMat73 };
// Writes the non-empty streams and log.args as the lab's saver does: column names as the
// logger of `version` writes them (pandas' names for repeated columns), values as pandas reads
// the CSV (pressures float32-widened; pwm_data int64 when the PWM file holds integers), integer
// arguments (Pref, diskRadius, P_lims, success) as int64, the history as an N x 11 cell array
// whose r_p, corr_p and r_p_final cells are 1 x 2.
bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error,
                      LoggerVersion version = LoggerVersion::kNewer,
                      MatVersion mat_version = MatVersion::kMat5);

// "DataLog_<stamp>_seb_testEdgeFollowing_refP_<Pref>_beta_<beta>_step_<d_lat>_deleteMe.mat",
// the disk benchmark script's name (Python's str() of each value).
std::string DiskBenchmarkMatName(const std::string& stamp, const LabRunArgs& args);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_MAT_LOG_H_
