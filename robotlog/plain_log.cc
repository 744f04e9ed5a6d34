#include "robotlog/plain_log.h"

#include <array>
#include <cmath>
#include <exception>
#include <fstream>
#include <functional>
#include <vector>

#include "common/output_file.h"
#include "robotlog/robot_log.h"
#include "robotlog/text_cells.h"

namespace ssc {
namespace {

// Column indices into kColumns.
enum Column : int { kT = 0, kX = 1, kQw = 4, kP1 = 8, kFx = 12, kPwm = 18, kNumColumns = 19 };
const char* const kColumns[kNumColumns] = {
    "t_s",   "x_m",   "y_m",  "z_m",  "qw",   "qx",    "qy",    "qz",    "p1_pa",  "p2_pa",
    "p3_pa", "p4_pa", "fx_n", "fy_n", "fz_n", "tx_nm", "ty_nm", "tz_nm", "pwm_pct"};

std::string Num(double v) { return text::FormatDouble(v); }

bool CheckRow(const std::array<double, kNumColumns>& v, const std::array<int, kNumColumns>& at,
              bool has_pwm, const ProcessedLog& log, const std::string& file, int line,
              LoadError* e) {
  auto fail = [&](int column, const std::string& msg) {
    text::SetError(e, file, line, at[column] + 1, msg);
    return false;
  };
  if (std::fabs(v[kT]) > 1e12) {
    return fail(kT, "t_s = " + Num(v[kT]) + " is not a time in seconds: nanoseconds?");
  }
  if (!log.t_s.empty() && !(v[kT] > log.t_s.back())) {
    return fail(kT, std::string(v[kT] == log.t_s.back() ? "duplicate" : "non-monotonic") +
                        " time " + Num(v[kT]) + " s (previous " + Num(log.t_s.back()) + " s)");
  }
  for (int k = 0; k < 3; ++k) {
    if (std::fabs(v[kX + k]) > kPositionMaxM) {
      return fail(kX + k, std::string(kColumns[kX + k]) + " = " + Num(v[kX + k]) +
                              " is more than 5 m from the scene origin: millimetres?");
    }
  }
  const double n = std::sqrt(v[kQw] * v[kQw] + v[kQw + 1] * v[kQw + 1] + v[kQw + 2] * v[kQw + 2] +
                             v[kQw + 3] * v[kQw + 3]);
  if (std::fabs(n - 1) > kQuaternionNormTolerance) {
    return fail(kQw, "qw..qz is not a unit quaternion (norm " + Num(n) + ")");
  }
  for (int c = 0; c < 4; ++c) {
    const double p = v[kP1 + c];
    if (p > kGaugeVacuumMaxPa) {
      return fail(kP1 + c, std::string(kColumns[kP1 + c]) + " = " + Num(p) +
                               " Pa looks like an absolute pressure; the plain format takes "
                               "gauge vacuum (ambient - absolute, positive = vacuum)");
    }
    if (p < kGaugeVacuumMinPa) {
      return fail(kP1 + c, std::string(kColumns[kP1 + c]) + " = " + Num(p) +
                               " Pa: vacuum written negative? The plain format takes vacuum "
                               "positive (ambient - absolute)");
    }
  }
  if (has_pwm && (v[kPwm] < 0 || v[kPwm] > 100)) {
    return fail(kPwm, "pwm_pct = " + Num(v[kPwm]) + " is outside 0..100 %");
  }
  return true;
}

bool ParseHeader(const std::vector<std::string_view>& cells, const std::string& file, int line,
                 std::array<int, kNumColumns>* at, LoadError* e) {
  at->fill(-1);
  for (size_t i = 0; i < cells.size(); ++i) {
    const std::string name = text::Lower(text::Trim(cells[i]));
    int found = -1;
    for (int k = 0; k < kNumColumns; ++k) {
      if (name == kColumns[k]) found = k;
    }
    if (found < 0) {
      text::SetError(e, file, line, text::ToInt(i + 1),
                     "unknown column " + text::Quote(cells[i]) +
                         " (the plain format: t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa..p4_pa, "
                         "optional fx_n,fy_n,fz_n,tx_nm,ty_nm,tz_nm and pwm_pct)");
      return false;
    }
    if ((*at)[found] >= 0) {
      text::SetError(e, file, line, text::ToInt(i + 1),
                     "column '" + name + "' appears twice (also column " +
                         std::to_string((*at)[found] + 1) + ")");
      return false;
    }
    (*at)[found] = static_cast<int>(i);
  }
  const bool any_ft = (*at)[kFx] >= 0 || (*at)[kFx + 1] >= 0 || (*at)[kFx + 2] >= 0 ||
                      (*at)[kFx + 3] >= 0 || (*at)[kFx + 4] >= 0 || (*at)[kFx + 5] >= 0;
  for (int k = 0; k < kPwm; ++k) {
    const bool required = k < kFx || any_ft;
    if (required && (*at)[k] < 0) {
      text::SetError(e, file, line, text::ToInt(cells.size() + 1),
                     std::string("missing column '") + kColumns[k] + "'" +
                         (k >= kFx ? " (F/T columns come all six or none)" : ""));
      return false;
    }
  }
  return true;
}

}  // namespace

namespace {

using LineFn = std::function<bool(int, std::string_view)>;

// The parser over any source of lines (`for_each_line(fn)`: false on a read error, with *error
// set), so a file is parsed as it is read, never held whole (a 1M-row log is ~95 MB of text).
bool ParsePlainLines(const std::function<bool(const LineFn&)>& for_each_line,
                     const std::string& file, ProcessedLog* log, LoadError* error) {
  try {
    *log = ProcessedLog();
    std::array<int, kNumColumns> at{};
    int at_t = 0, at_p1 = 0;
    size_t n_cells = 0;
    bool header = false, ok = true, has_ft = false, has_pwm = false;
    std::vector<int> lines;  // file line of each row
    const bool read = for_each_line([&](int line_no, std::string_view line) {
      if (text::Trim(line).empty()) return true;
      const std::vector<std::string_view> cells = text::SplitCells(line);
      if (!header) {
        double number = 0;
        if (text::ParseDouble(cells[0], &number) != text::NumberParse::kNotANumber) {
          text::SetError(error, file, line_no, 1,
                         "the plain format starts with a header row naming its columns "
                         "(t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,...)");
          return ok = false;
        }
        header = true;
        n_cells = cells.size();
        ok = ParseHeader(cells, file, line_no, &at, error);
        has_ft = at[kFx] >= 0;
        at_t = at[kT];
        at_p1 = at[kP1];
        has_pwm = at[kPwm] >= 0;
        return ok;
      }
      if (cells.size() != n_cells) {
        const bool missing = cells.size() < n_cells;
        text::SetError(error, file, line_no, text::ToInt((missing ? cells.size() : n_cells) + 1),
                       std::string(missing ? "missing column: " : "unexpected extra column: ") +
                           "row has " + std::to_string(cells.size()) + " cells, the header " +
                           std::to_string(n_cells));
        return ok = false;
      }
      std::array<double, kNumColumns> v{};
      for (int k = 0; k < kNumColumns; ++k) {
        if (at[k] < 0) continue;
        const std::string_view cell = cells[static_cast<size_t>(at[k])];
        const text::NumberParse r = text::ParseDouble(cell, &v[k]);
        if (r != text::NumberParse::kOk) {
          text::SetError(
              error, file, line_no, at[k] + 1,
              (r == text::NumberParse::kEmpty       ? std::string("empty cell")
               : r == text::NumberParse::kNonFinite ? "non-finite value " + text::Quote(cell)
                                                    : text::Quote(cell) + " is not a number") +
                  " (" + kColumns[k] + ")");
          return ok = false;
        }
      }
      if (!CheckRow(v, at, has_pwm, *log, file, line_no, error)) return ok = false;
      log->t_s.push_back(v[kT]);
      log->tcp_m.push_back({v[kX], v[kX + 1], v[kX + 2]});
      log->quat.push_back({v[kQw], v[kQw + 1], v[kQw + 2], v[kQw + 3]});
      log->p_pa.push_back({v[kP1], v[kP1 + 1], v[kP1 + 2], v[kP1 + 3]});
      if (has_ft) {
        log->ft.push_back({v[kFx], v[kFx + 1], v[kFx + 2], v[kFx + 3], v[kFx + 4], v[kFx + 5]});
      }
      if (has_pwm) log->pwm_pct.push_back(v[kPwm]);
      lines.push_back(line_no);
      return true;
    });
    if (!read || !ok) return false;
    if (log->t_s.empty()) {
      text::SetError(error, file, 0, 0,
                     header ? "empty log: no data rows after the header" : "empty file");
      return false;
    }
    std::string problem;
    size_t bad_row = 0;
    if (!CheckClock(log->t_s, true, true, &problem, &bad_row)) {
      text::SetError(error, file, lines[bad_row], at_t + 1, "t_s: " + problem);
      return false;
    }
    double peak = 0;
    size_t peak_row = 0;
    for (size_t i = 0; i < log->p_pa.size(); ++i) {
      for (double p : log->p_pa[i]) {
        if (p > peak) {
          peak = p;
          peak_row = i;
        }
      }
    }
    if (peak < kPeakVacuumMinPa) {
      text::SetError(error, file, lines[peak_row], at_p1 + 1,
                     "the largest vacuum in the log is " + Num(peak) +
                         " Pa: kPa under a _pa column? A trial on an object reads more than " +
                         Num(kPeakVacuumMinPa) +
                         " Pa (a cup that never touched anything gives "
                         "nothing to compare)");
      return false;
    }
    return true;
  } catch (const std::exception& ex) {
    text::SetError(error, file, 0, 0, std::string("cannot parse: ") + ex.what());
    return false;
  }
}

}  // namespace

bool ParsePlainLog(std::string_view contents, const std::string& file, ProcessedLog* log,
                   LoadError* error) {
  return ParsePlainLines(
      [contents](const LineFn& fn) {
        text::ForEachLine(contents, fn);
        return true;
      },
      file, log, error);
}

bool LoadPlainLog(const std::string& path, ProcessedLog* log, LoadError* error) {
  // Line by line with a bounded line length, parsed as read.
  return ParsePlainLines([&](const LineFn& fn) { return text::ForEachFileLine(path, fn, error); },
                         path, log, error);
}

bool WritePlainLog(const std::string& path, const ProcessedLog& log, std::string* error) {
  try {
    const size_t n = log.t_s.size();
    if (log.p_pa.size() != n || log.tcp_m.size() != n || log.quat.size() != n ||
        (!log.ft.empty() && log.ft.size() != n) ||
        (!log.pwm_pct.empty() && log.pwm_pct.size() != n)) {
      *error = path + ": the log's columns have different lengths";
      return false;
    }
    OutputFile file(path);
    std::ostream& f = file.stream();
    const bool has_ft = !log.ft.empty(), has_pwm = !log.pwm_pct.empty();
    const int last = has_ft ? kPwm : kFx;
    for (int k = 0; k < last; ++k) f << (k ? "," : "") << kColumns[k];
    if (has_pwm) f << ',' << kColumns[kPwm];
    f << '\n';
    for (size_t i = 0; i < n; ++i) {
      f << Num(log.t_s[i]);
      for (double v : log.tcp_m[i]) f << ',' << Num(v);
      for (double v : log.quat[i]) f << ',' << Num(v);
      for (double v : log.p_pa[i]) f << ',' << Num(v);
      if (has_ft) {
        for (double v : log.ft[i]) f << ',' << Num(v);
      }
      if (has_pwm) f << ',' << Num(log.pwm_pct[i]);
      f << '\n';
    }
    return file.Commit(error);
  } catch (const std::exception& ex) {
    *error = path + ": " + ex.what();
    return false;
  }
}

}  // namespace ssc
