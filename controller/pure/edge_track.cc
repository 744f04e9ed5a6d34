#include "controller/pure/edge_track.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

using V2 = std::array<double, 2>;

// Below this |curvature x arc length| the arc is a line to double precision.
constexpr double kStraight = 1e-7;

V2 Left(const V2& v) { return {-v[1], v[0]}; }
double Dot(const V2& a, const V2& b) { return a[0] * b[0] + a[1] * b[1]; }
double Cross(const V2& a, const V2& b) { return a[0] * b[1] - a[1] * b[0]; }
V2 Sub(const V2& a, const V2& b) { return {a[0] - b[0], a[1] - b[1]}; }
bool Finite(const V2& v) { return std::isfinite(v[0]) && std::isfinite(v[1]); }

// Solves the n x n system a x = b (n <= 3) by elimination with partial pivoting; false when
// singular relative to the matrix's scale.
template <std::size_t N>
bool Solve(std::array<std::array<double, N>, N> a, std::array<double, N> b,
           std::array<double, N>* x) {
  double scale = 0;
  for (const auto& row : a)
    for (double v : row) scale = std::max(scale, std::fabs(v));
  if (!(scale > 0)) return false;
  for (std::size_t c = 0; c < N; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < N; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    if (std::fabs(a[pivot][c]) < 1e-12 * scale) return false;
    std::swap(a[c], a[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < N; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < N; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = N; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < N; ++k) s -= a[c][k] * (*x)[k];
    (*x)[c] = s / a[c][c];
  }
  return true;
}

// The least-squares line y = m x + n through local points; false when they share one x.
bool FitLine(const V2* local, std::size_t n, double* m, double* c) {
  std::array<std::array<double, 2>, 2> a{};
  std::array<double, 2> b{}, x{};
  for (std::size_t i = 0; i < n; ++i) {
    const double u[2] = {local[i][0], 1};
    for (std::size_t r = 0; r < 2; ++r) {
      for (std::size_t k = 0; k < 2; ++k) a[r][k] += u[r] * u[k];
      b[r] += u[r] * local[i][1];
    }
  }
  if (!Solve<2>(a, b, &x)) return false;
  *m = x[0];
  *c = x[1];
  return true;
}

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

V2 EdgeArc::PointAt(double s_mm) const {
  const double k = curvature_per_mm, ks = k * s_mm;
  // sin(ks)/k and (1 - cos(ks))/k, by their series where ks vanishes.
  const double along = std::fabs(ks) < kStraight ? s_mm : std::sin(ks) / k;
  const double across = std::fabs(ks) < kStraight ? 0.5 * k * s_mm * s_mm : (1 - std::cos(ks)) / k;
  const V2 n = Left(tangent);
  return {point_mm[0] + along * tangent[0] + across * n[0],
          point_mm[1] + along * tangent[1] + across * n[1]};
}

V2 EdgeArc::TangentAt(double s_mm) const {
  const double a = curvature_per_mm * s_mm, c = std::cos(a), s = std::sin(a);
  return {c * tangent[0] - s * tangent[1], s * tangent[0] + c * tangent[1]};
}

double EdgeArc::Project(const V2& q_mm) const {
  const V2 d = Sub(q_mm, point_mm);
  const double k = curvature_per_mm;
  if (std::fabs(k) * std::hypot(d[0], d[1]) < kStraight) return Dot(d, tangent);
  const V2 n = Left(tangent);
  const V2 centre = {point_mm[0] + n[0] / k, point_mm[1] + n[1] / k};
  const V2 a = Sub(point_mm, centre), b = Sub(q_mm, centre);
  return std::atan2(Cross(a, b), Dot(a, b)) / k;
}

bool FitEdgeArc(const V2* points_mm, std::size_t n, double min_radius_mm, EdgeArc* arc,
                bool circle_allowed) {
  if (n < 3 || !(min_radius_mm > 0)) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (!Finite(points_mm[i])) return false;
  const V2 origin = points_mm[n - 1];
  const V2 chord = Sub(origin, points_mm[0]);
  const double span = std::hypot(chord[0], chord[1]);
  if (!(span >= 1.0)) return false;
  // A local frame: x along the chord from the oldest to the newest point, y to its left.
  const V2 ux = {chord[0] / span, chord[1] / span}, uy = Left(ux);
  std::array<V2, EdgeTrackController::kMaxFitPoints> local{};
  n = std::min(n, local.size());
  const V2* pts = points_mm + 0;
  for (std::size_t i = 0; i < n; ++i) {
    const V2 d = Sub(pts[i], origin);
    local[i] = {Dot(d, ux), Dot(d, uy)};
  }
  // A circle with its centre off the chord: y = k (x^2 + y^2) + m x + c, linear in (k, m, c),
  // with k = 1 / (2 y_centre); a line is k = 0.
  std::array<std::array<double, 3>, 3> a{};
  std::array<double, 3> b{}, x{};
  for (std::size_t i = 0; i < n; ++i) {
    const double u[3] = {local[i][0] * local[i][0] + local[i][1] * local[i][1], local[i][0], 1};
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t k = 0; k < 3; ++k) a[r][k] += u[r] * u[k];
      b[r] += u[r] * local[i][1];
    }
  }
  V2 p_local{}, t_local{};
  double curvature = 0;
  const bool circle = circle_allowed && Solve<3>(a, b, &x) && std::fabs(x[0]) * span > kStraight;
  double radius_sq = 0;
  V2 centre{};
  if (circle) {
    const double yc = 0.5 / x[0], xc = -x[1] * yc;
    centre = {xc, yc};
    radius_sq = xc * xc + yc * yc - 2 * yc * x[2];
  }
  if (circle && radius_sq > 0) {
    const double radius = std::sqrt(radius_sq);
    // The sense of travel round the centre: the sum of the turns between successive points.
    double turn = 0;
    for (std::size_t i = 0; i + 1 < n; ++i)
      turn += Cross(Sub(local[i], centre), Sub(local[i + 1], centre));
    const double sense = turn >= 0 ? 1 : -1;
    const V2 r = Sub(V2{0, 0}, centre);
    const double rn = std::hypot(r[0], r[1]);
    if (!(rn > 0)) return false;
    const V2 radial = {r[0] / rn, r[1] / rn};
    p_local = {centre[0] + radius * radial[0], centre[1] + radius * radial[1]};
    t_local = {-sense * radial[1], sense * radial[0]};
    curvature = sense / std::max(radius, min_radius_mm);
  } else {
    double m = 0, c = 0;
    if (!FitLine(local.data(), n, &m, &c)) return false;
    const double norm = std::hypot(1.0, m);
    t_local = {1 / norm, m / norm};
    // The foot of the perpendicular from the newest point (the origin) on the line.
    p_local = {-c * m / (norm * norm), c / (norm * norm)};
  }
  EdgeArc out;
  out.point_mm = {origin[0] + p_local[0] * ux[0] + p_local[1] * uy[0],
                  origin[1] + p_local[0] * ux[1] + p_local[1] * uy[1]};
  out.tangent = {t_local[0] * ux[0] + t_local[1] * uy[0], t_local[0] * ux[1] + t_local[1] * uy[1]};
  out.curvature_per_mm = curvature;
  if (!Finite(out.point_mm) || !Finite(out.tangent) || !std::isfinite(curvature)) return false;
  *arc = out;
  return true;
}

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
