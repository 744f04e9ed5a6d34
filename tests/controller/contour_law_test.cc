#include "controller/contour_law.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

// Tool frame: north = -x, south = +x, west = +y, east = -y.
constexpr std::array<double, 2> kNorth = {-1, 0}, kSouth = {1, 0}, kWest = {0, 1}, kEast = {0, -1};

void ExpectDir(const std::array<double, 2>& v, const std::array<double, 2>& want) {
  EXPECT_NEAR(v[0], want[0], 1e-12);
  EXPECT_NEAR(v[1], want[1], 1e-12);
}

TEST(ContourLawTest, SidePressuresAndDifferentials) {
  // Chambers 1..4 = SE, NE, NW, SW.
  const ContourStep s = ComputeContourStep({10, 20, 60, 110}, ContourLawParams{});
  EXPECT_DOUBLE_EQ(s.p_south_pa, 60);  // (10 + 110) / 2
  EXPECT_DOUBLE_EQ(s.p_north_pa, 40);  // (20 + 60) / 2
  EXPECT_DOUBLE_EQ(s.p_west_pa, 85);   // (60 + 110) / 2
  EXPECT_DOUBLE_EQ(s.p_east_pa, 15);   // (10 + 20) / 2
  EXPECT_DOUBLE_EQ(s.dpx_pa, -20);
  EXPECT_DOUBLE_EQ(s.dpy_pa, 70);
  EXPECT_DOUBLE_EQ(s.p_mean_pa, 50);
  // g = dPx north + dPy west = (-dPx, dPy) in tool x/y.
  EXPECT_DOUBLE_EQ(s.g[0], 20);
  EXPECT_DOUBLE_EQ(s.g[1], 70);
}

TEST(ContourLawTest, ObjectOnTheLeftSeenFromAbove) {
  ContourLawParams p;
  p.beta = 0;  // pure tangential motion
  // Object to the west (cup on the east edge of a disk): covered chambers 3, 4 -> move north.
  ExpectDir(ComputeContourStep({0, 0, 200, 200}, p).direction, kNorth);
  // Object to the north (chambers 2, 3 covered): facing east, north is on the left.
  ExpectDir(ComputeContourStep({0, 200, 200, 0}, p).direction, kEast);
  // Object to the east (chambers 1, 2) -> move south.
  ExpectDir(ComputeContourStep({200, 200, 0, 0}, p).direction, kSouth);
  // Object to the south (chambers 1, 4) -> move west.
  ExpectDir(ComputeContourStep({200, 0, 0, 200}, p).direction, kWest);
  // The other side: object on the right reverses the travel.
  p.side = FollowSide::kObjectOnRight;
  ExpectDir(ComputeContourStep({0, 0, 200, 200}, p).direction, kSouth);
}

TEST(ContourLawTest, CorrectionFactorBoundariesAndExtrapolation) {
  ContourLawParams p;
  p.p_noise_pa = 10;
  p.p_ref_pa = 100;
  p.p_grasp_pa = 15000;
  p.beta = 2;
  EXPECT_NEAR(CorrectionFactor(10, p), 2.0, 1e-12);
  EXPECT_NEAR(CorrectionFactor(100, p), 0.0, 1e-12);
  EXPECT_NEAR(CorrectionFactor(15000, p), -2.0, 1e-12);
  EXPECT_NEAR(CorrectionFactor(std::sqrt(10.0 * 100.0), p), 1.0, 1e-12);  // half way in log
  EXPECT_NEAR(CorrectionFactor(1, p), 4.0, 1e-12);                        // extrapolated
  EXPECT_NEAR(CorrectionFactor(15000 * (15000 / 100.0), p), -4.0, 1e-9);
  EXPECT_TRUE(std::isfinite(CorrectionFactor(-5, p)));
  EXPECT_GT(CorrectionFactor(-5, p), 2.0);
}

TEST(ContourLawTest, StepCombinesTangentAndCorrection) {
  ContourLawParams p;
  p.step_mm = 5;
  // Object to the west, mean 50 Pa < P_ref: c_f > 0 steers west (toward the object).
  const ContourStep s = ComputeContourStep({0, 0, 100, 100}, p);
  ASSERT_TRUE(s.moving);
  const double cf = CorrectionFactor(50, p);
  EXPECT_NEAR(s.cf, cf, 1e-12);
  const double n = std::hypot(1.0, cf);
  EXPECT_NEAR(s.step_m[0], 5e-3 * (-1.0) / n, 1e-12);  // north component
  EXPECT_NEAR(s.step_m[1], 5e-3 * cf / n, 1e-12);      // west component
  EXPECT_NEAR(std::hypot(s.step_m[0], s.step_m[1]), 5e-3, 1e-12);
  // Object to the south (chambers 1, 4 covered), mean 50 Pa: the tangent is west and c_f > 0
  // steers south (+x): both parts of the correction carry their sign.
  const ContourStep south = ComputeContourStep({100, 0, 0, 100}, p);
  ASSERT_TRUE(south.moving);
  EXPECT_NEAR(south.step_m[0], 5e-3 * cf / n, 1e-12);   // south component
  EXPECT_NEAR(south.step_m[1], 5e-3 * 1.0 / n, 1e-12);  // west component
  // Above P_ref (mean 1000 Pa) c_f < 0 steers away from the object: north, for the object south.
  const ContourStep deep = ComputeContourStep({2000, 0, 0, 2000}, p);
  EXPECT_LT(deep.cf, 0);
  EXPECT_LT(deep.step_m[0], 0);
}

TEST(ContourLawTest, DeadBandAndZeroDifferential) {
  ContourLawParams p;
  // Differentials of exactly P_n do not move; just above do.
  EXPECT_FALSE(ComputeContourStep({0, 0, 10, 10}, p).moving);  // dPy = 10 = P_n
  EXPECT_TRUE(ComputeContourStep({0, 0, 10.5, 10.5}, p).moving);
  p.dead_band = false;
  EXPECT_TRUE(ComputeContourStep({0, 0, 1, 1}, p).moving);
  const ContourStep zero = ComputeContourStep({50, 50, 50, 50}, p);
  EXPECT_FALSE(zero.moving);
  EXPECT_EQ(zero.step_m[0], 0.0);
  EXPECT_EQ(zero.step_m[1], 0.0);
  EXPECT_TRUE(std::isfinite(zero.cf));
}

TEST(ContourLawTest, ValidateNamesTheField) {
  ContourLawParams p;
  p.p_ref_pa = 5;  // below P_n
  EXPECT_NE(p.Validate().find("pref_pa"), std::string::npos);
  p = ContourLawParams{};
  p.step_mm = 0;
  EXPECT_NE(p.Validate().find("step_mm"), std::string::npos);
  p = ContourLawParams{};
  p.beta = std::nan("");
  EXPECT_NE(p.Validate().find("beta"), std::string::npos);
  EXPECT_EQ(ContourLawParams{}.Validate(), "");
}

}  // namespace
}  // namespace ssc
