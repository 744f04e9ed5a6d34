#include "robotlog/topic_csv.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>

#include "robotlog/robot_log.h"
#include "robotlog/text_cells.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTimeNames[] = {"t_ns",         "time",           "%time",
                                           "stamp",        "timestamp",      "header.stamp",
                                           "rosbagtimestamp", "time_ns",     "stamp_ns"};

// Header cell -> comparable name: lower case, quotes and export prefixes dropped.
std::string NormalizeName(std::string_view cell) {
  std::string_view t = text::Trim(cell);
  if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
  std::string name = text::Lower(t);
  for (bool again = true; again;) {
    again = false;
    for (const char* prefix : {"field.", "pose.", "wrench."}) {
      const std::string p(prefix);
      if (name.size() > p.size() && name.compare(0, p.size(), p) == 0) {
        name.erase(0, p.size());
        again = true;
      }
    }
  }
  return name;
}

std::string ColumnList(const StreamSpec& spec) {
  std::string s = "t_ns";
  for (const auto& c : spec.columns) s += "," + c.front();
  return s;
}

bool CheckHeader(const std::vector<std::string_view>& cells, const std::string& file, int line_no,
                 const StreamSpec& spec, LoadError* e) {
  const std::string time_name = NormalizeName(cells[0]);
  if (std::find(std::begin(kTimeNames), std::end(kTimeNames), time_name) ==
      std::end(kTimeNames)) {
    const bool seconds = time_name == "t_s" || time_name == "t" || time_name == "time_s";
    text::SetError(e, file, line_no, 1,
                   "first column " + text::Quote(cells[0]) +
                       (seconds ? " reads as seconds; per-topic logs take integer nanoseconds"
                                : " is not a time-stamp column") +
                       " (expected the header " + ColumnList(spec) + ")");
    return false;
  }
  for (size_t c = 1; c < cells.size() && c <= spec.fields(); ++c) {
    const std::vector<std::string>& names = spec.columns[c - 1];
    const std::string name = NormalizeName(cells[c]);
    bool ok = false;
    for (const std::string& n : names) ok = ok || text::Lower(n) == name;
    if (!ok) {
      text::SetError(e, file, line_no, text::ToInt(c + 1),
                     "header names " + text::Quote(cells[c]) + ", expected '" + names.front() +
                         "' (columns: " + ColumnList(spec) + ")");
      return false;
    }
  }
  if (cells.size() < spec.fields() + 1) {
    text::SetError(e, file, line_no, text::ToInt(cells.size() + 1),
                   "header is missing column '" + spec.columns[cells.size() - 1].front() +
                       "' (columns: " + ColumnList(spec) + ")");
    return false;
  }
  if (cells.size() > spec.fields() + 1) {
    text::SetError(e, file, line_no, text::ToInt(spec.fields() + 2),
                   "header has an unexpected extra column " +
                       text::Quote(cells[spec.fields() + 1]) + " (columns: " + ColumnList(spec) +
                       ")");
    return false;
  }
  return true;
}

bool ParseRow(const std::vector<std::string_view>& cells, const std::string& file, int line_no,
              const StreamSpec& spec, TopicTable* table, LoadError* e) {
  const size_t n_cols = spec.fields() + 1;
  if (cells.size() < n_cols) {
    text::SetError(e, file, line_no, text::ToInt(cells.size() + 1),
                   "missing column '" + spec.columns[cells.size() - 1].front() + "': row has " +
                       std::to_string(cells.size()) + " of " + std::to_string(n_cols) +
                       " columns");
    return false;
  }
  if (cells.size() > n_cols) {
    text::SetError(e, file, line_no, text::ToInt(n_cols + 1),
                   "unexpected extra column: row has " + std::to_string(cells.size()) +
                       " columns, expected " + std::to_string(n_cols));
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
                       " time stamp " + std::to_string(t) + " ns (previous row: " +
                       std::to_string(table->t_ns.back()) + " ns, line " +
                       std::to_string(table->lines.back()) + ")");
    return false;
  }
  std::vector<double> values(spec.fields());
  for (size_t c = 1; c < n_cols; ++c) {
    const std::string& name = spec.columns[c - 1].front();
    switch (text::ParseDouble(cells[c], &values[c - 1])) {
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

Stream ToStream(TopicTable&& table, long long t0_ns, const std::string& source) {
  Stream s;
  s.t_s.reserve(table.t_ns.size());
  for (long long t : table.t_ns) s.t_s.push_back(static_cast<double>(t - t0_ns) * 1e-9);
  s.rows = std::move(table.rows);
  s.lines = std::move(table.lines);
  s.source = source;
  return s;
}

bool WriteTopicFile(const fs::path& path, const StreamSpec& spec, const Stream& s,
                    long long t0_ns, bool header, std::string* error) {
  std::ofstream f(path);
  if (!f) {
    *error = path.string() + ": cannot create";
    return false;
  }
  if (header) f << ColumnList(spec) << '\n';
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.rows[i].size() != spec.fields()) {
      *error = path.string() + ": row " + std::to_string(i + 1) + " has " +
               std::to_string(s.rows[i].size()) + " fields, the topic has " +
               std::to_string(spec.fields());
      return false;
    }
    f << t0_ns + std::llround(s.t_s[i] * 1e9);
    for (double v : s.rows[i]) f << ',' << text::FormatDouble(v);
    f << '\n';
  }
  f.flush();
  if (!f) {
    *error = path.string() + ": write failed";
    return false;
  }
  return true;
}

}  // namespace

