#include "objects/object_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMm = 1e-3;
constexpr double kStartInset = 2.5 * kMm;  // cup centre inside the edge at the start (P ~ 100 Pa)
constexpr double kSeamOverlap = 0.1 * kMm;  // adjacent convex pieces overlap this much

Point2 W() { return {kWorkspaceX, kWorkspaceY}; }
Point2 Polar(const Point2& c, double r, double a) {
  return {c[0] + r * std::cos(a), c[1] + r * std::sin(a)};
}

std::string Name(const char* prefix, double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s%02d", prefix, static_cast<int>(std::lround(v)));
  return buf;
}

// Circular sector (convex for a span <= pi) as a polygon, counter-clockwise.
std::vector<Point2> Sector(const Point2& apex, double radius, double a0, double a1) {
  std::vector<Point2> p = {apex};
  const int n = std::max(2, static_cast<int>(std::ceil((a1 - a0) / (kPi / 12))) + 1);
  for (int i = 0; i < n; ++i) p.push_back(Polar(apex, radius, a0 + (a1 - a0) * i / (n - 1)));
  return p;
}

ConvexPiece Prism(std::vector<Point2> polygon) {
  ConvexPiece piece;
  piece.polygon = std::move(polygon);
  return piece;
}

// Monotone cubic (Fritsch-Carlson) through (x_i, y_i).
double MonotoneCubic(const std::vector<double>& x, const std::vector<double>& y, double t) {
  const size_t n = x.size();
  if (t <= x.front()) return y.front();
  if (t >= x.back()) return y.back();
  std::vector<double> d(n - 1), m(n);
  for (size_t i = 0; i + 1 < n; ++i) d[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  m[0] = d[0];
  m[n - 1] = d[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) m[i] = (d[i - 1] * d[i] <= 0) ? 0 : 0.5 * (d[i - 1] + d[i]);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (d[i] == 0) {
      m[i] = m[i + 1] = 0;
      continue;
    }
    const double a = m[i] / d[i], b = m[i + 1] / d[i], s = a * a + b * b;
    if (s > 9) {
      const double tau = 3 / std::sqrt(s);
      m[i] = tau * a * d[i];
      m[i + 1] = tau * b * d[i];
    }
  }
  size_t k = 0;
  while (k + 2 < n && t > x[k + 1]) ++k;
  const double h = x[k + 1] - x[k], u = (t - x[k]) / h;
  const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
  const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
  return h00 * y[k] + h10 * h * m[k] + h01 * y[k + 1] + h11 * h * m[k + 1];
}

// Strip with features along its north edge, walked from east to west (object to the south,
// on the left). `feature` adds one feature's contour (east foot to west foot) and pieces.
ObjectSpec Strip(const char* name, ObjectKind kind, bool semicircles) {
  ObjectSpec s;
  s.name = name;
  s.kind = kind;
  const double sizes_mm[] = {40, 28, 20, 14, 10, 7, 5};
  const double gap = 6 * kMm, lead = 25 * kMm, width = 40 * kMm;
  const double east = kWorkspaceX + 80 * kMm;
  double x = east;  // east foot of the next feature
  std::vector<Point2>& c = s.contour.points;
  c.push_back({east + lead, kWorkspaceY});
  for (double d_mm : sizes_mm) {
    const double d = d_mm * kMm, r = 0.5 * d;
    const double cx = x - r;
    if (semicircles) {
      std::vector<Point2> half;
      const int n = 24;
      for (int i = 0; i <= n; ++i) half.push_back(Polar({cx, kWorkspaceY}, r, kPi * i / n));
      for (const Point2& p : half) c.push_back(p);
      s.pieces.push_back(Prism(half));  // counter-clockwise from the east foot: convex
    } else {
      const double h = r;  // a square of side d cut in half: d wide, d/2 tall
      const std::vector<Point2> box = {{x, kWorkspaceY}, {x, kWorkspaceY + h},
                                       {x - d, kWorkspaceY + h}, {x - d, kWorkspaceY}};
      for (const Point2& p : box) c.push_back(p);
      s.pieces.push_back(Prism({{x - d, kWorkspaceY}, {x, kWorkspaceY}, {x, kWorkspaceY + h},
                                {x - d, kWorkspaceY + h}}));
    }
    x -= d + gap;
  }
  const double west = x + gap - lead;
  c.push_back({west, kWorkspaceY});
  s.contour.closed = false;
  // The strip body itself.
  s.pieces.push_back(Prism({{west - 5 * kMm, kWorkspaceY - width},
                            {east + lead + 5 * kMm, kWorkspaceY - width},
                            {east + lead + 5 * kMm, kWorkspaceY},
                            {west - 5 * kMm, kWorkspaceY}}));
  s.start = {east + 12 * kMm, kWorkspaceY - kStartInset};
  s.end_arc_m = s.contour.Length() - 10 * kMm;
  char desc[256];
  std::snprintf(desc, sizeof(desc),
                "strip %.0f x %.0f mm with %s of 40, 28, 20, 14, 10, 7, 5 mm along its north "
                "edge (6 mm apart), followed east to west",
                (east + lead - west) / kMm, width / kMm,
                semicircles ? "semicircles of diameter" : "half-squares (d wide, d/2 tall) of side");
  s.description = desc;
  return s;
}

}  // namespace

