// Robot-format logs made from a run in the twin's terms, with the perturbations a real log has
// (sensor offsets, noise, a different pressure rate, late or jittered pose stamps, dropped
// samples), so tests can feed the readers and the comparison logs whose truth is known.
// MakeRobotLog inverts ProcessRobotLog: processing its output (moving average 1, in-air window
// = the in-air lead) gives back the run, up to the perturbations.
#ifndef SSC_ROBOTLOG_SYNTHETIC_LOG_H_
#define SSC_ROBOTLOG_SYNTHETIC_LOG_H_

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "geometry/dimensions.h"
#include "robotlog/align.h"
#include "robotlog/log_types.h"

namespace ssc {

// One sample of a run as the twin records it.
struct TwinSample {
  double t_s = 0;
  std::array<double, 3> tcp_m{};           // tool centre point, scene frame
  std::array<double, 4> quat{1, 0, 0, 0};  // tool0 orientation, scene frame (w, x, y, z)
  std::array<double, 4> p_pa{};            // gauge vacuum, positive = vacuum
  std::array<double, 6> ft{};              // N, N m
  double pwm_pct = 100;
};

struct LogPerturbation {
  long long t0_ns = 1700000000000000000LL;  // ROS stamp of the first sample
  double ambient_pa = 101325;
  std::array<double, 4> sensor_offset_pa{};  // per-chamber bias of the absolute sensors
  double pressure_scale = 1;                 // logged vacuum = scale x run vacuum
  double noise_pa = 0;                       // Gaussian, 1 sigma, per chamber and sample
  double in_air_s = 1.0;                     // in-air samples before the run (first pose, vacuum 0)
  double pressure_rate_hz = 0;  // > 0: pressures sampled at this rate (linear), else run times
  double pose_delay_s = 0;      // pose and F/T stamps later than the truth by this
  double jitter_s = 0;          // uniform stamp jitter, +-, on every stream (order kept)
  double drop_fraction = 0;     // pose and F/T samples dropped at random (ends kept)
  PwmScale pwm_scale = PwmScale::kPercent;
  double tcp_offset_m = kToolCentreOffsetM;
  Eigen::Isometry3d X_scene_base = Eigen::Isometry3d::Identity();
  unsigned seed = 1;
};

// The run must have strictly increasing times. Deterministic for a given seed.
RobotLog MakeRobotLog(const std::vector<TwinSample>& run, const LogPerturbation& perturbation);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_SYNTHETIC_LOG_H_