const std::vector<StreamSpec>& AllStreamSpecs() {
  // Never destroyed: other statics may still read it at exit.
  static const auto* const specs = new std::vector<StreamSpec>{
      {StreamId::kPressure,
       {"pressure.csv"},
       {"pressure"},
       true,
       {{"ch"}, {"P1", "p0"}, {"P2", "p1"}, {"P3", "p2"}, {"P4", "p3"}}},
      {StreamId::kPose,
       {"tool_pose.csv", "pose.csv"},
       {"pose", "tool_pose"},
       true,
       {{"orientation.w"},
        {"orientation.x"},
        {"orientation.y"},
        {"orientation.z"},
        {"position.x"},
        {"position.y"},
        {"position.z"}}},
      {StreamId::kFt,
       {"ft.csv", "wrench.csv"},
       {"ft"},
       false,
       {{"force.x"}, {"force.y"}, {"force.z"}, {"torque.x"}, {"torque.y"}, {"torque.z"}}},
      {StreamId::kPwm, {"pwm.csv"}, {"pwm"}, false, {{"pwm", "data"}}},
  };
  return *specs;
}

const StreamSpec& GetStreamSpec(StreamId id) {
  return AllStreamSpecs()[static_cast<size_t>(id)];
}

bool ParseTopicCsv(std::string_view text, const std::string& file, const StreamSpec& spec,
                   TopicTable* table, LoadError* error) {
  try {
    *table = TopicTable();
    bool ok = true;
    bool first = true;
    text::ForEachLine(text, [&](int line_no, std::string_view line) {
      if (text::Trim(line).empty()) return true;
      const std::vector<std::string_view> cells = text::SplitCells(line);
      // A header starts with a name; a data row with a number (maybe a bad one, reported as
      // such by ParseRow).
      double number = 0;
      if (first && !text::Trim(cells[0]).empty() &&
          text::ParseDouble(cells[0], &number) == text::NumberParse::kNotANumber) {
        first = false;
        table->had_header = true;
        ok = CheckHeader(cells, file, line_no, spec, error);
        return ok;
      }
      first = false;
      ok = ParseRow(cells, file, line_no, spec, table, error);
      return ok;
    });
    if (!ok) return false;
    if (table->t_ns.empty()) {
      text::SetError(error, file, 0, 0,
                     std::string("empty stream: no data rows") +
                         (table->had_header ? " after the header" : ""));
      return false;
    }
    return true;
  } catch (const std::exception& ex) {  // e.g. bad_alloc on a huge input
    text::SetError(error, file, 0, 0, std::string("cannot parse: ") + ex.what());
    return false;
  }
}

bool ReadTopicCsv(const std::string& path, const StreamSpec& spec, TopicTable* table,
                  LoadError* error) {
  std::string contents;
  return text::ReadWholeFile(path, &contents, error) &&
         ParseTopicCsv(contents, path, spec, table, error);
}

bool LoadRobotLogDir(const std::string& dir, RobotLog* log, LoadError* error) {
  try {
    *log = RobotLog();
    std::error_code ec;
    if (!fs::exists(dir, ec)) {
      text::SetError(error, dir, 0, 0, "no such directory");
      return false;
    }
    if (!fs::is_directory(dir, ec)) {
      text::SetError(error, dir, 0, 0, "not a directory (a per-topic log is a directory of CSVs)");
      return false;
    }
    const std::vector<StreamSpec>& specs = AllStreamSpecs();
    std::vector<TopicTable> tables(specs.size());
    std::vector<std::string> paths(specs.size());
    long long t0 = -1;
    for (size_t i = 0; i < specs.size(); ++i) {
      for (const std::string& name : specs[i].files) {
        const std::string path = (fs::path(dir) / name).string();
        if (!fs::exists(path, ec)) continue;
        if (!paths[i].empty()) {
          text::SetError(error, path, 0, 0, "two files for one topic: also " + paths[i]);
          return false;
        }
        paths[i] = path;
      }
      if (paths[i].empty()) {
        if (specs[i].required) {
          text::SetError(error, (fs::path(dir) / specs[i].files.front()).string(), 0, 0,
                         "no such file (a required stream)");
          return false;
        }
        continue;
      }
      if (!ReadTopicCsv(paths[i], specs[i], &tables[i], error)) return false;
      const long long first = tables[i].t_ns.front();
      t0 = t0 < 0 ? first : std::min(t0, first);
    }
    log->t0_ns = t0;
    Stream* streams[] = {&log->pressure_abs, &log->tool_pose, &log->ft, &log->pwm};
    for (size_t i = 0; i < specs.size(); ++i) {
      if (!paths[i].empty()) *streams[i] = ToStream(std::move(tables[i]), t0, paths[i]);
    }
    return ValidateRobotLog(*log, error);
  } catch (const std::exception& ex) {
    text::SetError(error, dir, 0, 0, std::string("cannot load: ") + ex.what());
    return false;
  }
}

bool WriteTopicCsvLogs(const std::string& dir, const RobotLog& log,
                       const TopicCsvWriteOptions& options, std::string* error) {
  try {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
      *error = dir + ": cannot create the directory: " + ec.message();
      return false;
    }
    const Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
    const std::vector<StreamSpec>& specs = AllStreamSpecs();
    for (size_t i = 0; i < specs.size(); ++i) {
      if (streams[i]->empty()) continue;
      if (!WriteTopicFile(fs::path(dir) / specs[i].files.front(), specs[i], *streams[i],
                          log.t0_ns, options.header, error)) {
        return false;
      }
    }
    return true;
  } catch (const std::exception& ex) {
    *error = dir + ": " + ex.what();
    return false;
  }
}

bool WriteRobotLogDir(const std::string& dir, const RobotLog& log, std::string* error) {
  return WriteTopicCsvLogs(dir, log, TopicCsvWriteOptions(), error);
}

}  // namespace ssc
