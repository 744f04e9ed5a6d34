#include "robotlog/robot_log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>

#include "robotlog/text_cells.h"

namespace ssc {
namespace {

const char* StreamName(StreamId id) {
  switch (id) {
    case StreamId::kPressure:
      return "pressure";
    case StreamId::kPose:
      return "tool pose";
    case StreamId::kFt:
      return "F/T";
    case StreamId::kPwm:
      break;
  }
  return "PWM";
}

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

// An error at row i of a stream; `field` is the 0-based field index (-1: the time column).
// Columns count the time stamp as column 1, as in the files.
bool Fail(const Stream& s, StreamId id, size_t i, int field, const std::string& message,
          LoadError* e) {
  const std::string file = s.source.empty() ? std::string(StreamName(id)) + " stream" : s.source;
  const int line = i < s.lines.size() ? s.lines[i] : text::ToInt(i + 1);
  const std::string prefix = s.variable.empty() ? "" : "variable '" + s.variable + "': ";
  text::SetError(e, file, line, field + 2, prefix + message);
  return false;
}

bool CheckShape(const Stream& s, StreamId id, LoadError* e) {
  const LabTopic& spec = GetLabTopic(id);
  if (s.rows.size() != s.t_s.size()) {
    return Fail(s, id, 0, -1,
                "has " + std::to_string(s.t_s.size()) + " times but " +
                    std::to_string(s.rows.size()) + " rows",
                e);
  }
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.rows[i].size() != spec.size()) {
      return Fail(s, id, i, -1,
                  "row has " + std::to_string(s.rows[i].size()) + " fields, the topic has " +
                      std::to_string(spec.size()),
                  e);
    }
    if (!std::isfinite(s.t_s[i]) || (i > 0 && !(s.t_s[i] > s.t_s[i - 1]))) {
      return Fail(s, id, i, -1, "non-finite, duplicate or non-monotonic time", e);
    }
    for (size_t k = 0; k < spec.size(); ++k) {
      if (!std::isfinite(s.rows[i][k])) {
        return Fail(s, id, i, static_cast<int>(k), "non-finite value (" + spec.short_names[k] + ")",
                    e);
      }
    }
  }
  return true;
}

bool CheckStreamClock(const Stream& s, StreamId id, LoadError* e) {
  std::string problem;
  size_t at = 0;
  if (CheckClock(s.t_s, id != StreamId::kPwm, id == StreamId::kPressure, &problem, &at)) {
    return true;
  }
  return Fail(s, id, at, -1, problem, e);
}

std::string Span(const Stream& s) {
  return "[" + Num(s.t_s.front()) + ", " + Num(s.t_s.back()) + "] s";
}

// Pose and pressure must overlap for at least this share of the pressure stream's span.
constexpr double kMinStreamOverlap = 0.5;

bool CheckPressure(const Stream& s, LoadError* e) {
  for (size_t i = 0; i < s.size(); ++i) {
    for (int c = 1; c <= 4; ++c) {
      const double p = s.rows[i][c];
      if (p < kAbsolutePressureMinPa) {
        return Fail(s, StreamId::kPressure, i, c,
                    "P" + std::to_string(c) + " = " + Num(p) +
                        " Pa is not an absolute pressure (raw sensor readings lie within 15-175 "
                        "kPa): gauge vacuum or another unit? This stream takes raw absolute Pa",
                    e);
      }
      if (p > kAbsolutePressureMaxPa) {
        return Fail(s, StreamId::kPressure, i, c,
                    "P" + std::to_string(c) + " = " + Num(p) +
                        " Pa is above the sensor's absolute range (15-175 kPa): another unit?",
                    e);
      }
    }
  }
  return true;
}

bool CheckPose(const Stream& s, LoadError* e) {
  static const char* const kAxes[3] = {"position.x", "position.y", "position.z"};
  for (size_t i = 0; i < s.size(); ++i) {
    const std::vector<double>& r = s.rows[i];
    const double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    if (std::fabs(n - 1.0) > kQuaternionNormTolerance) {
      return Fail(s, StreamId::kPose, i, 0,
                  "orientation is not a unit quaternion (norm " + Num(n) + ")", e);
    }
    for (int k = 0; k < 3; ++k) {
      if (std::fabs(r[4 + k]) > kPositionMaxM) {
        return Fail(s, StreamId::kPose, i, 4 + k,
                    std::string(kAxes[k]) + " = " + Num(r[4 + k]) +
                        " is more than 5 m from the robot base: millimetres? The pose takes m",
                    e);
      }
    }
  }
  return true;
}

