#include "robotlog/topic_csv.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>
#include <system_error>

#include "common/output_file.h"
#include "robotlog/robot_log.h"
#include "robotlog/text_cells.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTimeColumn = "ROStimestamp";
constexpr int kChambers = 4;

std::string HeaderExample(const LabTopic& t) {
  std::string s(kTimeColumn);
  for (const std::string& f : t.fields) s += "," + t.topic + "." + f;
  return s;
}

bool AllDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// "data[2]" for base "data" and 2, if the topic has that element.
int ElementIndex(const LabTopic& t, const std::string& base, int k) {
  const std::string name = base + "[" + std::to_string(k) + "]";
  const auto it = std::find(t.fields.begin(), t.fields.end(), name);
  return it == t.fields.end() ? -1 : static_cast<int>(it - t.fields.begin());
}

bool IsArrayBase(const LabTopic& t, const std::string& base) {
  return ElementIndex(t, base, 0) >= 0;
}

bool ParseRow(const std::vector<std::string_view>& cells, const std::string& file, int line_no,
              TopicTable* table, LoadError* e) {
  const TopicHeader& h = table->header;
  const LabTopic& topic = *h.topic;
  const size_t n_cols = h.field_of_column.size() + 1;
  if (cells.size() != n_cols) {
    const bool missing = cells.size() < n_cols;
    text::SetError(e, file, line_no, text::ToInt((missing ? cells.size() : n_cols) + 1),
                   std::string(missing ? "missing column" : "unexpected extra column") +
                       ": row has " + std::to_string(cells.size()) + " cells, the header " +
                       std::to_string(n_cols));
    return false;
  }
  long long t = 0;
  if (!text::ParseInt64(cells[0], &t)) {
    double seconds = 0;
    const bool number = text::ParseDouble(cells[0], &seconds) == text::NumberParse::kOk;
    text::SetError(e, file, line_no, 1,
                   "time stamp " + text::Quote(cells[0]) +
                       (number ? " is not an integer number of nanoseconds"
                               : " is not an integer (ROS time in ns)"));
    return false;
  }
  if (t < 0) {
    text::SetError(e, file, line_no, 1, "negative time stamp " + std::to_string(t) + " ns");
    return false;
  }
  if (!table->t_ns.empty() && t <= table->t_ns.back()) {
    text::SetError(e, file, line_no, 1,
                   std::string(t == table->t_ns.back() ? "duplicate" : "non-monotonic") +
                       " time stamp " + std::to_string(t) +
                       " ns (previous row: " + std::to_string(table->t_ns.back()) + " ns, line " +
                       std::to_string(table->lines.back()) + ")");
    return false;
  }
  std::vector<double> values(topic.size(), 0.0);
  if (topic.id == StreamId::kPressure && !h.has_ch) values[0] = kChambers;
  for (size_t c = 1; c < n_cols; ++c) {
    const int field = h.field_of_column[c - 1];
    const std::string& name = topic.short_names[static_cast<size_t>(field)];
    switch (text::ParseDouble(cells[c], &values[static_cast<size_t>(field)])) {
      case text::NumberParse::kOk:
        break;
      case text::NumberParse::kEmpty:
        text::SetError(e, file, line_no, text::ToInt(c + 1), "empty cell (" + name + ")");
        return false;
      case text::NumberParse::kNotANumber:
        text::SetError(e, file, line_no, text::ToInt(c + 1),
                       text::Quote(cells[c]) + " is not a number (" + name + ")");
        return false;
      case text::NumberParse::kNonFinite:
        text::SetError(e, file, line_no, text::ToInt(c + 1),
                       "non-finite value " + text::Quote(cells[c]) + " (" + name +
                           "): NaN, infinity or out of the double range");
        return false;
    }
  }
  table->t_ns.push_back(t);
  table->rows.push_back(std::move(values));
  table->lines.push_back(line_no);
  return true;
}

