#include "geometry/edge_arc.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/linear_solve.h"
#include "geometry/plane.h"

namespace ssc {
namespace {

using plane::Cross;
using plane::Dot;
using plane::Finite;
using plane::Left;
using plane::Sub;
using plane::V2;

// Below this |curvature x arc length| the arc is a line to double precision.
constexpr double kStraight = 1e-7;

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
  return plane::Rotated(tangent, curvature_per_mm * s_mm);
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
  std::array<V2, kEdgeArcMaxPoints> local{};
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

}  // namespace ssc
