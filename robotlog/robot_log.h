// Reading the real robot stack's logs as they are, and turning them into the twin's terms.
//
// Per-topic CSV (one file per ROS topic; first column the ROS time stamp in integer nanoseconds,
// then the message's numeric fields in alphabetical order; an optional header row names them):
//   pressure.csv  t_ns, ch, P1..P4      raw ABSOLUTE chamber pressures, Pa
//   tool_pose.csv t_ns, orientation.w/x/y/z, position.x/y/z   tool0 in the robot base frame, m
//   ft.csv        t_ns, force.x/y/z, torque.x/y/z               N, N m
//   pwm.csv       t_ns, pwm                                     pump duty, 0..100 % or 0..255
// The MATLAB file that merges them holds one matrix per stream with the same columns
// (`pressure`, `tool_pose`, `ft`, `pwm`; time in ns as double), read with matio.
// The plain format for anyone else's robot is one CSV (docs/robot_logs.md):
//   t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa[,fx_n,fy_n,fz_n]
//   (tool centre point in the scene frame; GAUGE vacuum, positive = vacuum).
//
// Every reader reports bad input with the file, line and column (1-based) and never throws.
#ifndef SSC_ROBOTLOG_ROBOT_LOG_H_
#define SSC_ROBOTLOG_ROBOT_LOG_H_

#include <array>
#include <string>
#include <vector>

namespace ssc {

struct LoadError {
  std::string file;
  int line = 0, column = 0;  // 0 = not about one cell
  std::string message;
  std::string ToString() const;
};

// One stream: times (s, from the log's first time stamp) and rows of values.
struct Stream {
  std::vector<double> t_s;
  std::vector<std::vector<double>> rows;
  std::vector<int> lines;  // file line of each row (1-based), when read from a CSV
  bool empty() const { return t_s.empty(); }
};

struct RobotLog {
  Stream pressure_abs;  // columns ch, P1..P4 (absolute Pa)
  Stream tool_pose;     // qw, qx, qy, qz, x, y, z (tool0 in the base frame)
  Stream ft;            // fx, fy, fz, tx, ty, tz
  Stream pwm;           // duty
  long long t0_ns = 0;  // time stamp of t = 0
};

// Reads one per-topic CSV with `n_fields` value columns after the time stamp. `expected`
// names them for the header check (a header is optional). Time stamps must strictly increase.
bool ReadTopicCsv(const std::string& path, const std::vector<std::string>& expected,
                  std::vector<long long>* t_ns, std::vector<std::vector<double>>* rows,
                  LoadError* error, std::vector<int>* lines = nullptr);
// Same, from text (for fuzzing and tests); `name` stands for the file in errors.
bool ParseTopicCsv(const std::string& text, const std::string& name,
                   const std::vector<std::string>& expected, std::vector<long long>* t_ns,
                   std::vector<std::vector<double>>* rows, LoadError* error,
                   std::vector<int>* lines = nullptr);

// The directory of per-topic CSVs (pressure.csv and tool_pose.csv required; ft.csv and pwm.csv
// optional). Checks units: pressures must be absolute (between 30 and 130 kPa).
bool LoadRobotLogDir(const std::string& dir, RobotLog* log, LoadError* error);
bool WriteRobotLogDir(const std::string& dir, const RobotLog& log, std::string* error);

// The merged MATLAB file (matio).
bool LoadRobotLogMat(const std::string& path, RobotLog* log, LoadError* error);
bool WriteRobotLogMat(const std::string& path, const RobotLog& log, std::string* error);

// The twin's view of a log: on the pressure clock, gauge vacuum per chamber (offset taken as
// the mean absolute pressure over [0, offset_window_s] as the robot host did, vacuum = offset -
// absolute), optionally the host's moving average, and the tool centre point (tool0 + 146 mm
// along its z) interpolated onto those times, mapped into the scene frame.
struct ProcessedLog {
  std::vector<double> t_s;
  std::vector<std::array<double, 4>> p_pa;   // gauge vacuum, positive = vacuum
  std::vector<std::array<double, 3>> tcp_m;  // scene frame
  std::vector<std::array<double, 4>> quat;   // tool0 orientation in the scene frame (w, x, y, z)
};

struct ProcessOptions {
  double offset_window_s = 1.0;    // in-air offset: mean over the first second
  int moving_average = 7;          // host filter (1 = none)
  double tcp_offset_m = 0.146;     // tool centre point along tool0 z
  // Robot base -> scene: rotation (w, x, y, z) and translation. The scenes put the UR base
  // frame at the world origin: identity.
  std::array<double, 4> base_quat{1, 0, 0, 0};
  std::array<double, 3> base_pos_m{0, 0, 0};
};

bool ProcessRobotLog(const RobotLog& log, const ProcessOptions& options, ProcessedLog* out,
                     LoadError* error);

// The plain CSV (already gauge and in the scene frame).
bool LoadPlainLog(const std::string& path, ProcessedLog* out, LoadError* error);
bool WritePlainLog(const std::string& path, const ProcessedLog& log, std::string* error);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_ROBOT_LOG_H_