// Feeds lines to the header and row parsers; shared by the text and the file readers.
class TopicParser {
 public:
  TopicParser(const std::string& file, TopicTable* table, LoadError* e)
      : file_(file), table_(table), e_(e) {
    *table_ = TopicTable();
  }
  bool Line(int line_no, std::string_view line) {
    if (text::Trim(line).empty()) return true;
    const std::vector<std::string_view> cells = text::SplitCells(line);
    if (!have_header_) {
      have_header_ = true;
      return ParseTopicHeader(cells, file_, line_no, &table_->header, e_);
    }
    if (table_->header.topic == nullptr) return false;  // unused topic: the header is enough
    return ParseRow(cells, file_, line_no, table_, e_);
  }
  bool Finish(bool ok) const {
    if (!ok) return table_->header.topic == nullptr && have_header_ && e_->message.empty();
    if (!have_header_) {
      text::SetError(e_, file_, 0, 0, "empty file: no header line (ROStimestamp,...)");
      return false;
    }
    if (table_->header.topic != nullptr && table_->t_ns.empty()) {
      text::SetError(e_, file_, 0, 0, "empty stream: no data rows after the header");
      return false;
    }
    return true;
  }

 private:
  const std::string& file_;
  TopicTable* table_;
  LoadError* e_;
  bool have_header_ = false;
};

Stream ToStream(TopicTable&& table, long long t0_ns, const std::string& source) {
  Stream s;
  s.t_s.reserve(table.t_ns.size());
  for (long long t : table.t_ns) s.t_s.push_back(static_cast<double>(t - t0_ns) * 1e-9);
  s.rows = std::move(table.rows);
  s.lines = std::move(table.lines);
  s.source = source;
  return s;
}

// A logger file name: dataLog_<YYYY>_<MMDD>_<HHMMSS>_<topic>.csv -> the stamp, or "".
std::string StampOfFileName(const std::string& name) {
  constexpr std::string_view kPrefix = "dataLog_";
  if (name.size() < kPrefix.size() + 17 + 4 || name.compare(0, kPrefix.size(), kPrefix) != 0 ||
      name.substr(name.size() - 4) != ".csv") {
    return "";
  }
  const std::string stamp = name.substr(kPrefix.size(), 16);  // YYYY_MMDD_HHMMSS
  if (!AllDigits(std::string_view(stamp).substr(0, 4)) || stamp[4] != '_' ||
      !AllDigits(std::string_view(stamp).substr(5, 4)) || stamp[9] != '_' ||
      !AllDigits(std::string_view(stamp).substr(10, 6)) || name[kPrefix.size() + 16] != '_') {
    return "";
  }
  return stamp;
}

bool WriteTopicFile(const fs::path& path, const LabTopic& topic, LoggerVersion version,
                    const Stream& s, long long t0_ns, std::string* error) {
  OutputFile file(path.string());
  std::ostream& f = file.stream();
  const bool pressure = topic.id == StreamId::kPressure;
  const bool older = version == LoggerVersion::kOlder;
  f << kTimeColumn;
  for (const std::string& field : topic.fields) {
    if (pressure && older && field == "ch") continue;  // the older message had no ch
    std::string name = field;
    if (const size_t bracket = name.find('[');
        older && name.back() == ']' && bracket != std::string::npos) {
      name.resize(bracket);
    }
    f << ',' << topic.topic << '.' << name;
  }
  f << '\n';
  for (size_t i = 0; i < s.size(); ++i) {
    const std::vector<double>& r = s.rows[i];
    if (r.size() != topic.size()) {
      *error = path.string() + ": row " + std::to_string(i + 1) + " has " +
               std::to_string(r.size()) + " fields, the topic has " + std::to_string(topic.size());
      return false;
    }
    f << t0_ns + std::llround(s.t_s[i] * 1e9);
    switch (topic.id) {
      case StreamId::kPressure:
        // ch is an int; data is a float32 tuple printed without its brackets.
        if (!older) f << ',' << std::llround(r[0]);
        for (int c = 1; c <= kChambers; ++c) {
          f << (c == 1 ? "," : ", ") << text::PyFloat(static_cast<float>(r[c]));
        }
        break;
      case StreamId::kPwm:
        f << ',' << std::llround(r[0]);  // std_msgs/Int8
        break;
      case StreamId::kPose:
      case StreamId::kFt:
        for (double v : r) f << ',' << text::PyFloat(v);
        break;
    }
    f << '\n';
  }
  return file.Commit(error);
}

}  // namespace