bool CheckPwm(const Stream& s, LoadError* e) {
  for (size_t i = 0; i < s.size(); ++i) {
    const double v = s.rows[i][0];
    if (v < 0 || v > 255) {
      return Fail(s, StreamId::kPwm, i, 0,
                  "PWM " + Num(v) + " is outside 0..255 (fraction, percent or 8-bit duty)", e);
    }
  }
  return true;
}

}  // namespace

bool LabRunArgs::any() const {
  return !std::isnan(p_ref_pa) || !std::isnan(beta) || !std::isnan(d_lat_m) ||
         !std::isnan(disk_radius_mm) || !std::isnan(start_offset_m) || !history.empty();
}

std::string LoadError::ToString() const {
  std::ostringstream os;
  os << (file.empty() ? "log" : file);
  if (line > 0) os << ':' << line;
  if (line > 0 && column > 0) os << ':' << column;
  os << ": " << message;
  return os.str();
}

bool CheckClock(const std::vector<double>& t_s, bool periodic, bool whole_recording,
                std::string* problem, size_t* at) {
  if (t_s.size() < 2) return true;
  if (periodic) {
    std::vector<double> dt(t_s.size() - 1);
    for (size_t i = 1; i < t_s.size(); ++i) dt[i - 1] = t_s[i] - t_s[i - 1];
    std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
    const double median_s = dt[dt.size() / 2];
    if (median_s < kSampleIntervalMinS || median_s > kSampleIntervalMaxS) {
      *at = 1;
      *problem = "samples are " + Num(median_s) + " s apart (median): " +
                 (median_s < kSampleIntervalMinS ? "faster than 10 kHz, so the stamps are not "
                                                   "in the declared unit (us read as ns?)"
                                                 : "slower than 1 Hz, so the times are not in "
                                                   "the declared unit (ms read as s?)") +
                 "; a sensor stream has 0.1 ms to 1 s between samples";
      return false;
    }
  }
  const double span_s = t_s.back() - t_s.front();
  if (whole_recording && (span_s < kRecordingMinS || span_s > kRecordingMaxS)) {
    *at = t_s.size() - 1;
    *problem = "the recording lasts " + Num(span_s) + " s over " + std::to_string(t_s.size()) +
               " samples: " +
               (span_s < kRecordingMinS ? "shorter than 0.5 s, so the stamps are not in the "
                                          "declared unit (us read as ns?)"
                                        : "longer than 6 h, so the times are not in the "
                                          "declared unit (ms read as s?)");
    return false;
  }
  return true;
}

bool CheckRosEpoch(const RobotLog& log, LoadError* error) {
  if (log.t0_ns >= kRosStampMinNs && log.t0_ns < kRosStampMaxNs) return true;
  const Stream& p = log.pressure_abs;
  const std::string file = p.source.empty() ? "log" : p.source;
  text::SetError(error, file, p.lines.empty() ? 0 : p.lines.front(), 1,
                 "first time stamp " + std::to_string(log.t0_ns) +
                     " is not ROS time in ns since 1970 between 2001 and 2100 (" +
                     (log.t0_ns < kRosStampMinNs ? "microseconds or milliseconds?" : "too late") +
                     ")");
  return false;
}

