#include "plugin/pneumatics/cup_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(CupGeometryTest, ChambersFollowThePublishedLayout) {
  // Tool frame: +x south, +y west. 1 = SE, 2 = NE, 3 = NW, 4 = SW (indices 0..3).
  EXPECT_EQ(ChamberOfAngle(std::atan2(-1, 1)), 0);   // south-east
  EXPECT_EQ(ChamberOfAngle(std::atan2(-1, -1)), 1);  // north-east
  EXPECT_EQ(ChamberOfAngle(std::atan2(1, -1)), 2);   // north-west
  EXPECT_EQ(ChamberOfAngle(std::atan2(1, 1)), 3);    // south-west
  EXPECT_EQ(ChamberOfAngle(2 * kPi + 0.3), 3);       // wraps
}

TEST(CupGeometryTest, SubSectorAreaToggles) {
  const double r = 5e-3, dth = 0.1;
  EXPECT_NEAR(SubSectorCoveredArea(true, nullptr, 0, r, dth), 0.5 * dth * r * r, 1e-15);
  EXPECT_EQ(SubSectorCoveredArea(false, nullptr, 0, r, dth), 0.0);
  const double cross[2] = {2e-3, 4e-3};
  EXPECT_NEAR(SubSectorCoveredArea(false, cross, 2, r, dth), 0.5 * dth * (16e-6 - 4e-6), 1e-15);
  EXPECT_NEAR(SubSectorCoveredArea(true, cross, 2, r, dth),
              0.5 * dth * (4e-6 + 25e-6 - 16e-6), 1e-15);
  const double beyond[1] = {9e-3};  // crossing outside the opening is ignored
  EXPECT_NEAR(SubSectorCoveredArea(true, beyond, 1, r, dth), 0.5 * dth * r * r, 1e-15);
}

TEST(CupGeometryTest, StraightEdgeSealedAreaMatchesTheCircularSegment) {
  CupGeometry geo;
  geo.rays_per_chamber = 64;  // fine sampling converges to the analytic area
  const double a = geo.opening_radius_m;
  for (double d_mm : {-4.0, -1.0, 0.5, 2.5, 4.9}) {
    const double d = d_mm * 1e-3;
    const EdgeProbe probe = ProbeStraightEdge(geo, d, 0.3, 5.5e-3, 16, 0.0);
    double sealed = 0;
    for (double s : probe.sealed_area_m2) sealed += s;
    // Uncovered segment beyond the chord at distance d from the centre.
    const double segment = a * a * std::acos(d / a) - d * std::sqrt(a * a - d * d);
    EXPECT_NEAR(sealed, kPi * a * a - segment, 0.01 * kPi * a * a) << "offset " << d_mm << " mm";
  }
}

TEST(CupGeometryTest, LeakAreasAddOpeningLipGapsAndRoughness) {
  CupGeometry geo;
  std::array<double, 4> sealed;
  sealed.fill(geo.ChamberOpeningArea());
  sealed[1] = 0.5 * geo.ChamberOpeningArea();
  LipSegmentState segs[3];
  segs[0] = {0, 2e-3, true, 0.0};         // on the surface: roughness only
  segs[1] = {2, 2e-3, false, 0.2e-3};     // hovering within the seal distance
  segs[2] = {3, 2e-3, false, 5e-3};       // over air: counted by the opening, not here
  const auto leak = LeakAreas(geo, sealed, segs, 3);
  EXPECT_NEAR(leak[0], 2e-3 * geo.lip_roughness_gap_m, 1e-15);
  EXPECT_NEAR(leak[1], 0.5 * geo.ChamberOpeningArea(), 1e-15);
  EXPECT_NEAR(leak[2], 2e-3 * (0.2e-3 + geo.lip_roughness_gap_m), 1e-15);
  EXPECT_NEAR(leak[3], 0.0, 1e-15);
}

TEST(CupGeometryTest, ValidateRejectsBadValues) {
  CupGeometry g;
  g.rays_per_chamber = 0;
  EXPECT_NE(g.Validate().find("rays_per_chamber"), std::string::npos);
  g = CupGeometry{};
  g.seal_distance_m = -1e-3;
  EXPECT_NE(g.Validate().find("seal_distance"), std::string::npos);
}

}  // namespace
}  // namespace ssc