const std::vector<LabTopic>& LabTopics() {
  // Never destroyed: other statics may still read it at exit.
  static const auto* const topics = new std::vector<LabTopic>{
      {StreamId::kPressure,
       "/SensorPacket",
       "SensorPacket",
       true,
       {"ch", "data[0]", "data[1]", "data[2]", "data[3]"},
       {"ch", "P1", "P2", "P3", "P4"}},
      {StreamId::kPose,
       "/endEffectorPose",
       "endEffectorPose",
       true,
       {"pose.orientation.w", "pose.orientation.x", "pose.orientation.y", "pose.orientation.z",
        "pose.position.x", "pose.position.y", "pose.position.z"},
       {"qw", "qx", "qy", "qz", "x", "y", "z"}},
      {StreamId::kFt,
       "/netft_data",
       "netftdata",
       false,
       {"wrench.force.x", "wrench.force.y", "wrench.force.z", "wrench.torque.x", "wrench.torque.y",
        "wrench.torque.z"},
       {"fx", "fy", "fz", "tx", "ty", "tz"}},
      {StreamId::kPwm, "/pwm", "pwm", false, {"data"}, {"pwm"}},
  };
  return *topics;
}

const LabTopic& GetLabTopic(StreamId id) { return LabTopics()[static_cast<size_t>(id)]; }

bool ParseTopicHeader(const std::vector<std::string_view>& names, const std::string& file, int line,
                      TopicHeader* h, LoadError* e) {
  *h = TopicHeader();
  const std::string_view first = text::Trim(names[0]);
  if (first != kTimeColumn) {
    double number = 0;
    const bool data = text::ParseDouble(first, &number) == text::NumberParse::kOk;
    text::SetError(e, file, line, 1,
                   data ? "no header line: the lab's logger starts each file with "
                          "ROStimestamp,<topic>.<field>,..."
                        : "first column " + text::Quote(first) +
                              " is not the logger's time column 'ROStimestamp'");
    return false;
  }
  if (names.size() < 2) {
    text::SetError(e, file, line, 2, "header has no field after ROStimestamp");
    return false;
  }
  // The topic: everything before the first '.' (ROS names hold no dots); all columns share it.
  for (size_t c = 1; c < names.size(); ++c) {
    const std::string_view cell = text::Trim(names[c]);
    const size_t dot = cell.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 1 == cell.size()) {
      text::SetError(e, file, line, text::ToInt(c + 1),
                     "header names " + text::Quote(cell) + ", expected <topic>.<field> (e.g. " +
                         "/SensorPacket.data[0])");
      return false;
    }
    std::string topic(cell.substr(0, dot));
    if (topic.front() != '/') topic = "/" + topic;
    if (c == 1) {
      h->topic_name = topic;
    } else if (topic != h->topic_name) {
      text::SetError(e, file, line, text::ToInt(c + 1),
                     "column of topic " + text::Quote(topic) + " in a file of topic " +
                         text::Quote(h->topic_name) + " (one topic per file)");
      return false;
    }
  }
  for (const LabTopic& t : LabTopics()) {
    if (t.topic == h->topic_name) h->topic = &t;
  }
  if (h->topic == nullptr) return true;  // a topic the twin does not use
  const LabTopic& t = *h->topic;
  std::map<std::string, int> repeats;  // older logger: occurrences of an array's bare name
  std::vector<int> column_of_field(t.size(), -1);
  bool indexed = false, repeated = false;
  for (size_t c = 1; c < names.size(); ++c) {
    const std::string_view cell = text::Trim(names[c]);
    const std::string field(cell.substr(cell.find('.') + 1));
    int index = -1;
    const auto it = std::find(t.fields.begin(), t.fields.end(), field);
    if (it != t.fields.end()) {
      index = static_cast<int>(it - t.fields.begin());
      indexed = indexed || field.back() == ']';
    } else if (IsArrayBase(t, field)) {
      index = ElementIndex(t, field, repeats[field]++);
      repeated = true;
      if (index < 0) {
        text::SetError(e, file, line, text::ToInt(c + 1),
                       "more '" + field + "' columns than the " + std::to_string(kChambers) +
                           " chambers the twin has");
        return false;
      }
    } else {
      // pandas renames repeated columns "data", "data.1", "data.2" (a .mat from older files).
      const size_t dot = field.rfind('.');
      if (dot != std::string::npos && AllDigits(std::string_view(field).substr(dot + 1)) &&
          IsArrayBase(t, field.substr(0, dot))) {
        index = ElementIndex(t, field.substr(0, dot), std::atoi(field.c_str() + dot + 1));
        repeated = true;
      }
      if (index < 0) {
        std::string expected;
        for (const std::string& f : t.fields) expected += (expected.empty() ? "" : ", ") + f;
        text::SetError(e, file, line, text::ToInt(c + 1),
                       "unknown field " + text::Quote(field) + " of " + t.topic +
                           " (fields: " + expected + ")");
        return false;
      }
    }
    if (column_of_field[static_cast<size_t>(index)] >= 0) {
      text::SetError(e, file, line, text::ToInt(c + 1),
                     "field '" + t.fields[static_cast<size_t>(index)] + "' appears twice (also " +
                         "column " +
                         std::to_string(column_of_field[static_cast<size_t>(index)] + 1) + ")");
      return false;
    }
    column_of_field[static_cast<size_t>(index)] = static_cast<int>(c);
    h->field_of_column.push_back(index);
  }
  if (indexed && repeated) {
    text::SetError(e, file, line, 0,
                   "header mixes indexed (data[i]) and repeated array names: neither logger "
                   "version writes that");
    return false;
  }
  h->version = repeated ? LoggerVersion::kOlder : LoggerVersion::kNewer;
  for (size_t f = 0; f < t.size(); ++f) {
    if (column_of_field[f] >= 0) continue;
    if (t.id == StreamId::kPressure && f == 0) {
      h->has_ch = false;  // the older message had no ch field
      continue;
    }
    text::SetError(
        e, file, line, text::ToInt(names.size() + 1),
        "header is missing field '" + t.fields[f] + "' (expected " + HeaderExample(t) + ")");
    return false;
  }
  return true;
}

