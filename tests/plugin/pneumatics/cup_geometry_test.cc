#include "plugin/pneumatics/cup_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

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

double TotalLeak(const CupGeometry& geo, const EdgeProbe& probe) {
  const ChamberLeaks l = LeakAreas(geo, probe.wedges.data(), probe.n_wedges);
  return l.area_m2[0] + l.area_m2[1] + l.area_m2[2] + l.area_m2[3];
}

TEST(CupGeometryTest, SharpEdgeLeaksTheUncoveredCircularSegment) {
  CupGeometry geo;
  geo.rays_per_chamber = 64;  // fine sampling converges to the analytic area
  const double a = geo.opening_radius_m;
  for (double d_mm : {-4.0, -1.0, 0.5, 2.5, 4.9}) {
    const double d = d_mm * 1e-3;
    const EdgeProbe probe = ProbeStraightEdge(geo, d, 0.3);
    // Uncovered segment beyond the chord at distance d from the centre, and the roughness leak
    // of the lip (counted all round: over the open side it is a rounding error).
    const double segment = a * a * std::acos(d / a) - d * std::sqrt(a * a - d * d);
    const double lying = 2 * kPi * a * geo.lip_roughness_gap_m;
    EXPECT_NEAR(TotalLeak(geo, probe), segment + lying, 0.01 * segment + 1e-8)
        << "offset " << d_mm << " mm";
  }
}

TEST(CupGeometryTest, APlateSealsEveryChamber) {
  const CupGeometry geo;
  const EdgeProbe probe = ProbeFlatPlate(geo, 0.0);
  const ChamberLeaks l = LeakAreas(geo, probe.wedges.data(), probe.n_wedges);
  const double lip_per_chamber = 0.5 * kPi * geo.opening_radius_m * geo.lip_roughness_gap_m;
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(l.area_m2[c], lip_per_chamber, 1e-12) << "chamber " << c;
    EXPECT_NEAR(l.sealed_area_m2[c], geo.ChamberOpeningArea(), 1e-12);
    EXPECT_EQ(l.jet_area_m2[c], 0.0);
  }
}

TEST(CupGeometryTest, HoveringLipLeaksItsCurtainUntilTheOpeningLimits) {
  const CupGeometry geo;
  const double r = geo.opening_radius_m;
  for (double g_mm : {0.1, 0.5, 1.0, 2.0}) {
    const double g = g_mm * 1e-3;
    const double curtain = 2 * kPi * r * (g + geo.lip_roughness_gap_m);
    EXPECT_NEAR(TotalLeak(geo, ProbeFlatPlate(geo, g)), curtain, 1e-3 * curtain) << g_mm << " mm";
  }
  // Far from any surface the whole opening is open.
  EXPECT_NEAR(TotalLeak(geo, ProbeFlatPlate(geo, 20e-3)),
              kPi * r * r + 2 * kPi * r * geo.lip_roughness_gap_m, 1e-12);
}

TEST(CupGeometryTest, LeakOverASlopedPlateGrowsWithTheSlope) {
  const CupGeometry geo;
  double previous = TotalLeak(geo, ProbeSlopedPlate(geo, 0.0, 0.4));
  for (double slope : {0.02, 0.05, 0.1, 0.2, 0.4, 0.8}) {
    const double leak = TotalLeak(geo, ProbeSlopedPlate(geo, slope, 0.4));
    EXPECT_GT(leak, previous * 1.2) << "slope " << slope;
    previous = leak;
  }
}

TEST(CupGeometryTest, NoDistanceThresholdDecidesTheLeak) {
  // Moving a rounded edge across the cup in 0.05 mm steps changes the leak smoothly.
  const CupGeometry geo;
  double previous = TotalLeak(geo, ProbeRoundedEdge(geo, 6e-3, kPi, 8e-3));
  for (double d_mm = 5.95; d_mm >= -6.0; d_mm -= 0.05) {
    const double leak = TotalLeak(geo, ProbeRoundedEdge(geo, d_mm * 1e-3, kPi, 8e-3));
    EXPECT_GE(leak, previous - 1e-15) << d_mm;
    EXPECT_LT(leak - previous, 1.5e-6) << "jump at offset " << d_mm << " mm";
    previous = leak;
  }
}

TEST(CupGeometryTest, ValidateRejectsBadValues) {
  CupGeometry g;
  g.rays_per_chamber = 0;
  EXPECT_NE(g.Validate().find("rays_per_chamber"), std::string::npos);
  g = CupGeometry{};
  g.open_depth_m = -1e-3;
  EXPECT_NE(g.Validate().find("open_depth"), std::string::npos);
}

}  // namespace
}  // namespace ssc
