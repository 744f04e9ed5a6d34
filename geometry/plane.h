// Vector algebra in the plane on std::array<double, 2>: the one home of the planar rotation and
// the small products the controllers and fits use. Pure C++, header-only.
#ifndef SSC_GEOMETRY_PLANE_H_
#define SSC_GEOMETRY_PLANE_H_

#include <array>
#include <cmath>

namespace ssc {
namespace plane {

using V2 = std::array<double, 2>;

// v turned a quarter counter-clockwise.
inline V2 Left(const V2& v) { return {-v[1], v[0]}; }
inline double Dot(const V2& a, const V2& b) { return a[0] * b[0] + a[1] * b[1]; }
// The z component of a x b (+: b counter-clockwise of a).
inline double Cross(const V2& a, const V2& b) { return a[0] * b[1] - a[1] * b[0]; }
inline V2 Sub(const V2& a, const V2& b) { return {a[0] - b[0], a[1] - b[1]}; }
inline bool Finite(const V2& v) { return std::isfinite(v[0]) && std::isfinite(v[1]); }
// v turned counter-clockwise by angle_rad.
inline V2 Rotated(const V2& v, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v[0] - s * v[1], s * v[0] + c * v[1]};
}

}  // namespace plane
}  // namespace ssc

#endif  // SSC_GEOMETRY_PLANE_H_
