// The project's one contour type: a chain of straight segments, circular arcs and Archimedean
// spiral arcs, open or closed; a test object's exact edge is walked so that the object lies on
// the LEFT, and a polyline (a logged path, say) is a chain of segments (ContourPath::Polygon).
// Queries: length, point and tangent at an arc position, the arc position of the closest point
// ("where along the edge"), and the signed distance to the edge. Pure C++, world metres.
#ifndef SSC_GEOMETRY_CONTOUR_PATH_H_
#define SSC_GEOMETRY_CONTOUR_PATH_H_

#include <array>
#include <vector>

#include "geometry/point2.h"

namespace ssc {

// One piece of a contour. A polar piece is r(theta) = r0_m + dr_drad * (theta - theta0_rad)
// about `centre`, theta running from theta0_rad over sweep_rad (> 0 counter-clockwise):
// dr_drad = 0 is a circular arc, otherwise an Archimedean spiral arc.
struct PathPiece {
  bool polar = false;
  Point2 a{}, b{};  // segment: from a to b
  Point2 centre{};
  double r0_m = 0, dr_drad = 0, theta0_rad = 0, sweep_rad = 0;

  static PathPiece Segment(const Point2& from, const Point2& to);
  static PathPiece Arc(const Point2& centre, double radius_m, double theta0_rad, double sweep_rad);
  static PathPiece Spiral(const Point2& centre, double r0_m, double dr_drad, double theta0_rad,
                          double sweep_rad);

  double Length() const;
  // Point and unit tangent at arc length u in [0, Length()] along the piece.
  Point2 PointAt(double u) const;
  Point2 TangentAt(double u) const;
};

// Closest point of a contour to a query point.
struct ContourProjection {
  double arc_m = 0;       // arc position of the closest point, m from the contour's start
  double distance_m = 0;  // unsigned distance to it
  Point2 point{};
};

class ContourPath {
 public:
  ContourPath() = default;
  // Pieces must join end to start (within 1 um); `closed`: the last piece ends at the first's
  // start.
  ContourPath(std::vector<PathPiece> pieces, bool closed);
  // The polyline through `points` (repeated points are skipped); `closed` joins the last point
  // to the first.
  static ContourPath Polygon(const std::vector<Point2>& points, bool closed);
  // A circle walked counter-clockwise from its east point.
  static ContourPath Circle(const Point2& centre, double radius_m);

  bool closed() const { return closed_; }
  double Length() const { return total_m_; }
  const std::vector<PathPiece>& pieces() const { return pieces_; }

  // Point, unit tangent and unit left normal (toward the object) at arc position s, m
  // (clamped to [0, Length()] on open contours, wrapped on closed ones).
  Point2 PointAt(double s) const;
  Point2 TangentAt(double s) const;
  Point2 LeftNormalAt(double s) const;

  // Closest point over the whole contour.
  ContourProjection Project(double x, double y) const;
  // Closest point among arc positions [s_min, s_max] (wrapped on closed contours): a tracked
  // position that cannot jump to another part of the contour passing close by.
  ContourProjection ProjectWithin(double x, double y, double s_min, double s_max) const;
  double ArcPosition(double x, double y) const { return Project(x, y).arc_m; }

  // Signed distance to the contour, m: negative on the object's side (left of the walking
  // direction), positive off it. Exact for points whose closest point is inside a piece; at a
  // junction the side is taken against the sum of the two pieces' left normals (correct on both
  // convex and concave corners); past the ends of an open contour the end pieces are extended
  // straight.
  double SignedDistance(double x, double y) const;

  // Vertices of a polyline with chords within `tolerance_m` of the exact curve (piece junctions
  // are vertices; a closed contour's first point is not repeated), for plots and CSV files.
  std::vector<Point2> Vertices(double tolerance_m) const;

 private:
  // Piece index and arc length within it at contour arc position s.
  void Locate(double s, int* piece, double* u) const;

  std::vector<PathPiece> pieces_;
  std::vector<double> start_m_;  // arc position where each piece starts
  double total_m_ = 0;
  bool closed_ = false;
};

}  // namespace ssc

#endif  // SSC_GEOMETRY_CONTOUR_PATH_H_
