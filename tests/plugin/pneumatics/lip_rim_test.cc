// The lip rim's pure geometry: which rim points frame each wedge, which skirt vertices form the
// rim, and the pressure load on a skirt triangle.
#include "plugin/pneumatics/lip_rim.h"

#include <gtest/gtest.h>

#include <cmath>

#include "plugin/pneumatics/cup_geometry.h"

namespace ssc {
namespace {

TEST(LipRimTest, EachWedgeLiesBetweenItsTwoRimPoints) {
  // 16 points in the middle of 16 equal arcs; 4 wedges per chamber.
  std::vector<double> angles;
  for (int i = 0; i < 16; ++i)
    angles.push_back(std::remainder(2 * M_PI * (i + 0.5) / 16, 2 * M_PI));
  const std::vector<WedgeRim> rims = AssignWedgeRims(angles, 4);
  ASSERT_EQ(rims.size(), 16u);
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < 4; ++j) {
      const WedgeRim& rim = rims[c * 4 + j];
      const double a = RayAngle(c, j, 4);
      const double before = std::remainder(a - angles[rim.point[0]], 2 * M_PI);
      const double after = std::remainder(angles[rim.point[1]] - a, 2 * M_PI);
      EXPECT_GE(before, 0.0);
      EXPECT_GT(after, 0.0);
      EXPECT_LT(before + after, 2 * M_PI / 16 + 1e-12);  // neighbours, not any two points
      EXPECT_NEAR(rim.weight1, before / (before + after), 1e-12);
    }
  }
}

TEST(LipRimTest, OnePointRimGivesEveryWedgeThatPoint) {
  const std::vector<WedgeRim> rims = AssignWedgeRims({0.3}, 2);
  for (const WedgeRim& rim : rims) {
    EXPECT_EQ(rim.point[0], 0);
    EXPECT_EQ(rim.point[1], 0);
  }
}

TEST(LipRimTest, AtWedgeInterpolates) {
  WedgeRim rim;
  rim.point[0] = 1;
  rim.point[1] = 2;
  rim.weight1 = 0.25;
  const double values[3] = {100.0, 4.0, 8.0};
  EXPECT_DOUBLE_EQ(AtWedge(rim, values), 5.0);
}

TEST(LipRimTest, RimIsTheDeepestRingWithinTolerance) {
  const std::vector<int> rim = RimVertices({-3e-3, -1.5e-3, 0.0, 0.00005, -0.0002}, 0.1e-3);
  ASSERT_EQ(rim.size(), 2u);
  EXPECT_EQ(rim[0], 2);
  EXPECT_EQ(rim[1], 3);
  EXPECT_TRUE(RimVertices({}, 1e-3).empty());
}