const char* ObjectKindName(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kDisk: return "disk";
    case ObjectKind::kHole: return "hole";
    case ObjectKind::kCorner: return "corner";
    case ObjectKind::kVolute: return "volute";
    case ObjectKind::kSemicircleStrip: return "semicircle_strip";
    case ObjectKind::kSemisquareStrip: return "semisquare_strip";
    case ObjectKind::kFillet: return "fillet";
  }
  return "?";
}

ObjectSpec MakeDisk(double diameter_mm) {
  ObjectSpec s;
  const double r = 0.5 * diameter_mm * kMm;
  s.name = diameter_mm > 60 ? "disk_r35" : Name("disk_d", diameter_mm);
  s.kind = ObjectKind::kDisk;
  s.param = diameter_mm;
  const int n = 360;
  for (int i = 0; i < n; ++i) s.contour.points.push_back(Polar(W(), r, 2 * kPi * i / n));
  s.contour.closed = true;  // counter-clockwise: the disk on the left
  ConvexPiece cyl;
  cyl.cylinder = true;
  cyl.centre = W();
  cyl.radius_m = r;
  s.pieces.push_back(cyl);
  s.start = Polar(W(), std::max(0.0, r - kStartInset), 0.0);
  s.sweep_centre = W();
  s.success_sweep_deg = 355;
  char desc[128];
  std::snprintf(desc, sizeof(desc), "disk, diameter %.0f mm, 50 mm tall", diameter_mm);
  s.description = desc;
  return s;
}

ObjectSpec MakeHole(double diameter_mm) {
  ObjectSpec s;
  const double r = 0.5 * diameter_mm * kMm, half = 50 * kMm;
  s.name = Name("hole_d", diameter_mm);
  s.kind = ObjectKind::kHole;
  s.param = diameter_mm;
  // 48 wedges of 7.5 deg, turned by half a wedge so that no seam lies on the axes the trial
  // starts on; a wedge that spans a corner of the square keeps the corner (still convex).
  const int n = 48;
  for (int i = 0; i < 360; ++i) s.contour.points.push_back(Polar(W(), r, -2 * kPi * i / 360));
  s.contour.closed = true;  // clockwise: the plate on the left
  auto outer = [&](double a) {
    const double t = half / std::max(std::fabs(std::cos(a)), std::fabs(std::sin(a)));
    return Polar(W(), t, a);
  };
  for (int i = 0; i < n; ++i) {
    const double grow = kSeamOverlap / r;  // angular overlap with the neighbours
    const double a0 = 2 * kPi * (i + 0.5) / n - grow, a1 = 2 * kPi * (i + 1.5) / n + grow;
    std::vector<Point2> poly = {Polar(W(), r, a0), outer(a0)};
    for (int k = 0; k < 8; ++k) {  // square corners at 45 + 90 k deg
      double corner = kPi / 4 + k * kPi / 2;
      if (corner > a0 && corner < a1) poly.push_back({W()[0] + (std::cos(corner) > 0 ? half : -half),
                                                      W()[1] + (std::sin(corner) > 0 ? half : -half)});
    }
    poly.push_back(outer(a1));
    poly.push_back(Polar(W(), r, a1));
    s.pieces.push_back(Prism(poly));
  }
  s.start = Polar(W(), r + kStartInset, 0.0);
  s.sweep_centre = W();
  s.success_sweep_deg = -355;  // clockwise
  char desc[160];
  std::snprintf(desc, sizeof(desc),
                "round through-hole of diameter %.0f mm in a 100 x 100 mm plate (48 convex "
                "wedges), 50 mm of air below",
                diameter_mm);
  s.description = desc;
  return s;
}

