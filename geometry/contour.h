// Planar contours of test objects: polylines in world x/y (metres) with distance and arc-length
// queries. Pure C++.
#ifndef SSC_GEOMETRY_CONTOUR_H_
#define SSC_GEOMETRY_CONTOUR_H_

#include <array>
#include <vector>

#include "geometry/point2.h"

namespace ssc {

struct Polyline {
  std::vector<Point2> points;
  bool closed = false;

  double Length() const;
  // Unsigned distance from (x, y) to the polyline, m.
  double Distance(double x, double y) const;
  // Arc-length position of the closest point on the polyline, m from the first point.
  double ArcPosition(double x, double y) const;
  // Arc position of the closest point whose arc position lies in [s_min, s_max] (a tracked
  // position that cannot jump to another, nearby part of the contour).
  double ArcPositionIn(double x, double y, double s_min, double s_max) const;
  // Point at arc length s (clamped; wraps for closed polylines).
  Point2 PointAt(double s) const;
  // Unit tangent at arc length s.
  Point2 TangentAt(double s) const;
};

}  // namespace ssc

#endif  // SSC_GEOMETRY_CONTOUR_H_
