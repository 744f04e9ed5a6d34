#include "robotlog/robot_log.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ssc {
namespace {

const std::vector<std::string> kPressureFields = {"ch", "P1", "P2", "P3", "P4"};
const std::vector<std::string> kPoseFields = {"orientation.w", "orientation.x", "orientation.y",
                                              "orientation.z", "position.x",    "position.y",
                                              "position.z"};
const std::vector<std::string> kFtFields = {"force.x",  "force.y",  "force.z",
                                            "torque.x", "torque.y", "torque.z"};
const std::vector<std::string> kPwmFields = {"pwm"};

void Fail(LoadError* e, const std::string& file, int line, int column, const std::string& msg) {
  e->file = file;
  e->line = line;
  e->column = column;
  e->message = msg;
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::stringstream ss(line);
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

std::string Trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

bool ParseDouble(const std::string& text, double* out) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtod(t.c_str(), &end);
  return end && *end == '\0' && errno != ERANGE;
}

bool ParseInt64(const std::string& text, long long* out) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtoll(t.c_str(), &end, 10);
  return end && *end == '\0' && errno != ERANGE;
}

bool ReadFile(const std::string& path, std::string* text, LoadError* e) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    Fail(e, path, 0, 0, "cannot open the file");
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  *text = ss.str();
  return true;
}

Stream ToStream(const std::vector<long long>& t_ns, std::vector<std::vector<double>> rows,
                long long t0) {
  Stream s;
  for (long long t : t_ns) s.t_s.push_back(static_cast<double>(t - t0) * 1e-9);
  s.rows = std::move(rows);
  return s;
}

// Linear interpolation of stream column `c` at time t (clamped at the ends).
double Interp(const Stream& s, size_t c, double t) {
  if (t <= s.t_s.front()) return s.rows.front()[c];
  if (t >= s.t_s.back()) return s.rows.back()[c];
  const size_t i = static_cast<size_t>(std::upper_bound(s.t_s.begin(), s.t_s.end(), t) - s.t_s.begin());
  const double u = (t - s.t_s[i - 1]) / (s.t_s[i] - s.t_s[i - 1]);
  return s.rows[i - 1][c] + u * (s.rows[i][c] - s.rows[i - 1][c]);
}

void QuatMul(const double a[4], const double b[4], double out[4]) {
  out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

void Rotate(const double q[4], const double v[3], double out[3]) {
  const double p[4] = {0, v[0], v[1], v[2]}, qc[4] = {q[0], -q[1], -q[2], -q[3]};
  double t[4], r[4];
  QuatMul(q, p, t);
  QuatMul(t, qc, r);
  out[0] = r[1];
  out[1] = r[2];
  out[2] = r[3];
}

}  // namespace

std::string LoadError::ToString() const {
  std::ostringstream os;
  os << file;
  if (line > 0) os << ":" << line;
  if (column > 0) os << ":" << column;
  os << ": " << message;
  return os.str();
}

