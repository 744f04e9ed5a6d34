#include "controller/fast_following.h"

#include <algorithm>
#include <cmath>

#include "geometry/plane.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Below this travel between iterations the differential's turn says nothing of the edge.
constexpr double kMinTravelM = 0.5e-3;

using plane::Rotated;

}  // namespace

double AdaptiveStepMm(const FastFollowingParams& p, double strength_pa, double turn_per_step_rad,
                      double period_ratio) {
  const double lo = std::min(p.step_min_mm, p.step_max_mm);
  const double strong =
      p.strength_pa > 0 ? std::min(1.0, std::max(strength_pa, 0.0) / p.strength_pa) : 1.0;
  const double turn_slow_rad = p.turn_slow_deg * kPi / 180;
  const double straight = 1.0 / (1.0 + std::fabs(turn_per_step_rad) / turn_slow_rad);
  double step = std::clamp(p.step_max_mm * strong * straight, lo, p.step_max_mm);
  if (p.timing > 0 && std::isfinite(period_ratio)) step *= std::clamp(period_ratio, 0.5, 2.0);
  return step;
}

double RampStepMm(const FastFollowingParams& p, std::uint64_t iteration) {
  const double lo = std::min(p.step_min_mm, p.step_max_mm);
  if (!(p.ramp_iterations > 0) || static_cast<double>(iteration) >= p.ramp_iterations)
    return p.step_max_mm;
  return lo + (p.step_max_mm - lo) * static_cast<double>(iteration) / p.ramp_iterations;
}

double SignedAngle(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  const double cross = a[0] * b[1] - a[1] * b[0], dot = a[0] * b[0] + a[1] * b[1];
  if (cross == 0 && dot == 0) return 0;
  return std::atan2(cross, dot);
}

FastFollowingController::FastFollowingController(const ControllerContext& context,
                                                 const FastFollowingParams& p)
    : law_(context.law), period_s_(context.control_period_s), p_(p) {}

void FastFollowingController::ObserveBeforeFollowing(const ControllerInput& in) {
  air_tare_.Add(in.p_pa, in.tool_m[2]);
}

ControllerCommand FastFollowingController::Step(const ControllerInput& in) {
  ControllerCommand c;
  if (p_.tare_in_air > 0 && !tared_) {  // the hold height is known from the first iteration on
    tare_pa_ = air_tare_.Offsets(in.hold_z_m, p_.tare_clearance_mm * 1e-3);
    tared_ = true;
  }
  std::array<double, 4> p_pa = in.p_pa;
  for (std::size_t k = 0; k < 4; ++k) p_pa[k] -= tare_pa_[k];
  const ContourStep law = ComputeContourStep(p_pa, law_);
  const std::array<double, 2> tool = {in.tool_m[0], in.tool_m[1]};
  const auto& R = in.tool_rotation;
  if (!law.moving) {  // the dead band: hold, and measure the turn afresh after it
    have_last_ = have_target_ = false;
    last_step_mm_ = 0;
    return c;
  }
  const double period_ratio = have_last_ ? (in.t_s - last_t_s_) / period_s_ : 1.0;
  if (have_last_) {
    const double travel = std::hypot(tool[0] - last_tool_m_[0], tool[1] - last_tool_m_[1]);
    if (travel > kMinTravelM) {
      const double measured = SignedAngle(last_g_hat_, law.correction) / travel;
      turn_per_m_ += p_.turn_filter * (measured - turn_per_m_);
    }
  }
  const double strength = std::hypot(law.dpx_pa, law.dpy_pa);
  double step_mm = AdaptiveStepMm(p_, strength, turn_per_m_ * p_.step_max_mm * 1e-3, period_ratio);
  // Speeding up over the first iterations, while the turn estimate settles and the arm starts.
  if (p_.ramp_iterations > 0 && static_cast<double>(in.iteration) < p_.ramp_iterations) {
    step_mm = std::min(step_mm, RampStepMm(p_, in.iteration));
  }
  // The arm's lag behind the last target along the edge (tool frame): made up, so the target,
  // not the lagging tool, advances by the step. Across the edge the step starts from the
  // measured tool, as the law's does.
  const double cf_norm = std::sqrt(1 + law.cf * law.cf);
  double lag_along_m = 0;
  if (have_target_) {
    const double wx = last_target_m_[0] - tool[0], wy = last_target_m_[1] - tool[1];
    const std::array<double, 2> lag = {R[0] * wx + R[3] * wy, R[1] * wx + R[4] * wy};
    // A target the arm cannot reach (held by the object) is not chased further.
    lag_along_m = std::clamp(lag[0] * law.along_edge[0] + lag[1] * law.along_edge[1], 0.0,
                             2 * p_.step_max_mm * 1e-3);
  }
  const double along_m = step_mm * 1e-3 / cf_norm + p_.lag_gain * lag_along_m;
  // Aimed along the chord of the turning edge from the tool to the target: a chord of arc
  // length L leaves the tangent at half the turn over L.
  const std::array<double, 2> aim = Rotated(law.along_edge, p_.lead * turn_per_m_ * 0.5 * along_m);
  // Across the edge, the law's move at its own dL, whatever the step along.
  const double across_m = p_.lateral_gain * law_.step_mm * 1e-3 * law.cf / cf_norm;
  c.step_m = {along_m * aim[0] + across_m * law.correction[0],
              along_m * aim[1] + across_m * law.correction[1]};
  last_g_hat_ = law.correction;
  last_tool_m_ = tool;
  last_t_s_ = in.t_s;
  have_last_ = true;
  last_target_m_ = {tool[0] + R[0] * c.step_m[0] + R[1] * c.step_m[1],
                    tool[1] + R[3] * c.step_m[0] + R[4] * c.step_m[1]};
  have_target_ = true;
  last_step_mm_ = step_mm;
  return c;
}

