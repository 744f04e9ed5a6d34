// Fast following's pure logic: the adaptive step's bounds and trends, the turn measurement, and
// steps taken from the arm's target.
#include "controller/fast_following.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "controller/controller_registry.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(AdaptiveStepTest, StaysWithinItsBoundsAndShrinksWithTurnAndWeakSignal) {
  FastFollowingParams p;
  p.step_max_mm = 10;
  p.step_min_mm = 4;
  p.strength_pa = 50;
  p.turn_slow_deg = 30;
  p.timing = 0;
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 500, 0, 1), 10);  // straight, strong: the longest
  // A turn of turn_slow over a step halves it; a sharper one takes it to the floor.
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 500, 30 * kPi / 180, 1), 5);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 500, -30 * kPi / 180, 1), 5);  // either sense
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 500, kPi, 1), 4);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 30, 0, 1), 6);  // weak: in proportion
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, 1), 4);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, -5, 0, 1), 4);
  for (double s : {0.0, 10.0, 60.0, 1e6})
    for (double turn : {0.0, 0.1, 1.0, 3.0}) {
      const double step = AdaptiveStepMm(p, s, turn, 1);
      EXPECT_GE(step, p.step_min_mm);
      EXPECT_LE(step, p.step_max_mm);
    }
}

TEST(AdaptiveStepTest, FollowsTheMeasuredPeriodWithinHalfAndTwice) {
  FastFollowingParams p;
  p.step_max_mm = 10;
  p.strength_pa = 0;
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, 1.5), 15);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, 0.1), 5);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, 9), 20);
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, std::nan("")), 10);
  p.timing = 0;
  EXPECT_DOUBLE_EQ(AdaptiveStepMm(p, 0, 0, 1.5), 10);
}

TEST(SignedAngleTest, CounterClockwiseIsPositive) {
  EXPECT_NEAR(SignedAngle({1, 0}, {0, 1}), kPi / 2, 1e-12);
  EXPECT_NEAR(SignedAngle({0, 1}, {1, 0}), -kPi / 2, 1e-12);
  EXPECT_NEAR(SignedAngle({1, 0}, {-1, 0}), kPi, 1e-12);
  EXPECT_EQ(SignedAngle({0, 0}, {1, 0}), 0);
}

// The four chambers of a cup on an edge whose object lies toward `toward` (tool frame, unit):
// each chamber reads more the further its centre lies toward the object.
std::array<double, 4> Straddling(std::array<double, 2> toward, double covered, double open) {
  std::array<double, 4> p{};
  const double s = std::sqrt(0.5);
  const std::array<std::array<double, 2>, 4> dir = {{{s, -s}, {-s, -s}, {-s, s}, {s, s}}};
  for (int i = 0; i < 4; ++i) {
    const double along = dir[i][0] * toward[0] + dir[i][1] * toward[1];
    p[i] = 0.5 * (covered + open) + 0.5 * (covered - open) * along;
  }
  return p;
}

ControllerInput At(double t, double x, double y, std::array<double, 4> p) {
  ControllerInput in;
  in.t_s = t;
  in.tool_m = {x, y, 0.01};
  in.p_pa = p;
  return in;
}

TEST(FastFollowingTest, OnAStraightEdgeTheStepIsTheLawsDirectionAtTheLongestStep) {
  ControllerContext context;
  FastFollowingParams p;
  p.step_max_mm = 8;
  p.lag_gain = 0;
  FastFollowingController c(context, p);
  const std::array<double, 4> pressures = Straddling({0, 1}, 200, 10);
  const ControllerCommand cmd = c.Step(At(0, 0, 0, pressures));
  const ContourStep law = ComputeContourStep(pressures, context.law);
  ASSERT_TRUE(law.moving);
  const double along = cmd.step_m[0] * law.along_edge[0] + cmd.step_m[1] * law.along_edge[1];
  EXPECT_NEAR(along, 8e-3 / std::sqrt(1 + law.cf * law.cf), 1e-12);
  EXPECT_EQ(cmd.height_offset_m, 0.0);
}

