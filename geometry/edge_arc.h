// A piece of an edge fitted to points along it: a circle, or a line when straight (the edge
// tracking controller's estimate of the edge from the tool's own positions). Pure C++, mm.
#ifndef SSC_GEOMETRY_EDGE_ARC_H_
#define SSC_GEOMETRY_EDGE_ARC_H_

#include <cstddef>

#include "geometry/point2.h"

namespace ssc {

// The most points FitEdgeArc uses (the newest when given more).
inline constexpr std::size_t kEdgeArcMaxPoints = 16;

// A piece of edge near the tool: a point on it, the unit tangent there in the sense of travel
// and the signed curvature (+: turning counter-clockwise seen from above), world, mm.
struct EdgeArc {
  Point2 point_mm{};
  Point2 tangent{1, 0};
  double curvature_per_mm = 0;
  // The point at arc length s_mm from point_mm (negative: behind), and the tangent there.
  Point2 PointAt(double s_mm) const;
  Point2 TangentAt(double s_mm) const;
  // The arc length of the point of the edge nearest q (on a circle: within half a turn).
  double Project(const Point2& q_mm) const;
};

// The circle (or line) through points_mm[0..n) in the least-squares sense, the oldest first:
// the tangent in the sense from the oldest toward the newest, the point the newest one's
// projection. False when fewer than 3 points, the points span less than 1 mm, or a value is not
// finite. The curvature is clamped to 1 / min_radius_mm; without circle_allowed, a line.
bool FitEdgeArc(const Point2* points_mm, std::size_t n, double min_radius_mm, EdgeArc* arc,
                bool circle_allowed = true);

}  // namespace ssc

#endif  // SSC_GEOMETRY_EDGE_ARC_H_