bool ParseTopicCsv(std::string_view contents, const std::string& file, TopicTable* table,
                   LoadError* error) {
  try {
    *error = LoadError();
    TopicParser parser(file, table, error);
    bool ok = true;
    text::ForEachLine(contents, [&](int line_no, std::string_view line) {
      return ok = parser.Line(line_no, line);
    });
    return parser.Finish(ok);
  } catch (const std::exception& ex) {  // e.g. bad_alloc on a huge input
    text::SetError(error, file, 0, 0, std::string("cannot parse: ") + ex.what());
    return false;
  }
}

bool ReadTopicCsv(const std::string& path, TopicTable* table, LoadError* error) {
  try {
    *error = LoadError();
    TopicParser parser(path, table, error);
    bool ok = true;
    int torn = 0;
    if (!text::ForEachFileLine(
            path,
            [&](int line_no, std::string_view line) { return ok = parser.Line(line_no, line); },
            error, nullptr, &torn)) {
      return false;
    }
    if (!parser.Finish(ok)) return false;
    table->torn_last_line = torn;
    return true;
  } catch (const std::exception& ex) {
    text::SetError(error, path, 0, 0, std::string("cannot read: ") + ex.what());
    return false;
  }
}

bool FindRecordingFiles(const std::string& path, std::vector<std::string>* files,
                        std::string* stamp, LoadError* error) {
  files->clear();
  stamp->clear();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    text::SetError(error, path, 0, 0, "no such file or folder");
    return false;
  }
  const bool folder = fs::is_directory(path, ec);
  const fs::path dir = folder ? fs::path(path) : fs::path(path).parent_path();
  if (!folder) {
    *stamp = StampOfFileName(fs::path(path).filename().string());
    if (stamp->empty()) {  // not named by the logger: the file alone
      files->push_back(path);
      return true;
    }
  }
  std::map<std::string, std::vector<std::string>> by_stamp;
  for (const fs::directory_entry& entry :
       fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    const std::string s = StampOfFileName(entry.path().filename().string());
    if (!s.empty() && entry.is_regular_file(ec)) by_stamp[s].push_back(entry.path().string());
  }
  if (ec) {
    text::SetError(error, dir.string(), 0, 0, "cannot list the folder: " + ec.message());
    return false;
  }
  if (folder) {
    if (by_stamp.empty()) {
      text::SetError(error, path, 0, 0,
                     "no logger files in this folder (dataLog_<YYYY>_<MMDD>_<HHMMSS>_<topic>.csv)");
      return false;
    }
    if (by_stamp.size() > 1) {
      std::string list;
      for (const auto& [s, f] : by_stamp) list += (list.empty() ? "" : ", ") + s;
      text::SetError(error, path, 0, 0,
                     "the folder holds " + std::to_string(by_stamp.size()) +
                         " recordings (stamps " + list + "): give one of its files");
      return false;
    }
    *stamp = by_stamp.begin()->first;
  }
  *files = by_stamp[*stamp];
  std::sort(files->begin(), files->end());
  return true;
}