ObjectSpec MakeCorner(double alpha_deg) {
  ObjectSpec s;
  char name[32];
  std::snprintf(name, sizeof(name), "corner_a%03d", static_cast<int>(std::lround(alpha_deg)));
  s.name = name;
  s.kind = ObjectKind::kCorner;
  s.param = alpha_deg;
  const double alpha = alpha_deg * kPi / 180, edge = 60 * kMm, reach = 70 * kMm;
  // Edge 1 comes from the west along y = 0 to the apex W; edge 2 leaves at angle pi - alpha.
  // The object is the wedge of directions [pi - alpha, pi] at the apex.
  const double a_in = kPi, a_out = kPi - alpha;
  s.contour.points = {Polar(W(), edge, a_in), W(), Polar(W(), edge, a_out)};
  s.contour.closed = false;
  if (alpha <= kPi + 1e-9) {
    s.pieces.push_back(Prism(Sector(W(), reach, a_out, a_in)));
  } else {  // concave: two convex halves
    const double mid = 0.5 * (a_out + a_in);
    s.pieces.push_back(Prism(Sector(W(), reach, a_out, mid)));
    s.pieces.push_back(Prism(Sector(W(), reach, mid, a_in)));
  }
  s.start = {kWorkspaceX - 40 * kMm, kWorkspaceY + kStartInset};
  s.end_arc_m = edge + 30 * kMm;  // 30 mm past the apex along edge 2
  char desc[160];
  std::snprintf(desc, sizeof(desc),
                "corner of %.0f deg (%s) between two 60 mm straight edges, apex at W", alpha_deg,
                alpha_deg < 180 ? "convex" : (alpha_deg > 180 ? "concave" : "straight"));
  s.description = desc;
  return s;
}

ObjectSpec MakeVolute() {
  ObjectSpec s;
  s.name = "volute";
  s.kind = ObjectKind::kVolute;
  const double r0 = 25 * kMm, r1 = 60 * kMm;
  auto radius = [&](double th) { return r0 + (r1 - r0) * th / (2 * kPi); };
  const int n = 48;  // 7.5 deg wedges: chords within 0.13 mm of the spiral
  for (int i = 0; i <= n; ++i) {
    const double th = 2 * kPi * i / n;
    s.contour.points.push_back(Polar(W(), radius(th), th));
  }
  s.contour.closed = true;  // the straight inward step closes it (r1 -> r0 at angle 0)
  for (int i = 0; i < n; ++i) {
    const double grow = kSeamOverlap / r0;
    const double a = 2 * kPi * i / n - (i > 0 ? grow : 0), b = 2 * kPi * (i + 1) / n + (i + 1 < n ? grow : 0);
    s.pieces.push_back(Prism({W(), Polar(W(), radius(a), a), Polar(W(), radius(b), b)}));
  }
  const double a_start = kPi + kPi / n;  // mid-wedge, off the seams
  s.start = Polar(W(), radius(a_start) - kStartInset, a_start);
  s.sweep_centre = W();
  s.success_sweep_deg = 355;
  s.description =
      "volute: spiral r = 25 + 35 theta / (2 pi) mm over one turn (50 to 120 mm across), closed "
      "by a straight 35 mm inward step; 144 convex wedges";
  return s;
}