ControllerType FastFollowingControllerType() {
  using P = FastFollowingParams;
  return MakeControllerType<FastFollowingController, P>(
      "fast",
      "fast following: the law's direction aimed ahead along the turning edge, an adaptive step "
      "(longer where the edge is straight and the differential strong), taken from the arm's "
      "target instead of its lagging pose",
      {{"step_max_mm", "mm", 0.5, 30, "step on a straight edge with a strong differential",
        &P::step_max_mm},
       {"step_min_mm", "mm", 0.1, 30, "step where the edge turns hard or the signal is weak",
        &P::step_min_mm},
       {"strength_pa", "Pa", 0, 1000, "differential magnitude for the full step (0: always full)",
        &P::strength_pa},
       {"turn_slow_deg", "deg", 1, 180, "turn of the edge over one step that halves the step",
        &P::turn_slow_deg},
       {"turn_filter", "1", 0.05, 1, "weight of the newest turn measurement", &P::turn_filter},
       {"lead", "1", 0, 2, "share of the edge's predicted turn the aim leads by", &P::lead},
       {"lag_gain", "1", 0, 1, "share of the arm's lag behind its target added to the step",
        &P::lag_gain},
       {"lateral_gain", "1", 0, 3, "the move across the edge over the law's at its dL",
        &P::lateral_gain},
       {"timing", "1", 0, 1, "1: scale the step by the measured loop period; 0: fixed", &P::timing,
        true},
       {"ramp_iterations", "1", 0, 50,
        "iterations over which the step grows from step_min_mm to step_max_mm at the start",
        &P::ramp_iterations, true},
       {"tare_in_air", "1", 0, 1,
        "1: re-tare the chambers in air on the way down and subtract the offsets", &P::tare_in_air,
        true},
       {"tare_clearance_mm", "mm", 0.5, 50,
        "the air re-tare uses the readings at least this far above the hold height",
        &P::tare_clearance_mm}},
      // The adaptive step lives in [step_min_mm, step_max_mm]: a minimum above the maximum
      // would be read as the maximum without a word.
      {{&P::step_min_mm, &P::step_max_mm}});
}

}  // namespace ssc
