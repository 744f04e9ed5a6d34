// Fast following: the published law's direction with an adaptive step, aimed ahead along the
// turning edge, and steps taken from where the arm was sent rather than where it lags.
//
// Per iteration, from the law's reading of the four chambers (ComputeContourStep):
//   strength   |(dPx, dPy)|, Pa: how clearly the cup straddles the edge;
//   turn       the turn of the edge per metre travelled: the change of the differential's
//              direction between iterations over the measured distance between them, filtered
//              (turn_filter is the newest measurement's weight);
//   period     the measured time since the last iteration over the nominal period.
// The step grows to step_max_mm where the edge is straight and the signal strong, and shrinks
// toward step_min_mm where it turns (a turn of turn_slow_deg per step halves it) or the signal
// weakens (below strength_pa); it scales with the measured period (the same speed when the loop
// runs late). The direction is the law's turned by `lead` times half the edge's predicted turn
// between the cup and the target (the chord of the turning edge). The first ramp_iterations
// grow the step from step_min_mm (the turn estimate settles, the arm starts). The arm
// lags its target (the servo's smoothing) and misses it (the landing error); the step adds
// lag_gain times what separates the measured tool from the previous target, so the target, not
// the lagging tool, advances by the step. With tare_in_air, the chambers' residual tare offsets
// are measured in air on the way down (AirTare) and subtracted from every reading.
#ifndef SSC_CONTROLLER_FAST_FOLLOWING_H_
#define SSC_CONTROLLER_FAST_FOLLOWING_H_

#include <array>
#include <cstdint>

#include "controller/air_tare.h"
#include "controller/contour_law.h"
#include "controller/controller_registry.h"

namespace ssc {

struct FastFollowingParams {
  double step_max_mm = 7.5;      // step on a straight edge with a strong differential
  double step_min_mm = 5.0;      // step where the edge turns hard or the differential is weak
  double strength_pa = 20.0;     // differential magnitude for the full step (0: always full)
  double turn_slow_deg = 90;     // turn of the edge over one step that halves the step
  double turn_filter = 0.5;      // weight of the newest turn measurement
  double lead = 0.0;             // share of the edge's predicted turn the aim leads by
  double lag_gain = 1.0;         // share of the arm's lag behind its target added to the step
  double lateral_gain = 0.6;     // the move across the edge over the law's at its dL
  double timing = 1.0;           // 1: scale the step by the measured period; 0: fixed
  double ramp_iterations = 0;    // the step grows from step_min_mm over this many iterations
  double tare_in_air = 0;        // 1: re-tare the chambers in air on the way down (AirTare)
  double tare_clearance_mm = 4;  // ... from the readings this far above the hold height
};

// The step length, mm: step_max_mm x min(1, strength / strength_pa) / (1 + turn_per_step /
// turn_slow), clamped to [step_min_mm, step_max_mm], times the period ratio (clamped to
// [0.5, 2]) when `timing` is on. `turn_per_step_rad` is the edge's turn over a step of
// step_max_mm.
double AdaptiveStepMm(const FastFollowingParams& p, double strength_pa, double turn_per_step_rad,
                      double period_ratio);

// The largest step at iteration `iteration` of following while ramping up: from step_min_mm at
// the first iteration linearly to step_max_mm at ramp_iterations (step_max_mm from then on).
double RampStepMm(const FastFollowingParams& p, std::uint64_t iteration);

// The signed angle from a to b (2D vectors), rad in (-pi, pi]; 0 when either is zero.
double SignedAngle(const std::array<double, 2>& a, const std::array<double, 2>& b);

class FastFollowingController : public Controller {
 public:
  FastFollowingController(const ControllerContext& context, const FastFollowingParams& p);
  ControllerCommand Step(const ControllerInput& in) override;
  bool ObservesBeforeFollowing() const override { return p_.tare_in_air > 0; }
  void ObserveBeforeFollowing(const ControllerInput& in) override;
  // The chambers' offsets subtracted from every reading while following, Pa.
  const std::array<double, 4>& tare_offsets_pa() const { return tare_pa_; }
  // The filtered turn of the edge, rad per metre (tool frame sense).
  double turn_per_m() const { return turn_per_m_; }
  double last_step_mm() const { return last_step_mm_; }

 private:
  ContourLawParams law_;
  double period_s_;
  FastFollowingParams p_;
  bool have_last_ = false, have_target_ = false;
  std::array<double, 2> last_g_hat_{};     // tool frame
  std::array<double, 2> last_tool_m_{};    // world
  std::array<double, 2> last_target_m_{};  // world: where the last step sent the tool
  double last_t_s_ = 0;
  double turn_per_m_ = 0;
  double last_step_mm_ = 0;
  AirTare air_tare_;
  bool tared_ = false;
  std::array<double, 4> tare_pa_{};
};

ControllerType FastFollowingControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_FAST_FOLLOWING_H_