ObjectSpec MakeSemicircleStrip() {
  return Strip("semicircle_strip", ObjectKind::kSemicircleStrip, true);
}
ObjectSpec MakeSemisquareStrip() {
  return Strip("semisquare_strip", ObjectKind::kSemisquareStrip, false);
}

double FilletRadius(double x_m) {
  static const std::vector<double> x = {0, 0.045, 0.090, 0.135, 0.180};
  static const std::vector<double> r = {0, 4.7e-3, 10.4e-3, 14.5e-3, 16.0e-3};
  return MonotoneCubic(x, r, x_m);
}

ObjectSpec MakeFillet() {
  ObjectSpec s;
  s.name = "fillet";
  s.kind = ObjectKind::kFillet;
  const double length = 180 * kMm, depth = 60 * kMm;
  // The edge runs east along y = W.y from W; the bar lies to the north (on the left).
  s.contour.points = {W(), {kWorkspaceX + length, kWorkspaceY}};
  s.contour.closed = false;
  // Convex slices along the edge: each is the hull of the bar's cross-section (a rectangle with
  // its edge rounded by the local fillet radius: convex) at both slice ends, so the radius varies
  // linearly within a slice and continuously from slice to slice. Primitives and meshes, unlike a
  // height field, keep rays cheap (a height field's ray test walks its grid).
  auto section = [&](double x_local, std::vector<std::array<double, 3>>* out) {
    const double r = FilletRadius(std::clamp(x_local, 0.0, length));
    const double x = kWorkspaceX + x_local, y0 = kWorkspaceY;
    out->push_back({x, y0 + depth, kObjectTopZ});
    const int arc = 10;
    for (int i = 0; i <= arc; ++i) {
      const double phi = 0.5 * kPi + 0.5 * kPi * i / arc;  // from the top face to the side wall
      out->push_back({x, y0 + r + r * std::cos(phi), kObjectTopZ - r + r * std::sin(phi)});
    }
    out->push_back({x, y0, kObjectBottomZ});
    out->push_back({x, y0 + depth, kObjectBottomZ});
  };
  const double slice = 10 * kMm, x_begin = -30 * kMm, x_end = length + 30 * kMm;
  for (double xa = x_begin; xa < x_end - 1e-9; xa += slice) {
    ConvexPiece piece;
    // Neighbours overlap by 0.1 mm: a ray down an exact seam between two hulls can slip through.
    section(xa - kSeamOverlap, &piece.hull_points);
    section(std::min(x_end, xa + slice + kSeamOverlap), &piece.hull_points);
    s.pieces.push_back(std::move(piece));
  }
  s.start = {kWorkspaceX + 10 * kMm, kWorkspaceY + kStartInset};
  s.end_arc_m = length - 10 * kMm;
  s.description =
      "straight 180 mm edge of a bar (top at z = 10 mm, 50 mm tall) whose fillet radius grows "
      "smoothly from 0 to 16 mm (monotone cubic through 0, 4.7, 10.4, 14.5, 16.0 mm at 0, 45, 90, "
      "135, 180 mm); 24 convex slices 10 mm long (hull of the cross-sections at both ends)";
  return s;
}

std::vector<ObjectSpec> AllObjects() {
  std::vector<ObjectSpec> all;
  for (int d = 2; d <= 14; d += 2) all.push_back(MakeDisk(d));
  all.push_back(MakeDisk(70));
  for (int d = 2; d <= 14; d += 2) all.push_back(MakeHole(d));
  for (int a = 15; a <= 345; a += 15) all.push_back(MakeCorner(a));
  all.push_back(MakeVolute());
  all.push_back(MakeSemicircleStrip());
  all.push_back(MakeSemisquareStrip());
  all.push_back(MakeFillet());
  return all;
}

ObjectSpec ObjectByName(const std::string& name) {
  int angle = 0;
  if (std::sscanf(name.c_str(), "corner_a%d", &angle) == 1 && angle > 0 && angle < 360) {
    return MakeCorner(angle);
  }
  for (const ObjectSpec& s : AllObjects()) {
    if (s.name == name) return s;
  }
  return ObjectSpec{};
}

}  // namespace ssc
