// The compound shapes: the volute and the two strips edged with decreasing features.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "objects/object_spec.h"
#include "objects/spec_helpers.h"

namespace ssc {

using spec_internal::FinishSpec;
using spec_internal::kMm;
using spec_internal::kPi;
using spec_internal::Polar;
using spec_internal::W;

namespace {

// Volute: r = r0 + (r1 - r0) theta / 2 pi about W over one turn, closed by the straight step
// from r1 back to r0 at theta = 0 (a concave corner at its foot).
constexpr double kVoluteR0M = 25 * kMm, kVoluteR1M = 60 * kMm;
constexpr int kVoluteWedges = 16;          // 22.5 deg each
constexpr int kVoluteChordsPerWedge = 12;  // 1.9 deg chords: within 0.01 mm of the spiral
constexpr double kVoluteCoreM = 20 * kMm;  // central cylinder; wedges start inside it
constexpr double kVoluteInnerM = 18 * kMm;

// Strips: a 30 mm-wide bar whose north edge carries features of decreasing size, walked from
// its east end (at W) westward with the bar on the left.
constexpr double kFeatureSizesMm[] = {44, 28, 18, 11, 7};
constexpr double kStripGapM = 4 * kMm;       // flat edge between features
constexpr double kStripLeadInM = 14 * kMm;   // flat edge before the first feature
constexpr double kStripLeadOutM = 10 * kMm;  // and after the last
constexpr double kStripWidthM = 30 * kMm;
constexpr double kStripStartM = 7 * kMm;      // start: this far along the lead-in
constexpr double kStripEndMarginM = 5 * kMm;  // success: this far before the end of the edge

ObjectSpec Strip(const std::string& name, ObjectKind kind, bool semicircles) {
  ObjectSpec s;
  s.name = name;
  s.kind = kind;
  const double y0 = W()[1];
  double x = W()[0] - kStripLeadInM;  // east foot of the next feature
  std::vector<PathPiece> edge = {PathPiece::Segment(W(), {x, y0})};
  for (double d_mm : kFeatureSizesMm) {
    const double d = d_mm * kMm, r = 0.5 * d;
    if (semicircles) {
      // A whole cylinder: its southern half lies inside the bar, so the union is the semicircle.
      edge.push_back(PathPiece::Arc({x - r, y0}, r, 0, kPi));
      s.pieces.push_back(ConvexPiece::Cylinder({x - r, y0}, r));
    } else {  // a square of side d cut in half: d wide, d/2 tall
      const double h = 0.5 * d;
      edge.push_back(PathPiece::Segment({x, y0}, {x, y0 + h}));
      edge.push_back(PathPiece::Segment({x, y0 + h}, {x - d, y0 + h}));
      edge.push_back(PathPiece::Segment({x - d, y0 + h}, {x - d, y0}));
      s.pieces.push_back(ConvexPiece::Box(x - d, x, y0 - kSeamOverlapM, y0 + h));
    }
    x -= d;
    const bool last = d_mm == kFeatureSizesMm[std::size(kFeatureSizesMm) - 1];
    const double flat = last ? kStripLeadOutM : kStripGapM;
    edge.push_back(PathPiece::Segment({x, y0}, {x - flat, y0}));
    x -= flat;
  }
  s.pieces.push_back(ConvexPiece::Box(x, W()[0], y0 - kStripWidthM, y0));
  s.edge = ContourPath(std::move(edge), false);
  FinishSpec(&s, kStripStartM, kStartInsetM, W(), s.edge.Length() - kStripEndMarginM);
  char desc[320];
  std::snprintf(desc, sizeof(desc),
                "strip %.0f x %.0f mm (10 mm tall) whose north edge carries %s 44, 28, 18, 11 "
                "and 7 mm, 4 mm apart (edge %.1f mm long, from its east end at W westward); "
                "one box plus one %s per feature",
                (W()[0] - x) / kMm, kStripWidthM / kMm,
                semicircles ? "semicircles of diameter" : "half-squares (d wide, d/2 tall) of side",
                s.edge.Length() / kMm, semicircles ? "cylinder" : "box");
  s.description = desc;
  return s;
}

}  // namespace

ObjectSpec MakeVolute() {
  ObjectSpec s;
  s.name = "volute";
  s.kind = ObjectKind::kVolute;
  const double k = (kVoluteR1M - kVoluteR0M) / (2 * kPi);
  auto radius = [&](double th) { return kVoluteR0M + k * th; };
  s.edge = ContourPath({PathPiece::Spiral(W(), kVoluteR0M, k, 0, 2 * kPi),
                        PathPiece::Segment(Polar(W(), kVoluteR1M, 0), Polar(W(), kVoluteR0M, 0))},
                       true);
  s.pieces.push_back(ConvexPiece::Cylinder(W(), kVoluteCoreM));
  // Annular wedges: an inner chord inside the core, the spiral outside (convex: the spiral bulges
  // outward). Each wedge reaches back over its clockwise neighbour's seam; the first one may do
  // so below theta = 0 (there the spiral's extension lies inside the last wedge), but the last
  // one stops at 2 pi, where the step is.
  const double wedge = 2 * kPi / kVoluteWedges, grow = kSeamOverlapM / kVoluteInnerM;
  for (int i = 0; i < kVoluteWedges; ++i) {
    const double a0 = wedge * i - grow, a1 = wedge * (i + 1);
    std::vector<Point2> poly = {Polar(W(), kVoluteInnerM, a0), Polar(W(), kVoluteInnerM, a1)};
    for (int c = kVoluteChordsPerWedge; c >= 0; --c) {
      const double th = a0 + (a1 - a0) * c / kVoluteChordsPerWedge;
      poly.push_back(Polar(W(), radius(th), th));
    }
    s.pieces.push_back(ConvexPiece::Prism(std::move(poly)));
  }
  // Start on the west side in the middle of a wedge, counter-clockwise.
  const double th_start = kPi + 0.5 * wedge;
  const Point2 p = Polar(W(), radius(th_start), th_start);
  FinishSpec(&s, s.edge.ArcPosition(p[0], p[1]), kStartInsetM, W(), 0);
  char desc[320];
  std::snprintf(desc, sizeof(desc),
                "volute: spiral r = 25 + 35 theta / 2 pi mm about W over one turn, closed by a "
                "straight 35 mm inward step at theta = 0 (%.0f x %.0f mm, 10 mm tall): a 20 mm "
                "core cylinder and %d convex wedges; start %.0f mm inside its west side, "
                "counter-clockwise",
                (kVoluteR1M + radius(kPi)) / kMm, (radius(0.5 * kPi) + radius(1.5 * kPi)) / kMm,
                kVoluteWedges, kStartInsetM / kMm);
  s.description = desc;
  return s;
}

ObjectSpec MakeSemicircleStrip() {
  return Strip("semicircle_strip", ObjectKind::kSemicircleStrip, true);
}

ObjectSpec MakeSemisquareStrip() {
  return Strip("semisquare_strip", ObjectKind::kSemisquareStrip, false);
}

}  // namespace ssc
