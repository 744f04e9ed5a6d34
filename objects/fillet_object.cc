// The variable fillet: a bar whose straight 180 mm edge is rounded with a radius growing from 0
// (sharp) to 16 mm (objects/fillet_profile.h), built as a stack of convex slices.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "objects/object_spec.h"
#include "objects/spec_helpers.h"

namespace ssc {

using spec_internal::FinishSpec;
using spec_internal::kMm;
using spec_internal::kPi;
using spec_internal::W;

namespace {

constexpr double kBarDepthM = 60 * kMm;    // the bar reaches this far north of the edge
constexpr double kLeadInM = 30 * kMm;      // sharp bar before the edge's start (the start sees
constexpr double kRunOutM = 30 * kMm;      // a continuing edge) and 16 mm fillet after its end
constexpr double kSliceM = 10 * kMm;       // slice length along the edge
constexpr int kArcChords = 16;             // chords of the rounded edge per cross-section
constexpr double kStartAlongM = 10 * kMm;  // start on the sharp end
constexpr double kEndMarginM = 10 * kMm;   // success: this far before the end of the edge

// The bar's cross-section at x_local along the edge (y north of the edge, z up), convex: the top
// face, the rounded edge (radius r about (r, top - r)) down to the side wall or, where r exceeds
// the bar's height, down to the table, and the bottom.
void AddSection(double x_local, std::vector<std::array<double, 3>>* out) {
  const double r = FilletRadius(std::clamp(x_local, 0.0, kFilletEdgeLengthM));
  const double x = W()[0] + x_local, y0 = W()[1], top = kObjectTopZ, h = kObjectTopZ - kTableZ;
  out->push_back({x, y0 + kBarDepthM, top});
  if (r < 1e-9) {
    out->push_back({x, y0, top});
  } else {
    for (int i = 0; i <= kArcChords; ++i) {
      const double phi = 0.5 * kPi * (1.0 + static_cast<double>(i) / kArcChords);
      const double z = top - r + r * std::sin(phi);
      if (z < kTableZ) break;
      out->push_back({x, y0 + r + r * std::cos(phi), z});
    }
  }
  if (r > h) {  // the rounding meets the table before it turns vertical
    out->push_back({x, y0 + r - std::sqrt(r * r - (r - h) * (r - h)), kTableZ});
  } else {
    out->push_back({x, y0, kTableZ});
  }
  out->push_back({x, y0 + kBarDepthM, kTableZ});
}

}  // namespace

double FilletSurfaceZ(double x_m, double y_m) {
  const double x_local = x_m - W()[0], y = y_m - W()[1];
  const double r = FilletRadius(std::clamp(x_local, 0.0, kFilletEdgeLengthM));
  if (y >= r) return kObjectTopZ;
  if (y < 0) return kTableZ;
  const double z = kObjectTopZ - r + std::sqrt(r * r - (r - y) * (r - y));
  return std::max(kTableZ, z);
}

ObjectSpec MakeFillet() {
  ObjectSpec s;
  s.name = "fillet";
  s.kind = ObjectKind::kFillet;
  // The edge runs east from W; the bar lies to its north (on the left).
  s.edge = ContourPath({PathPiece::Segment(W(), {W()[0] + kFilletEdgeLengthM, W()[1]})}, false);
  // Each slice is the convex hull of the cross-sections at its two ends, so the radius varies
  // linearly within a slice and continuously from slice to slice; neighbours overlap.
  for (double xa = -kLeadInM; xa < kFilletEdgeLengthM + kRunOutM - 1e-9; xa += kSliceM) {
    std::vector<std::array<double, 3>> points;
    AddSection(xa - kSeamOverlapM, &points);
    AddSection(xa + kSliceM + kSeamOverlapM, &points);
    s.pieces.push_back(ConvexPiece::Hull(std::move(points)));
  }
  FinishSpec(&s, kStartAlongM, kStartInsetM, W(), kFilletEdgeLengthM - kEndMarginM);
  char desc[400];
  std::snprintf(desc, sizeof(desc),
                "variable fillet: a bar %.0f x %.0f x 10 mm whose straight 180 mm edge (from W "
                "eastward) is rounded with a radius growing smoothly from 0 to 16 mm (monotone "
                "cubic through 0, 4.7, 10.4, 14.5, 16.0 mm at 0, 45, 90, 135, 180 mm), with %.0f "
                "mm of sharp bar before and %.0f mm of 16 mm fillet after; %zu convex slices %.0f "
                "mm long; start %.0f mm along, %.0f mm inside",
                (kLeadInM + kFilletEdgeLengthM + kRunOutM) / kMm, kBarDepthM / kMm, kLeadInM / kMm,
                kRunOutM / kMm, s.pieces.size(), kSliceM / kMm, kStartAlongM / kMm,
                kStartInsetM / kMm);
  s.description = desc;
  return s;
}

}  // namespace ssc
