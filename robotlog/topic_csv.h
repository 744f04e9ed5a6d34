// The lab's per-topic CSV files, exactly as its ROS data logger writes them (both versions;
// docs/robot_logs.md and ../shared/reference/lab-logs.md):
//
//   dataLog_<YYYY>_<MMDD>_<HHMMSS>_<topic, every '/' -> '_'>.csv, one per topic, one stamp
//   header: ROStimestamp, then <topic>.<field path> per numeric field, fields alphabetical;
//           arrays as <topic>.<field>[i] (newer logger) or the name repeated (older logger)
//   rows:   integer ns, then the values; array elements separated by ", ", others by ","
//
//   topic             our stream  fields (our order)                                  units
//   /SensorPacket     pressure    ch, data[0..3] = P1..P4 (older logger: no ch)        ABSOLUTE Pa
//   /endEffectorPose  pose        pose.orientation.w/x/y/z, pose.position.x/y/z        tool0 in
//   base_link, m /netft_data       F/T         wrench.force.x/y/z, wrench.torque.x/y/z N, N m (raw)
//   /pwm              PWM         data                                                 % (Int8)
//
// A stream is recognised by the topic and field names in the file's header, never by the file
// name. Other topics (/sync) are skipped. /SensorPacket and /endEffectorPose are required.
#ifndef SSC_ROBOTLOG_TOPIC_CSV_H_
#define SSC_ROBOTLOG_TOPIC_CSV_H_

#include <string>
#include <string_view>
#include <vector>

#include "robotlog/log_types.h"

namespace ssc {

enum class StreamId { kPressure, kPose, kFt, kPwm };

// One of the lab's topics and the stream it fills.
struct LabTopic {
  StreamId id;
  std::string topic;     // ROS topic, e.g. "/SensorPacket"
  std::string mat_name;  // the MAT saver's prefix: <mat_name>_data, <mat_name>_columnName
  bool required;
  // Our stream's fields in order: the lab's field path (newer logger) and the short name used
  // in messages. An array's elements are "data[0]".."data[3]".
  std::vector<std::string> fields;
  std::vector<std::string> short_names;
  size_t size() const { return fields.size(); }
};

// All four, in the order pressure, pose, F/T, PWM (StreamId order).
const std::vector<LabTopic>& LabTopics();
const LabTopic& GetLabTopic(StreamId id);

// A topic file's header (or a .mat *_columnName): the topic, the logger version and, per
// column after ROStimestamp, the field of our stream it fills.
struct TopicHeader {
  const LabTopic* topic = nullptr;  // null: a topic the twin does not use (e.g. /sync)
  std::string topic_name;
  LoggerVersion version = LoggerVersion::kNewer;
  std::vector<int> field_of_column;  // one per column after the time stamp
  bool has_ch = true;                // /SensorPacket: the older logger has no `ch`
};

// `names` includes ROStimestamp first. `line` names the header's line (or 0). Also accepts the
// names pandas gives repeated columns ("<topic>.data.1") when a .mat was saved from an older
// logger's files.
bool ParseTopicHeader(const std::vector<std::string_view>& names, const std::string& file, int line,
                      TopicHeader* header, LoadError* error);

// One parsed topic file.
struct TopicTable {
  TopicHeader header;
  std::vector<long long> t_ns;
  std::vector<std::vector<double>> rows;  // header.topic->size() values each
  std::vector<int> lines;                 // file line of each row (1-based)
  int torn_last_line = 0;  // ReadTopicCsv: the line of a dropped last row without a line end
};

// Parses one topic file's text; `file` names it in errors. Time stamps must be non-negative
// integers (ns) and strictly increase; every value a finite number. A topic the twin does not
// use parses its header only (header.topic == nullptr, no rows).
bool ParseTopicCsv(std::string_view text, const std::string& file, TopicTable* table,
                   LoadError* error);
// The same from a file, read line by line (bounded memory: text::kMaxLineBytes per line). A last
// row without a line end (the logger stopped mid-row: its last number may be cut) is dropped
// and its line number kept in table->torn_last_line.
bool ReadTopicCsv(const std::string& path, TopicTable* table, LoadError* error);

// The files of one recording. `path`: a folder holding exactly one recording's
// dataLog_<stamp>_*.csv files, or any one of those files (its siblings with the same stamp are
// taken). A .csv file not named like that is taken alone. `stamp` gets "<YYYY>_<MMDD>_<HHMMSS>"
// (empty for a file not named by the logger).
bool FindRecordingFiles(const std::string& path, std::vector<std::string>* files,
                        std::string* stamp, LoadError* error);

// A recording (folder or one of its files) -> RobotLog (times relative to the earliest first
// stamp), checked with ValidateRobotLog (robot_log.h).
bool LoadTopicCsvRecording(const std::string& path, RobotLog* log, LoadError* error);

// "<YYYY>_<MMDD>_<HHMMSS>" of a ROS stamp (UTC), as the logger names its files.
std::string RecordingStamp(long long t_ns);
// "dataLog_<stamp>_<topic with '/' -> '_'>.csv"
std::string TopicFileName(const std::string& stamp, const std::string& topic);

// Writes each non-empty stream as the logger of `version` would: file names, header, ", "
// between array elements, pressures as float32 values widened to double, Python's float text.
// Stamps t0_ns + round(t_s * 1e9). `written` (optional) gets the paths.
bool WriteTopicCsvRecording(const std::string& dir, const RobotLog& log, LoggerVersion version,
                            std::vector<std::string>* written, std::string* error);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_TOPIC_CSV_H_
