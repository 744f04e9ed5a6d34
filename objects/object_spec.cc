#include "objects/object_spec.h"

#include <cmath>
#include <cstdio>
#include <string_view>

#include "common/strict_number.h"
#include "objects/spec_helpers.h"

namespace ssc {

namespace spec_internal {

Point2 Polar(const Point2& centre, double r, double angle_rad) {
  return {centre[0] + r * std::cos(angle_rad), centre[1] + r * std::sin(angle_rad)};
}

std::string ValueName(const char* prefix, double value, int width) {
  char buf[64];
  if (std::fabs(value - std::round(value)) < 1e-9) {
    std::snprintf(buf, sizeof(buf), "%s%0*d", prefix, width, static_cast<int>(std::lround(value)));
  } else {
    std::snprintf(buf, sizeof(buf), "%s%0*.1f", prefix, width + 2, value);
  }
  return buf;
}

void FinishSpec(ObjectSpec* spec, double start_arc_m, double inset_m, const Point2& sweep_centre,
                double end_arc_m) {
  spec->outline = spec->edge.Vertices(2e-5);
  ObjectTrialSetup& t = spec->trial;
  const Point2 p = spec->edge.PointAt(start_arc_m), n = spec->edge.LeftNormalAt(start_arc_m);
  t.start_arc_m = start_arc_m;
  t.start_inset_m = inset_m;
  t.start_xy_m = {p[0] + inset_m * n[0], p[1] + inset_m * n[1]};
  t.landing_xy_m = t.start_xy_m;
  t.follow_direction = spec->edge.TangentAt(start_arc_m);
  t.object_on_left = true;
  t.surface_top_z_m = spec->top_z_m;
  if (spec->edge.closed()) {
    // Shoelace area of the edge: > 0 when it is walked counter-clockwise.
    double area = 0;
    const auto& q = spec->outline;
    for (size_t i = 0; i < q.size(); ++i) {
      const Point2& a = q[i];
      const Point2& b = q[(i + 1) % q.size()];
      area += a[0] * b[1] - b[0] * a[1];
    }
    t.goal = TrialGoal::SweptAngle(sweep_centre, area > 0 ? kLoopSweepDeg : -kLoopSweepDeg);
  } else {
    t.goal = TrialGoal::GoalPoint(end_arc_m);
    t.goal.start_arc_m = start_arc_m;
  }
  t.goal.band_m = kFollowBandM;
}

}  // namespace spec_internal

ConvexPiece ConvexPiece::Box(double x_min, double x_max, double y_min, double y_max) {
  ConvexPiece p;
  p.shape = Shape::kBox;
  p.centre = {0.5 * (x_min + x_max), 0.5 * (y_min + y_max)};
  p.half_x_m = 0.5 * (x_max - x_min);
  p.half_y_m = 0.5 * (y_max - y_min);
  return p;
}

ConvexPiece ConvexPiece::Cylinder(const Point2& centre, double radius_m) {
  ConvexPiece p;
  p.shape = Shape::kCylinder;
  p.centre = centre;
  p.radius_m = radius_m;
  return p;
}

ConvexPiece ConvexPiece::Prism(std::vector<Point2> polygon) {
  ConvexPiece p;
  p.shape = Shape::kPrism;
  p.polygon = std::move(polygon);
  return p;
}

ConvexPiece ConvexPiece::Hull(std::vector<std::array<double, 3>> points) {
  ConvexPiece p;
  p.shape = Shape::kHull;
  p.hull_points = std::move(points);
  return p;
}

const char* ObjectKindName(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kDisk:
      return "disk";
    case ObjectKind::kHole:
      return "hole";
    case ObjectKind::kCorner:
      return "corner";
    case ObjectKind::kVolute:
      return "volute";
    case ObjectKind::kSemicircleStrip:
      return "semicircle_strip";
    case ObjectKind::kSemisquareStrip:
      return "semisquare_strip";
    case ObjectKind::kFillet:
      return "fillet";
  }
  return "?";
}

std::vector<ObjectSpec> AllObjects() {
  std::vector<ObjectSpec> all;
  for (int d = 2; d <= 14; d += 2) all.push_back(MakeDisk(d));
  all.push_back(MakeBenchmarkDisk());
  for (int d = 2; d <= 14; d += 2) all.push_back(MakeHole(d));
  for (int a = 15; a <= 345; a += 15) all.push_back(MakeCorner(a));
  all.push_back(MakeVolute());
  all.push_back(MakeSemicircleStrip());
  all.push_back(MakeSemisquareStrip());
  all.push_back(MakeFillet());
  return all;
}

ObjectSpec ObjectByName(const std::string& name) {
  // Parametric names first: "<prefix><number>" with nothing after the number.
  auto value = [&name](const char* prefix, double* v) {
    const std::string p = prefix;
    if (name.size() <= p.size() || name.compare(0, p.size(), p) != 0) return false;
    std::string error;
    return ParseNumber(std::string_view(name).substr(p.size()), NumberRange(), v, &error);
  };
  double v = 0;
  if (value("corner_a", &v) && v > 0 && v < 360) return MakeCorner(v);
  if (value("disk_d", &v) && v > 0 && v <= 100) return MakeDisk(v);
  if (value("hole_d", &v) && v > 0 && v <= 60) return MakeHole(v);
  if (name == "disk_r35") return MakeBenchmarkDisk();
  if (name == "volute") return MakeVolute();
  if (name == "semicircle_strip") return MakeSemicircleStrip();
  if (name == "semisquare_strip") return MakeSemisquareStrip();
  if (name == "fillet") return MakeFillet();
  return ObjectSpec{};
}

}  // namespace ssc
