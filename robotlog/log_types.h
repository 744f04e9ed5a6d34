// The data every robot-log reader fills and every writer takes, and the error they report.
//
// Conventions: times in seconds relative to the log's first time stamp (`t0_ns`, the earliest
// first stamp of all streams); per-topic rows hold the message fields in the documented order
// (robotlog/topic_csv.h); pressures in a RobotLog are raw ABSOLUTE Pa, pressures in a
// ProcessedLog are GAUGE vacuum Pa, positive = vacuum.
#ifndef SSC_ROBOTLOG_LOG_TYPES_H_
#define SSC_ROBOTLOG_LOG_TYPES_H_

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ssc {

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// Where and why a log was refused. `line` and `column` are 1-based; 0 means the error is not
// about one cell (a missing file, an empty stream). For a .mat file they are the matrix row and
// column of the named variable.
struct LoadError {
  std::string file;
  int line = 0;
  int column = 0;
  std::string message;
  // "file:line:column: message" (line and column left out when 0).
  std::string ToString() const;
};

// One stream of a robot log: time stamps and rows of the message's fields (without the time).
struct Stream {
  std::vector<double> t_s;
  std::vector<std::vector<double>> rows;
  // Where each row came from, for errors found after parsing (unit checks): the file line
  // (1-based) of a CSV row or the matrix row of a .mat variable. May be empty (built in code).
  std::vector<int> lines;
  std::string source;    // file the stream was read from
  std::string variable;  // .mat variable name; empty for CSV
  bool empty() const { return t_s.empty(); }
  size_t size() const { return t_s.size(); }
};

// Which version of the lab's ROS logger wrote a per-topic file (docs/robot_logs.md).
enum class LoggerVersion {
  kNewer,  // array elements named <topic>.<field>[i]; /SensorPacket has a `ch` field
  kOlder,  // an array's name repeated once per element; /SensorPacket without `ch`
};

// One controller iteration of the disk benchmark script (`edgeFollowing_history`, .mat only):
// [time_s, x, y, r_p, corr_p, r_p_final, F_normal, P1, P2, P3, P4]. x, y: the measured TCP in
// the log's base frame, m; r_p, corr_p, r_p_final: 2-vectors in the tool frame as the script
// stores them ([y, x] components: the script moves dy = r[0] dL, dx = r[1] dL); F_normal: the
// tared F/T z force, N (negative = compression); P: the host's filtered pressures, absolute
// minus the in-air offset, Pa (negative = vacuum).
struct HistoryRow {
  double t_s = 0, x_m = 0, y_m = 0;
  std::array<double, 2> r_p{}, corr_p{}, r_p_final{};
  double f_normal_n = 0;
  std::array<double, 4> p_pa{};
};

// A history row spread out into numbers, as the N x 14 matrix form holds it (and Python's
// write_lab_mat rows): [t, x, y, r_p[0], r_p[1], corr_p[0], corr_p[1], r_p_final[0],
// r_p_final[1], F_normal, P1, P2, P3, P4].
inline constexpr std::size_t kHistoryRowNumbers = 14;
inline HistoryRow HistoryRowFromNumbers(const double* v) {
  HistoryRow h;
  h.t_s = v[0];
  h.x_m = v[1];
  h.y_m = v[2];
  h.r_p = {v[3], v[4]};
  h.corr_p = {v[5], v[6]};
  h.r_p_final = {v[7], v[8]};
  h.f_normal_n = v[9];
  h.p_pa = {v[10], v[11], v[12], v[13]};
  return h;
}

// The experiment script's arguments that the lab's MAT saver stores as variables (the disk
// benchmark's; NaN or empty when the file does not hold them). Units as the script has them.
struct LabRunArgs {
  double p_ref_pa = kNoValue;        // Pref
  double beta = kNoValue;            // beta
  double d_lat_m = kNoValue;         // d_lat: the step dL, METRES
  double disk_radius_mm = kNoValue;  // diskRadius, mm
  double start_offset_m = kNoValue;  // start_offset, m (from the engage point toward the edge)
  std::vector<double> p_lims_pa;     // P_lims [lower, upper]
  std::vector<double> alpha_beta;    // [alpha2, beta2, alpha1, beta1]
  std::vector<double> fz_set_n;      // Fz_set: the approach force band [low, high], N
  double success = kNoValue;         // 0 or 1
  std::vector<HistoryRow> history;   // edgeFollowing_history
  bool any() const;
};

// The merged robot log: what the robot stack recorded, in its own units and frames.
struct RobotLog {
  Stream pressure_abs;  // ch, P1..P4: raw absolute chamber pressures, Pa (chambers 1..4)
  Stream tool_pose;     // qw, qx, qy, qz, x, y, z: tool0 in the robot base frame, m
  Stream ft;            // fx, fy, fz (N), tx, ty, tz (N m) in the transducer frame; optional
  Stream pwm;           // pump drive as logged (fraction, percent or 0..255); optional
  long long t0_ns = 0;  // ROS time stamp of t = 0
  LabRunArgs args;      // the script's arguments (.mat); empty for CSV
  std::string origin;   // what was read: the folder, the files or the .mat
  std::vector<std::string> warnings;  // read, but worth a line (e.g. a torn last row dropped)
};

// The twin's view of a log, on one clock: gauge vacuum per chamber, the tool centre point and
// tool0's orientation in the scene frame, and the optional streams interpolated onto the clock.
struct ProcessedLog {
  std::vector<double> t_s;
  std::vector<std::array<double, 4>> p_pa;   // gauge vacuum, positive = vacuum
  std::vector<std::array<double, 3>> tcp_m;  // tool centre point, scene frame
  std::vector<std::array<double, 4>> quat;   // tool0 orientation in the scene frame (w, x, y, z)
  std::vector<std::array<double, 6>> ft;     // fx, fy, fz (N), tx, ty, tz (N m); empty if none
  std::vector<double> pwm_pct;               // pump drive, percent; empty if none
  std::array<double, 4> offset_pa{};         // the in-air absolute pressure subtracted, Pa
};

}  // namespace ssc

#endif  // SSC_ROBOTLOG_LOG_TYPES_H_