bool ParseTopicCsv(const std::string& text, const std::string& name,
                   const std::vector<std::string>& expected, std::vector<long long>* t_ns,
                   std::vector<std::vector<double>>* rows, LoadError* e,
                   std::vector<int>* lines) {
  t_ns->clear();
  rows->clear();
  if (lines) lines->clear();
  const size_t n_cols = expected.size() + 1;
  std::stringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (Trim(line).empty()) continue;
    const std::vector<std::string> cells = SplitCsv(line);
    long long t = 0;
    double first_cell = 0;
    if (t_ns->empty() && rows->empty() && !ParseDouble(cells[0], &first_cell)) {
      // A header: it must name the documented fields in order.
      if (cells.size() != n_cols) {
        Fail(e, name, line_no, 0, "header has " + std::to_string(cells.size()) +
                                      " columns, expected " + std::to_string(n_cols) +
                                      " (time + " + std::to_string(expected.size()) + " fields)");
        return false;
      }
      for (size_t c = 1; c < n_cols; ++c) {
        const std::string h = Trim(cells[c]);
        if (h != expected[c - 1]) {
          Fail(e, name, line_no, static_cast<int>(c + 1),
               "header names '" + h + "', expected '" + expected[c - 1] + "'");
          return false;
        }
      }
      continue;
    }
    if (cells.size() != n_cols) {
      Fail(e, name, line_no, static_cast<int>(std::min(cells.size(), n_cols) + 1),
           "row has " + std::to_string(cells.size()) + " columns, expected " +
               std::to_string(n_cols) + (cells.size() < n_cols ? " (missing columns)" : ""));
      return false;
    }
    if (!ParseInt64(cells[0], &t)) {
      Fail(e, name, line_no, 1, "time stamp '" + Trim(cells[0]) + "' is not an integer (ns)");
      return false;
    }
    if (!t_ns->empty() && t <= t_ns->back()) {
      Fail(e, name, line_no, 1, std::string(t == t_ns->back() ? "duplicate" : "non-monotonic") +
                                    " time stamp " + std::to_string(t) + " (previous " +
                                    std::to_string(t_ns->back()) + ")");
      return false;
    }
    std::vector<double> values(expected.size());
    for (size_t c = 1; c < n_cols; ++c) {
      if (!ParseDouble(cells[c], &values[c - 1])) {
        Fail(e, name, line_no, static_cast<int>(c + 1),
             "'" + Trim(cells[c]) + "' is not a number (" + expected[c - 1] + ")");
        return false;
      }
      if (!std::isfinite(values[c - 1])) {
        Fail(e, name, line_no, static_cast<int>(c + 1), "non-finite value (" + expected[c - 1] + ")");
        return false;
      }
    }
    t_ns->push_back(t);
    rows->push_back(std::move(values));
    if (lines) lines->push_back(line_no);
  }
  if (t_ns->empty()) {
    Fail(e, name, 0, 0, "empty stream: no data rows");
    return false;
  }
  return true;
}

bool ReadTopicCsv(const std::string& path, const std::vector<std::string>& expected,
                  std::vector<long long>* t_ns, std::vector<std::vector<double>>* rows,
                  LoadError* e, std::vector<int>* lines) {
  std::string text;
  return ReadFile(path, &text, e) && ParseTopicCsv(text, path, expected, t_ns, rows, e, lines);
}

namespace {

bool CheckAbsolutePressure(const std::string& file, const Stream& s, LoadError* e) {
  for (size_t i = 0; i < s.rows.size(); ++i) {
    for (int c = 1; c <= 4; ++c) {
      const double p = s.rows[i][c];
      if (p < 30000 || p > 130000) {
        Fail(e, file, i < s.lines.size() ? s.lines[i] : static_cast<int>(i + 1), c + 2,
             "pressure " + std::to_string(p) + " Pa is not an absolute pressure (expected "
             "30-130 kPa; gauge vacuum belongs in the plain format)");
        return false;
      }
    }
  }
  return true;
}

}  // namespace

bool LoadRobotLogDir(const std::string& dir, RobotLog* log, LoadError* e) {
  namespace fs = std::filesystem;
  struct Topic {
    const char* file;
    const std::vector<std::string>* fields;
    Stream* stream;
    bool required;
  };
  std::vector<long long> t[4];
  std::vector<std::vector<double>> rows[4];
  std::vector<int> lines[4];
  const Topic topics[4] = {{"pressure.csv", &kPressureFields, &log->pressure_abs, true},
                           {"tool_pose.csv", &kPoseFields, &log->tool_pose, true},
                           {"ft.csv", &kFtFields, &log->ft, false},
                           {"pwm.csv", &kPwmFields, &log->pwm, false}};
  long long t0 = -1;
  for (int i = 0; i < 4; ++i) {
    const std::string path = (fs::path(dir) / topics[i].file).string();
    if (!fs::exists(path)) {
      if (topics[i].required) {
        Fail(e, path, 0, 0, "missing stream (required)");
        return false;
      }
      continue;
    }
    if (!ReadTopicCsv(path, *topics[i].fields, &t[i], &rows[i], e, &lines[i])) return false;
    t0 = t0 < 0 ? t[i].front() : std::min(t0, t[i].front());
  }
  log->t0_ns = t0;
  for (int i = 0; i < 4; ++i) {
    if (!t[i].empty()) {
      *topics[i].stream = ToStream(t[i], std::move(rows[i]), t0);
      topics[i].stream->lines = std::move(lines[i]);
    }
  }
  return CheckAbsolutePressure((fs::path(dir) / "pressure.csv").string(), log->pressure_abs, e);
}

