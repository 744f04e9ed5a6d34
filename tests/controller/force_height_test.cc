// Force-regulated height as pure logic: the force loop's step response against a spring
// contact, its bounds, and the controller's planar step (the law's).
#include "controller/force_height.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

// A contact of stiffness k_n_per_mm whose surface lies `surface_mm` below the hold height
// (negative: above it): the force the F/T reads with the tool at `offset_m`.
double SpringForce(double offset_m, double surface_mm, double k_n_per_mm) {
  return std::fmax(0.0, k_n_per_mm * (-surface_mm - offset_m * 1e3));
}

TEST(ForceHeightTest, TheLoopSettlesOnTheTargetWithoutOvershootAfterTheSurfaceFallsAway) {
  ForceHeightParams p;   // 1.5 N, 0.3 mm/N
  const double k = 2.0;  // N/mm: gain x k = 0.6 < 1
  double offset = 0;
  // At the hold height the lip pressed 1.5 N; the surface then drops 0.5 mm (a rounding).
  const double surface_mm = 0.5 - 1.5 / k;
  double previous_error = p.force_n - SpringForce(offset, surface_mm, k);
  ASSERT_GT(previous_error, 0);
  for (int i = 0; i < 12; ++i) {
    offset = NextHeightOffsetM(p, offset, SpringForce(offset, surface_mm, k));
    const double error = p.force_n - SpringForce(offset, surface_mm, k);
    EXPECT_GE(error, -1e-12) << i;                  // never pressing harder than asked
    EXPECT_LT(error, previous_error + 1e-12) << i;  // always closer
    previous_error = error;
  }
  EXPECT_NEAR(SpringForce(offset, surface_mm, k), p.force_n, 0.01);
  EXPECT_NEAR(offset, -0.5e-3, 0.01e-3);  // went down by the drop
}

TEST(ForceHeightTest, TheHeightStaysWithinItsBoundsAndHoldsWithoutAReading) {
  ForceHeightParams p;
  p.max_down_mm = 1;
  p.max_up_mm = 2;
  double offset = 0;
  for (int i = 0; i < 100; ++i) offset = NextHeightOffsetM(p, offset, 0);  // in the air
  EXPECT_DOUBLE_EQ(offset, -1e-3);
  for (int i = 0; i < 100; ++i) offset = NextHeightOffsetM(p, offset, 50);  // pressed hard
  EXPECT_DOUBLE_EQ(offset, 2e-3);
  EXPECT_DOUBLE_EQ(NextHeightOffsetM(p, 0.5e-3, std::nan("")), 0.5e-3);
}

TEST(ForceHeightTest, ThePlanarStepIsThePublishedLaws) {
  ControllerContext context;
  ForceHeightController c(context, ForceHeightParams{});
  ControllerInput in;
  in.p_pa = {200, 180, 20, 30};
  in.ft_normal_n = 1.0;
  const ControllerCommand cmd = c.Step(in);
  EXPECT_EQ(cmd.step_m, ComputeContourStep(in.p_pa, context.law).step_m);
  EXPECT_NEAR(cmd.height_offset_m, -0.3e-3 * 0.5, 1e-15);  // 0.5 N short: 0.15 mm down
}

}  // namespace
}  // namespace ssc