bool ValidateRobotLog(const RobotLog& log, LoadError* error) {
  try {
    const Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
    for (const LabTopic& spec : LabTopics()) {
      const Stream& s = *streams[static_cast<size_t>(spec.id)];
      if (s.empty()) {
        if (spec.required) {
          text::SetError(
              error, s.source.empty() ? "log" : s.source, 0, 0,
              std::string("empty stream: the ") + StreamName(spec.id) + " stream is required");
          return false;
        }
        continue;
      }
      if (!CheckShape(s, spec.id, error)) return false;
    }
    // Values before clocks: a cell in the wrong unit is the more precise message.
    if (!CheckPressure(log.pressure_abs, error) || !CheckPose(log.tool_pose, error) ||
        !CheckPwm(log.pwm, error)) {
      return false;
    }
    for (const LabTopic& spec : LabTopics()) {
      const Stream& s = *streams[static_cast<size_t>(spec.id)];
      if (!s.empty() && !CheckStreamClock(s, spec.id, error)) return false;
    }
    // Pressure and pose must describe the same run: a pose file cut short (or from another
    // recording) would replay a sliver of it while the report looked whole.
    const Stream& p = log.pressure_abs;
    const Stream& q = log.tool_pose;
    const double p_span_s = p.t_s.back() - p.t_s.front();
    const double overlap_s =
        std::min(p.t_s.back(), q.t_s.back()) - std::max(p.t_s.front(), q.t_s.front());
    if (p_span_s > 0 && overlap_s < kMinStreamOverlap * p_span_s) {
      text::SetError(error, q.source.empty() ? "log" : q.source, 0, 0,
                     "the pose stream covers " + Span(q) + ", the pressure stream " + Span(p) +
                         (overlap_s > 0 ? ": they overlap for only " + Num(overlap_s) +
                                              " s, less than half the recording"
                                        : ": they do not overlap") +
                         " (a file cut short, or from another recording?)");
      return false;
    }
    return true;
  } catch (const std::exception& ex) {
    text::SetError(error, "log", 0, 0, std::string("cannot check: ") + ex.what());
    return false;
  }
}