bool WriteRobotLogDir(const std::string& dir, const RobotLog& log, std::string* error) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  auto write = [&](const char* file, const std::vector<std::string>& fields, const Stream& s) {
    if (s.empty()) return true;
    std::ofstream f(fs::path(dir) / file);
    f << "t_ns";
    for (const std::string& h : fields) f << ',' << h;
    f << '\n';
    char buf[64];
    for (size_t i = 0; i < s.t_s.size(); ++i) {
      f << log.t0_ns + std::llround(s.t_s[i] * 1e9);
      for (double v : s.rows[i]) {
        std::snprintf(buf, sizeof(buf), ",%.10g", v);
        f << buf;
      }
      f << '\n';
    }
    if (!f) *error = (fs::path(dir) / file).string() + ": write failed";
    return static_cast<bool>(f);
  };
  return write("pressure.csv", kPressureFields, log.pressure_abs) &&
         write("tool_pose.csv", kPoseFields, log.tool_pose) && write("ft.csv", kFtFields, log.ft) &&
         write("pwm.csv", kPwmFields, log.pwm);
}

bool ProcessRobotLog(const RobotLog& log, const ProcessOptions& o, ProcessedLog* out,
                     LoadError* e) {
  *out = ProcessedLog();
  const Stream& p = log.pressure_abs;
  if (p.empty() || log.tool_pose.empty()) {
    Fail(e, "log", 0, 0, p.empty() ? "empty pressure stream" : "empty tool pose stream");
    return false;
  }
  // In-air offset: mean absolute pressure per chamber over the first offset_window_s.
  std::array<double, 4> offset{};
  int n = 0;
  for (size_t i = 0; i < p.t_s.size() && p.t_s[i] <= p.t_s.front() + o.offset_window_s; ++i) {
    for (int c = 0; c < 4; ++c) offset[c] += p.rows[i][c + 1];
    ++n;
  }
  for (double& v : offset) v /= n;
  const int window = std::max(1, o.moving_average);
  std::vector<std::array<double, 4>> raw(p.t_s.size());
  for (size_t i = 0; i < p.t_s.size(); ++i)
    for (int c = 0; c < 4; ++c) raw[i][c] = offset[c] - p.rows[i][c + 1];
  for (size_t i = 0; i < p.t_s.size(); ++i) {
    std::array<double, 4> avg{};
    const size_t from = i + 1 >= static_cast<size_t>(window) ? i + 1 - window : 0;
    for (size_t k = from; k <= i; ++k)
      for (int c = 0; c < 4; ++c) avg[c] += raw[k][c] / static_cast<double>(i - from + 1);
    // Pose at this time: interpolated position; orientation from the nearest sample.
    double q[4], pos[3];
    for (int k = 0; k < 4; ++k) q[k] = Interp(log.tool_pose, k, p.t_s[i]);
    for (int k = 0; k < 3; ++k) pos[k] = Interp(log.tool_pose, 4 + k, p.t_s[i]);
    const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(qn > 0.5 && qn < 1.5)) {
      Fail(e, "tool_pose", 0, 0, "orientation is not a unit quaternion near t = " +
                                     std::to_string(p.t_s[i]) + " s");
      return false;
    }
    for (double& v : q) v /= qn;
    // TCP = tool0 + R * (0, 0, tcp_offset), then base -> scene.
    const double along[3] = {0, 0, o.tcp_offset_m};
    double d[3], tcp_base[3], tcp_scene[3], q_scene[4];
    Rotate(q, along, d);
    for (int k = 0; k < 3; ++k) tcp_base[k] = pos[k] + d[k];
    const double bq[4] = {o.base_quat[0], o.base_quat[1], o.base_quat[2], o.base_quat[3]};
    Rotate(bq, tcp_base, tcp_scene);
    QuatMul(bq, q, q_scene);
    out->t_s.push_back(p.t_s[i]);
    out->p_pa.push_back(avg);
    out->tcp_m.push_back({tcp_scene[0] + o.base_pos_m[0], tcp_scene[1] + o.base_pos_m[1],
                          tcp_scene[2] + o.base_pos_m[2]});
    out->quat.push_back({q_scene[0], q_scene[1], q_scene[2], q_scene[3]});
  }
  return true;
}

