// The MATLAB file that merges the robot's topics, read and written with matio (Debian's
// libmatio; never a hand-written MAT parser). No real file was available: this is the layout
// the project defines (docs/robot_logs.md).
//
//   variable   size   columns (as the per-topic CSV, time first)
//   pressure   N x 6  t_ns, ch, P1, P2, P3, P4              raw absolute Pa      required
//   pose       N x 8  t_ns, qw, qx, qy, qz, x, y, z         tool0 in base, m     required
//                     (also read under the name tool_pose)
//   ft         N x 7  t_ns, fx, fy, fz, tx, ty, tz          N, N m               optional
//   pwm        N x 2  t_ns, pwm                             as logged            optional
//
// Each a real, non-sparse numeric matrix of any class (double as MATLAB writes by default;
// single and integer classes are converted). Time stamps are ROS time in integer nanoseconds;
// a double holds an epoch-sized stamp (~1.7e18) to 256 ns, so stamps closer than that merge
// and are refused as duplicates. Other variables are ignored. MAT v5 and v7.3 (HDF5) files
// both read. Errors give the matrix row and column as line and column.
#ifndef SSC_ROBOTLOG_MAT_LOG_H_
#define SSC_ROBOTLOG_MAT_LOG_H_

#include <string>

#include "robotlog/log_types.h"

namespace ssc {

// Reads and checks (ValidateRobotLog) a merged log.
bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* error);

enum class MatVersion { kMat5, kMat73 };
// Writes the non-empty streams as double matrices in the layout above.
bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error,
                      MatVersion version = MatVersion::kMat5);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_MAT_LOG_H_
