// Per-topic CSV files as the robot stack writes them: one file per ROS topic, first column the
// ROS time stamp in integer nanoseconds, then the message's numeric fields in alphabetical order.
//
//   file (in one directory)   columns after the time stamp                      units
//   pressure.csv (required)   ch, P1, P2, P3, P4                                raw ABSOLUTE Pa
//   tool_pose.csv (required)  orientation.w/x/y/z, position.x/y/z               tool0 in base, m
//   ft.csv (optional)         force.x/y/z, torque.x/y/z                         N, N m
//   pwm.csv (optional)        pwm                                               see align.h
//
// A header row is optional. When the first non-blank line does not start with an integer it is
// a header and must name the columns in this order; names compare case-insensitively after
// dropping the prefixes `field.`, `pose.` and `wrench.` (rostopic/rosbag exports), the time
// column may be called t_ns, time, %time, stamp, timestamp, header.stamp or rosbagTimestamp,
// pressure columns may also use the authors' 0-based numbering (P0..P3) and the PWM column
// `data` (std_msgs). Blank lines are skipped; '\r\n' endings and a UTF-8 BOM are accepted.
#ifndef SSC_ROBOTLOG_TOPIC_CSV_H_
#define SSC_ROBOTLOG_TOPIC_CSV_H_

#include <string>
#include <string_view>
#include <vector>

#include "robotlog/log_types.h"

namespace ssc {

enum class StreamId { kPressure, kPose, kFt, kPwm };

// One topic: its file names, .mat variable names and columns (after the time stamp).
struct StreamSpec {
  StreamId id;
  std::vector<std::string> files;      // first = the name written; others accepted on read
  std::vector<std::string> variables;  // .mat: first = the name written; others accepted
  bool required;
  // Per column: the canonical name (written) first, then accepted aliases (lower case).
  std::vector<std::vector<std::string>> columns;
  size_t fields() const { return columns.size(); }
};

const StreamSpec& GetStreamSpec(StreamId id);
// All four, in the order pressure, pose, F/T, PWM.
const std::vector<StreamSpec>& AllStreamSpecs();

// One parsed topic file.
struct TopicTable {
  std::vector<long long> t_ns;
  std::vector<std::vector<double>> rows;  // spec.fields() values each
  std::vector<int> lines;                 // file line of each row (1-based)
  bool had_header = false;
};

// Parses the text of one topic file; `file` names it in errors. Time stamps must be
// non-negative integers and strictly increase; every value must be a finite number.
bool ParseTopicCsv(std::string_view text, const std::string& file, const StreamSpec& spec,
                   TopicTable* table, LoadError* error);
bool ReadTopicCsv(const std::string& path, const StreamSpec& spec, TopicTable* table,
                  LoadError* error);

// A directory of topic files -> RobotLog (times relative to the earliest first stamp), checked
// with ValidateRobotLog (robot_log.h): units, quaternions, time-stamp spacing.
bool LoadRobotLogDir(const std::string& dir, RobotLog* log, LoadError* error);

struct TopicCsvWriteOptions {
  bool header = true;  // false: data rows only, in the documented column order
};
// Writes each non-empty stream of `log` as its topic file in `dir` (created if needed), time
// stamps t0_ns + round(t_s * 1e9), values in shortest round-trip form.
bool WriteTopicCsvLogs(const std::string& dir, const RobotLog& log,
                       const TopicCsvWriteOptions& options, std::string* error);
// Same with a header row (the name existing callers use).
bool WriteRobotLogDir(const std::string& dir, const RobotLog& log, std::string* error);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_TOPIC_CSV_H_
