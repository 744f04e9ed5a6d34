// The primitive geometries: disks, holes in a plate, corners between two straight edges.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/dimensions.h"
#include "objects/object_spec.h"
#include "objects/spec_helpers.h"

namespace ssc {

using spec_internal::FinishSpec;
using spec_internal::kMm;
using spec_internal::kPi;
using spec_internal::Polar;
using spec_internal::ValueName;
using spec_internal::W;

namespace {

constexpr double kPlateHalfM = 50 * kMm;      // hole plate: 100 x 100 mm
constexpr double kHoleRingM = 6 * kMm;        // wedges reach this far beyond the hole's radius
constexpr double kHoleSagittaM = 0.03 * kMm;  // largest chord-to-circle gap of the hole polygon
constexpr double kCornerEdgeM = 60 * kMm;     // both straight edges of a corner
constexpr double kCornerReachM = 70 * kMm;    // radius of the corner's round back
constexpr double kCornerStartM = 40 * kMm;    // start: this far before the apex on edge 1
// Success: the cup follows edge 2 for one body diameter past the apex.
constexpr double kCornerPastM = kCupBodyDiameterMm * kMm;

ObjectSpec Disk(const std::string& name, double diameter_mm) {
  ObjectSpec s;
  const double r = 0.5 * diameter_mm * kMm;
  s.name = name;
  s.kind = ObjectKind::kDisk;
  s.param = diameter_mm;
  s.edge = ContourPath({PathPiece::Arc(W(), r, 0, 2 * kPi)}, true);  // ccw: disk on the left
  s.pieces.push_back(ConvexPiece::Cylinder(W(), r));
  // East side, inside by the inset (a disk smaller than that: the cup starts over its centre).
  FinishSpec(&s, 0, std::min(kStartInsetM, r), W(), 0);
  s.trial.goal = TrialGoal::AroundDisk(W(), r);
  char desc[160];
  std::snprintf(desc, sizeof(desc),
                "disk of diameter %.4g mm, 10 mm tall: one cylinder; start %.1f mm inside its "
                "east edge, counter-clockwise",
                diameter_mm, std::min(kStartInsetM, r) / kMm);
  s.description = desc;
  return s;
}

// Point where the ray from W at angle a leaves the square of half size `half` about W.
Point2 OnSquare(double half, double a) {
  return Polar(W(), half / std::max(std::fabs(std::cos(a)), std::fabs(std::sin(a))), a);
}

}  // namespace

ObjectSpec MakeDisk(double diameter_mm) {
  return Disk(ValueName("disk_d", diameter_mm, 2), diameter_mm);
}

ObjectSpec MakeBenchmarkDisk() { return Disk("disk_r35", 2 * kBenchmarkDiskRadiusM * 1e3); }

ObjectSpec MakeHole(double diameter_mm) {
  ObjectSpec s;
  const double r = 0.5 * diameter_mm * kMm, ring = r + kHoleRingM;
  s.name = ValueName("hole_d", diameter_mm, 2);
  s.kind = ObjectKind::kHole;
  s.param = diameter_mm;
  s.edge = ContourPath({PathPiece::Arc(W(), r, 0, -2 * kPi)}, true);  // cw: plate on the left
  // The hole is a regular n-gon whose chords straddle the circle (vertices outside, chord
  // middles inside by the same amount); n is a multiple of 4 with that gap within the sagitta
  // bound. Turned half a wedge so that no seam lies on the axes, where trials start.
  const double half_angle = std::acos(1 - 2 * kHoleSagittaM / r);
  const int n = std::max(12, 4 * static_cast<int>(std::ceil(kPi / half_angle / 4)));
  const double phi = kPi / n, rv = 2 * r / (1 + std::cos(phi));
  const double grow = kSeamOverlapM / rv;  // neighbours overlap from the hole's vertices out
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * phi * (i + 0.5), a1 = a0 + 2 * phi;
    std::vector<Point2> poly = {Polar(W(), rv, a0), Polar(W(), rv, a1), OnSquare(ring, a1 + grow)};
    // Square corners inside the (grown) wedge, walked back from a1 to a0.
    for (int k = 7; k >= 0; --k) {
      double c = kPi / 4 + k * kPi / 2;
      while (c > a1 + grow) c -= 2 * kPi;
      while (c < a0 - grow) c += 2 * kPi;
      if (c < a1 + grow && c > a0 - grow) poly.push_back(OnSquare(ring, c));
    }
    poly.push_back(OnSquare(ring, a0 - grow));
    s.pieces.push_back(ConvexPiece::Prism(std::move(poly)));
  }
  // The rest of the plate: four boxes round the ring's square (primitives are cheap).
  const double x = W()[0], y = W()[1], h = kPlateHalfM, in = ring - kSeamOverlapM;
  s.pieces.push_back(ConvexPiece::Box(x - h, x + h, y + in, y + h));
  s.pieces.push_back(ConvexPiece::Box(x - h, x + h, y - h, y - in));
  s.pieces.push_back(ConvexPiece::Box(x + in, x + h, y - ring, y + ring));
  s.pieces.push_back(ConvexPiece::Box(x - h, x - in, y - ring, y + ring));
  FinishSpec(&s, 0, kStartInsetM, W(), 0);  // east side of the hole, on the plate
  char desc[240];
  std::snprintf(desc, sizeof(desc),
                "round through-hole of diameter %.4g mm in a 100 x 100 x 10 mm plate: %d convex "
                "wedges round the hole out to a %.0f mm square, four boxes beyond; start %.0f mm "
                "outside its east edge, clockwise",
                diameter_mm, n, 2 * ring / kMm, kStartInsetM / kMm);
  s.description = desc;
  return s;
}