bool LoadTopicCsvRecording(const std::string& path, RobotLog* log, LoadError* error) {
  try {
    *log = RobotLog();
    std::vector<std::string> files;
    std::string stamp;
    if (!FindRecordingFiles(path, &files, &stamp, error)) return false;
    const std::vector<LabTopic>& topics = LabTopics();
    std::vector<TopicTable> tables(topics.size());
    std::vector<std::string> sources(topics.size());
    long long t0 = -1;
    for (const std::string& file : files) {
      TopicTable table;
      if (!ReadTopicCsv(file, &table, error)) return false;
      if (table.header.topic == nullptr) continue;  // e.g. /sync
      if (table.torn_last_line > 0) {
        log->warnings.push_back(file + ":" + std::to_string(table.torn_last_line) +
                                ": the last row has no line end (the logger stopped while "
                                "writing it; its last value may be cut): dropped");
      }
      const size_t i = static_cast<size_t>(table.header.topic->id);
      if (!sources[i].empty()) {
        text::SetError(error, file, 1, 0,
                       "a second file of topic " + topics[i].topic + " in one recording (also " +
                           sources[i] + ")");
        return false;
      }
      sources[i] = file;
      const long long first = table.t_ns.front();
      t0 = t0 < 0 ? first : std::min(t0, first);
      tables[i] = std::move(table);
    }
    for (size_t i = 0; i < topics.size(); ++i) {
      if (!topics[i].required || !sources[i].empty()) continue;
      const std::string expected =
          stamp.empty() ? topics[i].topic : TopicFileName(stamp, topics[i].topic);
      text::SetError(error, path, 0, 0,
                     "no file of topic " + topics[i].topic + " (a required stream; expected " +
                         expected + " beside the others, with its header naming " +
                         topics[i].topic + ")");
      return false;
    }
    log->t0_ns = t0;
    log->origin = path;
    Stream* streams[] = {&log->pressure_abs, &log->tool_pose, &log->ft, &log->pwm};
    for (size_t i = 0; i < topics.size(); ++i) {
      if (!sources[i].empty()) *streams[i] = ToStream(std::move(tables[i]), t0, sources[i]);
    }
    return CheckRosEpoch(*log, error) && ValidateRobotLog(*log, error);
  } catch (const std::exception& ex) {
    text::SetError(error, path, 0, 0, std::string("cannot load: ") + ex.what());
    return false;
  }
}

std::string RecordingStamp(long long t_ns) {
  const std::time_t secs = static_cast<std::time_t>(t_ns / 1000000000LL);
  std::tm tm{};
  gmtime_r(&secs, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y_%m%d_%H%M%S", &tm);
  return buf;
}

std::string TopicFileName(const std::string& stamp, const std::string& topic) {
  std::string t = topic;
  std::replace(t.begin(), t.end(), '/', '_');
  return "dataLog_" + stamp + "_" + t + ".csv";
}

bool WriteTopicCsvRecording(const std::string& dir, const RobotLog& log, LoggerVersion version,
                            std::vector<std::string>* written, std::string* error) {
  try {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
      *error = dir + ": cannot create the folder: " + ec.message();
      return false;
    }
    const std::string stamp = RecordingStamp(log.t0_ns);
    const Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
    for (const LabTopic& t : LabTopics()) {
      const Stream& s = *streams[static_cast<size_t>(t.id)];
      if (s.empty()) continue;
      const fs::path path = fs::path(dir) / TopicFileName(stamp, t.topic);
      if (!WriteTopicFile(path, t, version, s, log.t0_ns, error)) return false;
      if (written != nullptr) written->push_back(path.string());
    }
    return true;
  } catch (const std::exception& ex) {
    *error = dir + ": " + ex.what();
    return false;
  }
}

}  // namespace ssc
