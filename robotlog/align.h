// The processing steps between a robot log and the twin, as pure functions on streams:
// resampling onto a clock, the robot host's in-air offset and moving average, the tool centre
// point, the base -> scene transform and the PWM scale. ProcessRobotLog (robot_log.h) chains
// them.
//
// Interpolation: kLinear interpolates each value column linearly and the orientation by slerp
// (the shortest way); kZeroOrderHold takes the latest sample at or before each time (what the
// robot host knew then: it acted on the last message received). Outside a stream's time span
// both hold the end sample; ProcessRobotLog only asks inside the pressure/pose overlap.
#ifndef SSC_ROBOTLOG_ALIGN_H_
#define SSC_ROBOTLOG_ALIGN_H_

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "robotlog/log_types.h"

namespace ssc {

enum class Interpolation { kLinear, kZeroOrderHold };

// Every column of `in` at each time of `t_s` (any order).
std::vector<std::vector<double>> ResampleRows(const Stream& in, const std::vector<double>& t_s,
                                              Interpolation mode);

// Pose rows (qw, qx, qy, qz, x, y, z) as X_base_tool0 at each time of `t_s`: position as
// ResampleRows, orientation by slerp (kLinear) or held (kZeroOrderHold), normalised. `quats`,
// when given, receives the orientations as quaternions keeping the logged sign (a rotation
// matrix would not).
std::vector<Eigen::Isometry3d> ResamplePose(const Stream& pose, const std::vector<double>& t_s,
                                            Interpolation mode,
                                            std::vector<Eigen::Quaterniond>* quats = nullptr);

// begin_s, begin_s + 1/rate_hz, ... up to end_s (inclusive within 1e-9 s). Empty if rate_hz <= 0
// or end_s < begin_s.
std::vector<double> UniformClock(double begin_s, double end_s, double rate_hz);

// The robot host's in-air offset: per chamber, the mean absolute pressure (columns P1..P4 of
// the pressure stream) over the samples with begin_s <= t < end_s. Returns the number of
// samples used (0: none in the window; `offset_pa` untouched).
int InAirOffset(const Stream& pressure_abs, double begin_s, double end_s,
                std::array<double, 4>* offset_pa);

// Gauge vacuum = offset - absolute, positive = vacuum, per sample and chamber.
std::vector<std::array<double, 4>> GaugeVacuum(const Stream& pressure_abs,
                                               const std::array<double, 4>& offset_pa);

// The host's causal moving average over the last `window` samples (fewer at the start, where
// the host had fewer); window <= 1 returns the input.
std::vector<std::array<double, 4>> MovingAverage(const std::vector<std::array<double, 4>>& x,
                                                 int window);

// X_base_tool0 from one pose row (qw, qx, qy, qz, x, y, z); the quaternion is normalised.
Eigen::Isometry3d PoseFromRow(const std::vector<double>& row);

// Tool centre point: `tcp_offset_m` along tool0's z axis (the F/T transducer plus the cup:
// 146 mm on the real robot), in the frame X_frame_tool0 is given in.
Eigen::Vector3d TcpFromTool0(const Eigen::Isometry3d& X_frame_tool0, double tcp_offset_m);
// The inverse: tool0's position from the tool centre point and tool0's orientation (w, x, y, z).
Eigen::Vector3d Tool0FromTcp(const Eigen::Vector3d& tcp, const Eigen::Quaterniond& q_frame_tool0,
                             double tcp_offset_m);

// Moves a processed log into another frame: X_new_old applied to the TCP and to tool0's
// orientation (times, pressures, F/T and PWM unchanged).
void TransformProcessedLog(const Eigen::Isometry3d& X_new_old, ProcessedLog* log);

// The transform hook for the robot base -> scene frame when it comes as a 4x4 homogeneous
// matrix (row-major). The rotation block is orthonormalised.
Eigen::Isometry3d IsometryFromRowMajor(const std::array<double, 16>& m);

// PWM as logged: a fraction (0..1), a percent (0..100) or an 8-bit duty (0..255).
enum class PwmScale { kAuto, kFraction, kPercent, kByte };
// kAuto resolved on the stream's largest value: <= 1 fraction, <= 100 percent, else byte. The
// pump runs at 100 % during contour following, so a trial's maximum tells the scale; a log that
// never drives the pump above 1 % (percent) or 100/255 (byte) is misread: pass the scale.
PwmScale DetectPwmScale(const Stream& pwm);
double PwmPercent(double raw, PwmScale scale);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_ALIGN_H_