ObjectSpec MakeCorner(double alpha_deg) {
  ObjectSpec s;
  s.name = ValueName("corner_a", alpha_deg, 3);
  s.kind = ObjectKind::kCorner;
  s.param = alpha_deg;
  const double alpha = std::clamp(alpha_deg, 0.1, 359.9) * kPi / 180;
  // Edge 1 comes from the west along y = W.y to the apex W; edge 2 leaves it at angle pi - alpha.
  // The object is the sector of directions [pi - alpha, pi] round the apex (on the left).
  const double a_out = kPi - alpha, a_in = kPi;
  s.edge = ContourPath({PathPiece::Segment(Polar(W(), kCornerEdgeM, a_in), W()),
                        PathPiece::Segment(W(), Polar(W(), kCornerEdgeM, a_out))},
                       false);
  auto sector = [](double a0, double a1) {
    std::vector<Point2> p = {W()};
    const int arc = std::max(1, static_cast<int>(std::ceil((a1 - a0) / (kPi / 12))));
    for (int i = 0; i <= arc; ++i) p.push_back(Polar(W(), kCornerReachM, a0 + (a1 - a0) * i / arc));
    return p;
  };
  if (alpha <= kPi) {
    s.pieces.push_back(ConvexPiece::Prism(sector(a_out, a_in)));
  } else {  // concave: two convex halves overlapping along the bisector
    const double mid = 0.5 * (a_out + a_in), grow = kSeamOverlapM / kCornerReachM;
    s.pieces.push_back(ConvexPiece::Prism(sector(a_out, mid + grow)));
    s.pieces.push_back(ConvexPiece::Prism(sector(mid - grow, a_in)));
  }
  FinishSpec(&s, kCornerEdgeM - kCornerStartM, kStartInsetM, W(), kCornerEdgeM + kCornerPastM);
  char desc[240];
  std::snprintf(desc, sizeof(desc),
                "%s corner of %.4g deg between two 60 mm straight edges (apex at W), a sector of "
                "radius 70 mm (%zu convex prism%s); start %.0f mm before the apex, %.0f mm inside",
                alpha_deg < 180 ? "convex" : (alpha_deg > 180 ? "concave" : "straight (180 deg)"),
                alpha_deg, s.pieces.size(), s.pieces.size() > 1 ? "s" : "", kCornerStartM / kMm,
                kStartInsetM / kMm);
  s.description = desc;
  return s;
}

}  // namespace ssc
