#include "controller/edge_track.h"

#include <algorithm>
#include <cmath>

#include "geometry/plane.h"

namespace ssc {
namespace {

using plane::Dot;
using plane::Finite;
using plane::Left;
using plane::Sub;
using plane::V2;

// `fast` at start_step_mm and start_lateral_gain, whatever the differential's strength (no re-tare
// of its own: it gets the tared readings).
FastFollowingParams StartParams(const EdgeTrackParams& p) {
  FastFollowingParams f;
  f.step_max_mm = f.step_min_mm = p.start_step_mm;
  f.strength_pa = 0;
  f.lateral_gain = p.start_lateral_gain;
  return f;
}

}  // namespace

double InsetFromMeanVacuumMm(double p_mean_pa) {
  // (P-bar Pa, inset mm): medians over 0.5 mm bins of 301 control iterations of 12 edge_track
  // trials (the default scene, default effects), the inset from the disk's radius.
  static constexpr std::array<std::array<double, 2>, 12> kCurve = {{{10, -0.9},
                                                                    {20, 0.0},
                                                                    {36, 0.5},
                                                                    {46, 1.0},
                                                                    {57, 1.5},
                                                                    {71, 2.0},
                                                                    {118, 2.5},
                                                                    {190, 3.0},
                                                                    {290, 3.5},
                                                                    {700, 4.0},
                                                                    {1650, 4.5},
                                                                    {7000, 5.0}}};
  const double p = std::isfinite(p_mean_pa) ? p_mean_pa : 100.0;
  if (p <= kCurve.front()[0]) return kCurve.front()[1];
  for (std::size_t i = 1; i < kCurve.size(); ++i) {
    if (p <= kCurve[i][0]) {
      const double f = std::log(p / kCurve[i - 1][0]) / std::log(kCurve[i][0] / kCurve[i - 1][0]);
      return kCurve[i - 1][1] + f * (kCurve[i][1] - kCurve[i - 1][1]);
    }
  }
  return kCurve.back()[1];
}

EdgeTrackController::EdgeTrackController(const ControllerContext& context, const EdgeTrackParams& p)
    : context_(context),
      law_(context.law),
      period_s_(context.control_period_s),
      p_(p),
      start_(context, StartParams(p)) {}

void EdgeTrackController::ObserveBeforeFollowing(const ControllerInput& in) {
  air_tare_.Add(in.p_pa, in.tool_m[2]);
}

bool EdgeTrackController::TrackStep(const V2& tool_mm, const std::array<double, 9>& R,
                                    ControllerCommand* c) {
  const std::size_t n = std::min(count_, static_cast<std::size_t>(std::lround(p_.fit_points)));
  const V2* pts = tool_mm_.data() + (count_ - n);
  const double* insets = inset_mm_.data() + (count_ - n);
  // Fewer positions than circle_points: their scatter says nothing of the curvature.
  const bool circle = static_cast<double>(n) >= p_.circle_points;
  EdgeArc path;
  if (!FitEdgeArc(pts, n, p_.min_radius_mm, &path, circle)) return false;
  // Each position moved out across the path by its inset: a point of the edge.
  const double side = law_.side == FollowSide::kObjectOnLeft ? 1 : -1;
  std::array<V2, kMaxFitPoints> line{};
  for (std::size_t i = 0; i < n; ++i) {
    const V2 inward = Left(path.TangentAt(path.Project(pts[i])));
    line[i] = {pts[i][0] - side * insets[i] * inward[0], pts[i][1] - side * insets[i] * inward[1]};
  }
  if (!FitEdgeArc(line.data(), n, p_.min_radius_mm, &edge_, circle)) return false;
  const double s_tool = edge_.Project(tool_mm);
  const double s_from = have_goal_ ? edge_.Project(goal_mm_) : s_tool;
  const double advance_mm = p_.speed_mm_s * period_s_;
  const double s_goal = std::clamp(s_from + advance_mm, s_tool, s_tool + p_.max_lead_mm);
  // The arm covers arm_reach of the way to its goal in a period: the goal's inset is set so that
  // the cup, from its inset now, is expected at inset_mm at the next iteration.
  const V2 tool_inward = Left(edge_.TangentAt(s_tool));
  const double tool_inset_mm = side * Dot(Sub(tool_mm, edge_.PointAt(s_tool)), tool_inward);
  const double goal_inset_mm = tool_inset_mm + (p_.inset_mm - tool_inset_mm) / p_.arm_reach;
  const V2 inward = Left(edge_.TangentAt(s_goal));
  const V2 on_edge = edge_.PointAt(s_goal);
  const V2 goal = {on_edge[0] + side * goal_inset_mm * inward[0],
                   on_edge[1] + side * goal_inset_mm * inward[1]};
  V2 w = Sub(goal, tool_mm);
  // Across the edge, at most max_across_mm per step: a poor fit does not throw the cup off.
  const V2 across_dir = Left(edge_.TangentAt(s_tool));
  const double across = Dot(w, across_dir);
  const double held = std::clamp(across, -p_.max_across_mm, p_.max_across_mm);
  w = {w[0] + (held - across) * across_dir[0], w[1] + (held - across) * across_dir[1]};
  // World to tool frame: the transpose of the tool-to-world rotation.
  const V2 step_mm = {R[0] * w[0] + R[3] * w[1], R[1] * w[0] + R[4] * w[1]};
  if (!Finite(step_mm)) return false;
  const double len = std::hypot(step_mm[0], step_mm[1]);
  const double max_mm = advance_mm + p_.max_lead_mm;
  const double scale = len > max_mm ? max_mm / len : 1.0;
  c->step_m = {1e-3 * scale * step_mm[0], 1e-3 * scale * step_mm[1]};
  return true;
}

ControllerCommand EdgeTrackController::Step(const ControllerInput& in) {
  ControllerCommand c;
  if (p_.tare_in_air > 0 && !tared_) {  // the hold height is known from the first iteration on
    tare_pa_ = air_tare_.Offsets(in.hold_z_m, p_.tare_clearance_mm * 1e-3);
    tared_ = true;
  }
  ControllerInput tared = in;
  for (std::size_t k = 0; k < 4; ++k) tared.p_pa[k] -= tare_pa_[k];
  const auto& R = in.tool_rotation;
  bool finite = std::isfinite(in.tool_m[0]) && std::isfinite(in.tool_m[1]);
  for (double v : tared.p_pa) finite = finite && std::isfinite(v);
  for (double v : R) finite = finite && std::isfinite(v);
  if (!finite) {  // nothing to steer by: hold, and start the fit afresh
    count_ = 0;
    have_goal_ = tracking_ = false;
    return c;
  }
  const ContourStep law = ComputeContourStep(tared.p_pa, law_);
  const V2 tool_mm = {1e3 * in.tool_m[0], 1e3 * in.tool_m[1]};
  const std::size_t capacity = std::clamp(static_cast<std::size_t>(std::lround(p_.fit_points)),
                                          std::size_t{3}, kMaxFitPoints);
  if (count_ == capacity) {
    std::copy(tool_mm_.begin() + 1, tool_mm_.begin() + capacity, tool_mm_.begin());
    std::copy(inset_mm_.begin() + 1, inset_mm_.begin() + capacity, inset_mm_.begin());
    --count_;
  }
  const double inset_mm = InsetFromMeanVacuumMm(law.p_mean_pa);
  if (tracking_ && p_.restart_mm > 0) {
    // The reading disagrees with the fit where the tool now is: a corner the fit could not see
    // coming. Start afresh from here, by the pressure direction.
    const double s = edge_.Project(tool_mm);
    const double side = law_.side == FollowSide::kObjectOnLeft ? 1 : -1;
    const double fit_inset_mm =
        side * Dot(Sub(tool_mm, edge_.PointAt(s)), Left(edge_.TangentAt(s)));
    if (std::fabs(inset_mm - fit_inset_mm) > p_.restart_mm) {
      count_ = 0;
      start_from_ = in.iteration;
      start_ = FastFollowingController(context_, StartParams(p_));
    }
  }
  tool_mm_[count_] = tool_mm;
  inset_mm_[count_] = inset_mm;
  ++count_;
  tracking_ = static_cast<double>(in.iteration - start_from_) >= p_.start_iterations &&
              TrackStep(tool_mm, R, &c);
  if (!tracking_) c = start_.Step(tared);
  // Where this command sends the tool (world, mm): the next target advances from here.
  goal_mm_ = {tool_mm[0] + 1e3 * (R[0] * c.step_m[0] + R[1] * c.step_m[1]),
              tool_mm[1] + 1e3 * (R[3] * c.step_m[0] + R[4] * c.step_m[1])};
  have_goal_ = c.step_m[0] != 0 || c.step_m[1] != 0;
  return c;
}

ControllerType EdgeTrackControllerType() {
  using P = EdgeTrackParams;
  return MakeControllerType<EdgeTrackController, P>(
      "edge_track",
      "edge tracking: the edge fitted to the tool's past positions, each moved out by its inset "
      "read from the mean vacuum; absolute targets advanced along the fit, so landing misses "
      "do not add up (starts as `fast`)",
      {{"speed_mm_s", "mm/s", 1, 200,
        "the target's advance along the edge (this times the nominal period per iteration)",
        &P::speed_mm_s},
       {"inset_mm", "mm", -2, 6, "the target's inset of the cup centre inside the edge",
        &P::inset_mm},
       {"fit_points", "1", 3, 16, "the last positions in the edge fit", &P::fit_points, true},
       {"start_iterations", "1", 0, 50, "iterations run by `fast` before the fit takes over",
        &P::start_iterations, true},
       {"start_step_mm", "mm", 0.5, 30, "`fast`'s step over those iterations", &P::start_step_mm},
       {"start_lateral_gain", "1", 0, 3, "`fast`'s lateral_gain over those iterations",
        &P::start_lateral_gain},
       {"max_lead_mm", "mm", 0, 50, "the target's lead along the edge ahead of the tool, at most",
        &P::max_lead_mm},
       {"arm_reach", "1", 0.2, 1,
        "the share of the way to its goal the arm covers in one control period", &P::arm_reach},
       {"restart_mm", "mm", 0, 20,
        "a reading this far from the fit's inset restarts from `fast` (a corner; 0: never)",
        &P::restart_mm},
       {"circle_points", "1", 3, 16,
        "positions needed before the fit may curve (fewer: a straight line)", &P::circle_points,
        true},
       {"max_across_mm", "mm", 0.1, 20, "the step across the fitted edge, at most",
        &P::max_across_mm},
       {"min_radius_mm", "mm", 0.5, 1000, "the fitted edge turns no tighter than this",
        &P::min_radius_mm},
       {"tare_in_air", "1", 0, 1,
        "1: re-tare the chambers in air on the way down and subtract the offsets", &P::tare_in_air,
        true},
       {"tare_clearance_mm", "mm", 0.5, 50,
        "the air re-tare uses the readings at least this far above the hold height",
        &P::tare_clearance_mm}},
      // More positions to curve than the fit holds would leave the fit a line without a word.
      {{&P::circle_points, &P::fit_points}});
}

}  // namespace ssc
