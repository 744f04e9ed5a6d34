// Reading the real robot stack's logs as they are, and turning them into the twin's terms.
// docs/robot_logs.md describes the formats, the processing and the errors.
//
//   topic_csv.h   per-topic CSV files (the robot stack's own output), reader and writer
//   mat_log.h     the merged MATLAB file (matio), reader and writer
//   plain_log.h   one plain CSV for anyone else's robot (already gauge, scene frame)
//   align.h       the processing steps as pure functions
//   synthetic_log.h  robot-format logs made from a twin run, with perturbations
//
// Every reader reports bad input as a LoadError naming the file, line and column (1-based) and
// returns false; none lets an exception out.
#ifndef SSC_ROBOTLOG_ROBOT_LOG_H_
#define SSC_ROBOTLOG_ROBOT_LOG_H_

#include <Eigen/Geometry>

#include "geometry/dimensions.h"
#include "robotlog/align.h"
#include "robotlog/log_types.h"
#include "robotlog/mat_log.h"
#include "robotlog/plain_log.h"
#include "robotlog/topic_csv.h"

namespace ssc {

// Plausibility limits of the checks below (docs/robot_logs.md, "Errors").
inline constexpr double kAbsolutePressureMinPa = 15e3;   // a strong pump on a sealed cup
inline constexpr double kAbsolutePressureMaxPa = 175e3;  // MPRLS full scale, 25 psi
inline constexpr double kAmbientMinPa = 70e3;            // in-air offset: ~3000 m altitude
inline constexpr double kAmbientMaxPa = 110e3;
inline constexpr double kQuaternionNormTolerance = 0.01;
inline constexpr double kPositionMaxM = 5.0;  // UR-10 reach 1.3 m; mm would be > 5
// Clock checks, for every format (stamps or times in another unit must not pass): the median
// time between samples of a sensor stream (pressure, pose, F/T; not PWM, which is published
// only when it changes), and the span of the pressure stream, the recording's duration.
inline constexpr double kSampleIntervalMinS = 1e-4;  // 10 kHz; us stamps at 50 Hz read as ns: 20 us
inline constexpr double kSampleIntervalMaxS = 1.0;   // ms times at 100 Hz read as s: 10 s
inline constexpr double kRecordingMinS = 0.5;        // a trial with its in-air lead: seconds
inline constexpr double kRecordingMaxS = 6 * 3600.0;
// ROS stamps are ns since the Unix epoch: 2001-09-09 .. 2100 (us or ms stamps fall in 1970).
inline constexpr long long kRosStampMinNs = 1000000000000000000LL;
inline constexpr long long kRosStampMaxNs = 4102444800000000000LL;

// The median time between samples of `t_s` and its span must be a sensor stream's: the error
// (false) names the found values and the likely unit. Used by every reader.
bool CheckClock(const std::vector<double>& t_s, bool periodic, bool whole_recording,
                std::string* problem, size_t* at);

// Checks a merged log's units and shapes, reporting the first bad cell at its file line (CSV)
// or matrix row (.mat): the required streams present and non-empty; pressures absolute (within
// 15..175 kPa, so gauge vacuum or another unit is refused); unit quaternions; positions within
// 5 m of the base (millimetres refused); PWM within 0..255; CheckClock on each stream (stamps
// in us or ms instead of ns refused).
bool ValidateRobotLog(const RobotLog& log, LoadError* error);
// The stamps of a log read from a file are ROS time (ns since the epoch): t0_ns in 2001..2100.
bool CheckRosEpoch(const RobotLog& log, LoadError* error);

enum class ClockSource {
  kPressure,  // the pressure samples' own times (the controller acted on pressure samples)
  kUniform,   // a uniform clock at clock_rate_hz over the pressure/pose overlap
};

// Largest tool centre point offset along tool0 z accepted (--tcp-offset, mm on the command line).
constexpr double kMaxTcpOffsetM = 0.5;

struct ProcessOptions {
  // In-air offset window: [trial_start_s - offset_window_s, trial_start_s). A negative
  // trial_start_s puts the window at the first offset_window_s of the pressure stream.
  double offset_window_s = 1.0;
  double trial_start_s = -1.0;
  int moving_average = 7;                    // the host's filter, samples (1 = none)
  double tcp_offset_m = kToolCentreOffsetM;  // tool centre point along tool0 z
  Interpolation interpolation = Interpolation::kLinear;
  ClockSource clock = ClockSource::kPressure;
  double clock_rate_hz = 100.0;  // kUniform only
  PwmScale pwm_scale = PwmScale::kAuto;
  // Robot base -> scene frame. The project's scenes put the UR base frame at the world origin.
  Eigen::Isometry3d X_scene_base = Eigen::Isometry3d::Identity();
};

// The twin's view of a raw log, in order: in-air offset per chamber (its mean must be an
// ambient pressure, 70..110 kPa), gauge vacuum = offset - absolute, the host's moving average
// (on the pressure samples, as the host ran it), then everything onto the clock: the pressure
// times (or the uniform clock) inside the span both pressure and pose cover; pose, F/T by
// `interpolation`, PWM held (a command holds until the next); TCP = tool0 + tcp_offset_m along
// tool0 z; then base -> scene.
bool ProcessRobotLog(const RobotLog& log, const ProcessOptions& options, ProcessedLog* out,
                     LoadError* error);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_ROBOT_LOG_H_