bool ProcessRobotLog(const RobotLog& log, const ProcessOptions& o, ProcessedLog* out,
                     LoadError* error) {
  try {
    *out = ProcessedLog();
    if (!ValidateRobotLog(log, error)) return false;
    const Stream& p = log.pressure_abs;
    const Stream& pose = log.tool_pose;
    const std::string p_file = p.source.empty() ? "pressure stream" : p.source;
    if (!(o.tcp_offset_m >= 0 && o.tcp_offset_m <= kMaxTcpOffsetM)) {
      // The option is in mm (--tcp-offset, tcp_offset_mm): say so in mm.
      text::SetError(error, p_file, 0, 0,
                     "TCP offset " + Num(o.tcp_offset_m * 1e3) + " mm is out of range [0, " +
                         Num(kMaxTcpOffsetM * 1e3) +
                         "] mm (the lab's tool: " + Num(kToolCentreOffsetM * 1e3) + " mm)");
      return false;
    }
    // Windows measured against the log they act on: longer than the log, they would average
    // the trial itself into the in-air offset (a mean ratio of -11280).
    const double span_s = p.t_s.back() - p.t_s.front();
    if (o.trial_start_s < 0 && o.offset_window_s >= 0.5 * span_s) {
      text::SetError(error, p_file, 0, 0,
                     "in-air offset window " + Num(o.offset_window_s) +
                         " s (--offset-window) is not shorter than half the pressure stream (" +
                         Num(span_s) + " s, " + Span(p) +
                         "): the window must hold only the cup in air before the trial");
      return false;
    }
    if (o.moving_average < 1) {
      text::SetError(error, p_file, 0, 0,
                     "moving average of " + std::to_string(o.moving_average) +
                         " samples (--average) is out of range: at least 1 (1 = none)");
      return false;
    }
    if (o.moving_average > static_cast<int>(p.size()) / 2) {
      text::SetError(error, p_file, 0, 0,
                     "moving average of " + std::to_string(o.moving_average) +
                         " samples (--average) is longer than half the log's " +
                         std::to_string(p.size()) + " pressure samples");
      return false;
    }
    if (!(o.offset_window_s > 0) || o.moving_average > 100000 ||
        (o.clock == ClockSource::kUniform && !(o.clock_rate_hz > 0 && o.clock_rate_hz <= 1e5))) {
      text::SetError(error, p_file, 0, 0,
                     "bad processing options: need offset window > 0 s, "
                     "moving average <= 100000 samples and a uniform clock rate in (0, 100000] "
                     "Hz");
      return false;
    }

    // 1. In-air offset, as the robot host took it before the trial.
    const double start_s =
        o.trial_start_s >= 0 ? o.trial_start_s : p.t_s.front() + o.offset_window_s;
    const double begin_s = start_s - o.offset_window_s;
    std::array<double, 4> offset{};
    if (InAirOffset(p, begin_s, start_s, &offset) == 0) {
      text::SetError(error, p_file, 0, 0,
                     "no pressure sample in the in-air offset window [" + Num(begin_s) + ", " +
                         Num(start_s) + ") s; the stream covers " + Span(p));
      return false;
    }
    size_t first_in_window = 0;
    while (p.t_s[first_in_window] < begin_s) ++first_in_window;
    for (int c = 0; c < 4; ++c) {
      if (offset[c] < kAmbientMinPa || offset[c] > kAmbientMaxPa) {
        return Fail(p, StreamId::kPressure, first_in_window, c + 1,
                    "P" + std::to_string(c + 1) + " averages " + Num(offset[c]) +
                        " Pa over the in-air window [" + Num(begin_s) + ", " + Num(start_s) +
                        ") s, not an ambient pressure (70-110 kPa): is the cup in air then?",
                    error);
      }
    }
    out->offset_pa = offset;

    // 2. Gauge vacuum and the host's filter, on the pressure samples.
    const std::vector<std::array<double, 4>> vacuum =
        MovingAverage(GaugeVacuum(p, offset), o.moving_average);

    // 3. The clock: inside the span covered by both pressure and pose.
    const double from_s = std::max(p.t_s.front(), pose.t_s.front());
    const double to_s = std::min(p.t_s.back(), pose.t_s.back());
    std::vector<size_t> p_index;  // pressure clock: which samples
    if (o.clock == ClockSource::kPressure) {
      for (size_t i = 0; i < p.size(); ++i) {
        if (p.t_s[i] >= from_s && p.t_s[i] <= to_s) {
          out->t_s.push_back(p.t_s[i]);
          p_index.push_back(i);
        }
      }
    } else {
      const double ticks = (to_s - from_s) * o.clock_rate_hz;
      if (ticks > 1e8) {
        text::SetError(error, p_file, 0, 0,
                       "a uniform clock at " + Num(o.clock_rate_hz) + " Hz over " +
                           Num(to_s - from_s) + " s would have " + Num(ticks) +
                           " samples (limit 1e8)");
        return false;
      }
      out->t_s = UniformClock(from_s, to_s, o.clock_rate_hz);
    }
    if (out->t_s.empty()) {
      text::SetError(error, p_file, 0, 0,
                     "the pressure and pose streams do not overlap in time: pressure covers " +
                         Span(p) + ", pose " + Span(pose));
      return false;
    }

    // 4. Everything onto the clock.
    if (o.clock == ClockSource::kPressure) {
      for (size_t i : p_index) out->p_pa.push_back(vacuum[i]);
    } else {
      Stream v;
      v.t_s = p.t_s;
      for (const auto& row : vacuum) v.rows.push_back({row[0], row[1], row[2], row[3]});
      for (const auto& row : ResampleRows(v, out->t_s, o.interpolation)) {
        out->p_pa.push_back({row[0], row[1], row[2], row[3]});
      }
    }
    const Eigen::Quaterniond q_scene_base(o.X_scene_base.rotation());
    std::vector<Eigen::Quaterniond> q_base_tool0;
    const std::vector<Eigen::Isometry3d> X_base_tool0 =
        ResamplePose(pose, out->t_s, o.interpolation, &q_base_tool0);
    for (size_t i = 0; i < X_base_tool0.size(); ++i) {
      const Eigen::Isometry3d X_scene_tool0 = o.X_scene_base * X_base_tool0[i];
      const Eigen::Vector3d tcp = TcpFromTool0(X_scene_tool0, o.tcp_offset_m);
      const Eigen::Quaterniond q = q_scene_base * q_base_tool0[i];
      out->tcp_m.push_back({tcp.x(), tcp.y(), tcp.z()});
      out->quat.push_back({q.w(), q.x(), q.y(), q.z()});
    }
    for (const auto& row : ResampleRows(log.ft, out->t_s, o.interpolation)) {
      out->ft.push_back({row[0], row[1], row[2], row[3], row[4], row[5]});
    }
    const PwmScale scale = o.pwm_scale == PwmScale::kAuto ? DetectPwmScale(log.pwm) : o.pwm_scale;
    for (const auto& row : ResampleRows(log.pwm, out->t_s, Interpolation::kZeroOrderHold)) {
      out->pwm_pct.push_back(PwmPercent(row[0], scale));
    }
    return true;
  } catch (const std::exception& ex) {
    text::SetError(error, "log", 0, 0, std::string("cannot process: ") + ex.what());
    return false;
  }
}

}  // namespace ssc