TEST(LipRimTest, ColumnsGatherTheVerticesAboveEachRimPointAndShareTheOnesMidway) {
  // Four rim points at 0, 90, 180, 270 deg; vertices at 10 deg, 45 deg (midway), 350 deg, 180 deg.
  const double deg = M_PI / 180;
  const std::vector<std::vector<int>> columns =
      SkirtColumns({10 * deg, 45 * deg, 350 * deg, -180 * deg}, {0, 90 * deg, M_PI, -90 * deg});
  ASSERT_EQ(columns.size(), 4u);
  EXPECT_EQ(columns[0], (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(columns[1], (std::vector<int>{1}));
  EXPECT_EQ(columns[2], (std::vector<int>{3}));
  EXPECT_TRUE(columns[3].empty());
}

TEST(LipRimTest, AColumnSealsAtItsDeepestPointAndAFlatStretchAtItsInnermost) {
  // An unfolded skirt: the rim (the outermost, deepest) seals.
  const double cone_depth[3] = {-3e-3, -1.5e-3, 0.0}, cone_radius[3] = {4e-3, 4.75e-3, 5.5e-3};
  EXPECT_EQ(ColumnSealPoint(cone_depth, cone_radius, 3, 0.1e-3), 2);
  // Folded in on itself: the crease (middle vertex) is deepest, the rim curls up inside it.
  const double crease_depth[3] = {-3e-3, 0.0, -0.8e-3}, crease_radius[3] = {4e-3, 5e-3, 3e-3};
  EXPECT_EQ(ColumnSealPoint(crease_depth, crease_radius, 3, 0.1e-3), 1);
  // A stretch lying flat on the surface from the crease in to the rim: the rim, innermost, seals.
  const double flat_depth[3] = {-3e-3, 0.0, -0.05e-3}, flat_radius[3] = {4e-3, 5e-3, 2.5e-3};
  EXPECT_EQ(ColumnSealPoint(flat_depth, flat_radius, 3, 0.1e-3), 2);
  EXPECT_EQ(ColumnSealPoint(flat_depth, flat_radius, 0, 0.1e-3), -1);
}

TEST(LipRimTest, VacuumPullsATriangleTowardTheCavityWithPressureTimesArea) {
  // A 2 mm x 2 mm right triangle (area 2e-6 m^2) in the plane x = 1 mm, cavity on the axis.
  const double p0[3] = {1e-3, 0, 0}, p1[3] = {1e-3, 2e-3, 0}, p2[3] = {1e-3, 0, 2e-3};
  const double cavity[3] = {0, 0, 0};
  const std::array<double, 3> f = TrianglePressureForce(p0, p1, p2, 500.0, cavity);
  EXPECT_NEAR(f[0], -500.0 * 2e-6, 1e-15);  // toward x = 0
  EXPECT_NEAR(f[1], 0.0, 1e-15);
  EXPECT_NEAR(f[2], 0.0, 1e-15);
  // The vertex order does not matter; no vacuum, no force; a degenerate triangle, no force.
  const std::array<double, 3> g = TrianglePressureForce(p0, p2, p1, 500.0, cavity);
  EXPECT_NEAR(g[0], f[0], 1e-15);
  EXPECT_EQ(TrianglePressureForce(p0, p1, p2, 0.0, cavity)[0], 0.0);
  EXPECT_EQ(TrianglePressureForce(p0, p0, p1, 500.0, cavity)[0], 0.0);
}

TEST(LipRimTest, TheAreaVectorFollowsTheWinding) {
  // The same triangle as above: area 2e-6 m^2 along +x for this winding, -x for the other (a
  // skirt keeps each triangle's winding however it folds, so a side fixed at rest stays put).
  const double p0[3] = {1e-3, 0, 0}, p1[3] = {1e-3, 2e-3, 0}, p2[3] = {1e-3, 0, 2e-3};
  const std::array<double, 3> a = TriangleAreaVector(p0, p1, p2);
  EXPECT_NEAR(a[0], 2e-6, 1e-18);
  EXPECT_NEAR(a[1], 0.0, 1e-18);
  EXPECT_NEAR(a[2], 0.0, 1e-18);
  EXPECT_NEAR(TriangleAreaVector(p0, p2, p1)[0], -2e-6, 1e-18);
}

TEST(LipRimTest, AFoldedRimShortensTheCurtainAndClosesTheWedgeBeyondIt) {
  // A lip hovering 0.2 mm over a plate: the curtain under the rim is the whole leak.
  CupGeometry geo;
  const EdgeProbe plate = ProbeFlatPlate(geo, 0.2e-3);
  OpeningWedge w = plate.wedges[0];
  const double on_edge = WedgeLeakArea(geo, w).area_m2;
  w.rim_radius_m = 0.5 * geo.opening_radius_m;
  const double folded = WedgeLeakArea(geo, w).area_m2;
  EXPECT_LT(folded, 0.6 * on_edge);
  w.rim_radius_m = 2.0 * geo.opening_radius_m;  // never beyond the opening's edge
  EXPECT_DOUBLE_EQ(WedgeLeakArea(geo, w).area_m2, on_edge);
}

}  // namespace
}  // namespace ssc