bool LoadPlainLog(const std::string& path, ProcessedLog* out, LoadError* e) {
  *out = ProcessedLog();
  std::string text;
  if (!ReadFile(path, &text, e)) return false;
  std::stringstream in(text);
  std::string line;
  int line_no = 0;
  const std::vector<std::string> want = {"t_s", "x_m",   "y_m",   "z_m",   "qw",   "qx",
                                         "qy",  "qz",    "p1_pa", "p2_pa", "p3_pa", "p4_pa"};
  while (std::getline(in, line)) {
    ++line_no;
    if (Trim(line).empty()) continue;
    const std::vector<std::string> cells = SplitCsv(line);
    if (line_no == 1) {
      for (size_t c = 0; c < want.size(); ++c) {
        if (c >= cells.size() || Trim(cells[c]) != want[c]) {
          Fail(e, path, 1, static_cast<int>(c + 1),
               "header must start with " + want[c] + " (the plain format: t_s,x_m,y_m,z_m,qw,qx,"
               "qy,qz,p1_pa..p4_pa)");
          return false;
        }
      }
      continue;
    }
    if (cells.size() < want.size()) {
      Fail(e, path, line_no, static_cast<int>(cells.size() + 1), "missing columns");
      return false;
    }
    double v[12];
    for (size_t c = 0; c < 12; ++c) {
      if (!ParseDouble(cells[c], &v[c]) || !std::isfinite(v[c])) {
        Fail(e, path, line_no, static_cast<int>(c + 1), "'" + Trim(cells[c]) + "' is not a finite number");
        return false;
      }
    }
    if (!out->t_s.empty() && v[0] <= out->t_s.back()) {
      Fail(e, path, line_no, 1, "non-monotonic or duplicate time");
      return false;
    }
    for (int c = 8; c < 12; ++c) {
      if (v[c] > 80000) {
        Fail(e, path, line_no, c + 1, "pressure " + std::to_string(v[c]) +
                                          " Pa looks absolute; the plain format takes gauge vacuum");
        return false;
      }
    }
    out->t_s.push_back(v[0]);
    out->tcp_m.push_back({v[1], v[2], v[3]});
    out->quat.push_back({v[4], v[5], v[6], v[7]});
    out->p_pa.push_back({v[8], v[9], v[10], v[11]});
  }
  if (out->t_s.empty()) {
    Fail(e, path, 0, 0, "empty log: no data rows");
    return false;
  }
  return true;
}

bool WritePlainLog(const std::string& path, const ProcessedLog& log, std::string* error) {
  std::ofstream f(path);
  f << "t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa\n";
  char buf[512];
  for (size_t i = 0; i < log.t_s.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%.6f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%.4f,%.4f,%.4f,%.4f\n",
                  log.t_s[i], log.tcp_m[i][0], log.tcp_m[i][1], log.tcp_m[i][2], log.quat[i][0],
                  log.quat[i][1], log.quat[i][2], log.quat[i][3], log.p_pa[i][0], log.p_pa[i][1],
                  log.p_pa[i][2], log.p_pa[i][3]);
    f << buf;
  }
  if (!f) *error = path + ": write failed";
  return static_cast<bool>(f);
}

}  // namespace ssc