TEST(FastFollowingTest, TheArmsLagAlongTheEdgeIsAddedSoTheTargetAdvancesByTheStep) {
  ControllerContext context;
  FastFollowingParams p;
  p.step_max_mm = p.step_min_mm = 8;
  p.strength_pa = 0;
  p.timing = 0;
  const std::array<double, 4> pressures = Straddling({0, 1}, 200, 10);
  FastFollowingController lagging(context, p);
  const ControllerCommand first = lagging.Step(At(0, 0, 0, pressures));
  // The arm covered only half of the first step by the next iteration.
  const ControllerCommand second =
      lagging.Step(At(0.15, 0.5 * first.step_m[0], 0.5 * first.step_m[1], pressures));
  const double first_len = std::hypot(first.step_m[0], first.step_m[1]);
  const double second_len = std::hypot(second.step_m[0], second.step_m[1]);
  EXPECT_NEAR(second_len, 1.5 * first_len, 0.05 * first_len);
  p.lag_gain = 0;
  FastFollowingController fixed(context, p);
  fixed.Step(At(0, 0, 0, pressures));
  const ControllerCommand no_lag =
      fixed.Step(At(0.15, 0.5 * first.step_m[0], 0.5 * first.step_m[1], pressures));
  EXPECT_NEAR(std::hypot(no_lag.step_m[0], no_lag.step_m[1]), first_len, 1e-12);
}

TEST(FastFollowingTest, AnEdgeThatTurnsIsMeasuredAndSlowsTheStep) {
  ControllerContext context;
  FastFollowingParams p;
  p.step_max_mm = 8;
  p.step_min_mm = 2;
  p.strength_pa = 0;
  p.turn_slow_deg = 10;
  p.turn_filter = 1;
  p.lag_gain = 0;
  p.timing = 0;
  FastFollowingController c(context, p);
  // The object's direction turns by 0.2 rad per 5 mm travelled: 40 rad/m.
  c.Step(At(0, 0, 0, Straddling({0, 1}, 200, 10)));
  c.Step(At(0.15, 0.005, 0, Straddling({-std::sin(0.2), std::cos(0.2)}, 200, 10)));
  // The differential points toward the object: it turned by 0.2 rad (in the tool frame's
  // sense) over the 5 mm travelled; a turn of 18 deg over a step of 8 mm (turn_slow 10 deg)
  // takes the step to 8 / (1 + 1.83) mm.
  EXPECT_NEAR(std::fabs(c.turn_per_m()), 40, 1e-6);
  EXPECT_NEAR(c.last_step_mm(), 8 / (1 + 0.32 * 180 / kPi / 10), 1e-9);
}

TEST(RampStepTest, GrowsFromTheShortestToTheLongestStepOverTheRamp) {
  FastFollowingParams p;
  p.step_min_mm = 4;
  p.step_max_mm = 10;
  p.ramp_iterations = 3;
  EXPECT_DOUBLE_EQ(RampStepMm(p, 0), 4);
  EXPECT_DOUBLE_EQ(RampStepMm(p, 1), 6);
  EXPECT_DOUBLE_EQ(RampStepMm(p, 2), 8);
  EXPECT_DOUBLE_EQ(RampStepMm(p, 3), 10);
  EXPECT_DOUBLE_EQ(RampStepMm(p, 30), 10);
  p.ramp_iterations = 0;  // off
  EXPECT_DOUBLE_EQ(RampStepMm(p, 0), 10);
}

TEST(FastFollowingTest, TheFirstStepIsTheRampsShortestAndTheAimLeadsIntoTheTurn) {
  ControllerContext context;
  FastFollowingParams p;
  p.step_max_mm = 10;
  p.step_min_mm = 4;
  p.strength_pa = 0;
  p.lag_gain = 0;
  p.timing = 0;
  p.ramp_iterations = 5;
  FastFollowingController ramped(context, p);
  ramped.Step(At(0, 0, 0, Straddling({0, 1}, 200, 10)));
  EXPECT_DOUBLE_EQ(ramped.last_step_mm(), 4);
  // Lead: once the edge is measured turning, the step's along-edge part turns the same way
  // by half the turn over the step's length.
  p.ramp_iterations = 0;
  p.turn_filter = 1;
  p.turn_slow_deg = 180;
  p.lateral_gain = 0;
  p.lead = 1;
  FastFollowingController leading(context, p);
  leading.Step(At(0, 0, 0, Straddling({0, 1}, 200, 10)));
  const std::array<double, 4> turned = Straddling({-std::sin(0.2), std::cos(0.2)}, 200, 10);
  const ControllerCommand cmd = leading.Step(At(0.15, 0.005, 0, turned));
  const ContourStep law = ComputeContourStep(turned, context.law);
  const double angle = SignedAngle(law.along_edge, cmd.step_m);
  const double along_m = std::hypot(cmd.step_m[0], cmd.step_m[1]);
  EXPECT_NEAR(angle, leading.turn_per_m() * 0.5 * along_m, 1e-9);
  EXPECT_GT(std::fabs(angle), 0.01);
}

TEST(FastFollowingTest, TheAirTareRemovesTheChambersOffsetsFromEveryReading) {
  ControllerContext context;
  FastFollowingParams p;
  p.tare_in_air = 1;
  p.tare_clearance_mm = 4;
  FastFollowingController tared(context, p);
  ASSERT_TRUE(tared.ObservesBeforeFollowing());
  const std::array<double, 4> offsets = {8, -6, 3, -2};
  // On the way down: two readings high in the air, one near the object (left out).
  for (double z : {0.020, 0.016, 0.011}) {
    ControllerInput air = At(0, 0, 0, offsets);
    air.tool_m[2] = z;
    if (z < 0.012) air.p_pa = {20, 10, 15, 12};
    tared.ObserveBeforeFollowing(air);
  }
  const std::array<double, 4> edge = Straddling({std::sin(0.3), std::cos(0.3)}, 60, 5);
  std::array<double, 4> read = edge;
  for (std::size_t k = 0; k < 4; ++k) read[k] += offsets[k];
  ControllerInput in = At(0, 0, 0, read);
  in.hold_z_m = 0.008;  // the readings from 12 mm up count
  const ControllerCommand cmd = tared.Step(in);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(tared.tare_offsets_pa()[k], offsets[k]);
  p.tare_in_air = 0;
  FastFollowingController ideal(context, p);
  EXPECT_FALSE(ideal.ObservesBeforeFollowing());
  const ControllerCommand truth = ideal.Step(At(0, 0, 0, edge));
  EXPECT_NEAR(cmd.step_m[0], truth.step_m[0], 1e-12);
  EXPECT_NEAR(cmd.step_m[1], truth.step_m[1], 1e-12);
  FastFollowingController untared(context, p);
  const ControllerCommand raw = untared.Step(At(0, 0, 0, read));
  EXPECT_GT(std::hypot(raw.step_m[0] - truth.step_m[0], raw.step_m[1] - truth.step_m[1]), 1e-4);
}

TEST(FastFollowingTest, InTheDeadBandItHolds) {
  ControllerContext context;
  FastFollowingController c(context, FastFollowingParams{});
  const ControllerCommand cmd = c.Step(At(0, 0, 0, {3, 3, 3, 3}));
  EXPECT_EQ(cmd.step_m[0], 0.0);
  EXPECT_EQ(cmd.step_m[1], 0.0);
}

TEST(FastFollowingTest, AShortestStepAboveTheLongestIsRefusedNamingBoth) {
  ControllerChoice choice;
  std::string error;
  // The default longest step is 7.5 mm: a shortest step of 9 mm alone cannot hold.
  EXPECT_FALSE(ParseControllerChoice("fast", "step_min_mm=9", &choice, &error));
  EXPECT_NE(error.find("step_min_mm = 9 exceeds step_max_mm = 7.5"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(ParseControllerChoice("fast", "step_max_mm=4", &choice, &error));
  EXPECT_NE(error.find("step_max_mm = 4"), std::string::npos) << error;
  ASSERT_TRUE(ParseControllerChoice("fast", "step_min_mm=9,step_max_mm=10", &choice, &error))
      << error;
  ASSERT_TRUE(ParseControllerChoice("fast", "step_min_mm=10,step_max_mm=10", &choice, &error))
      << error;
  EXPECT_TRUE(choice.Validate().empty());
}

}  // namespace
}  // namespace ssc
