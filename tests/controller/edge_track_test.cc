// Edge tracking's pure logic: the edge fit on noisy circles and lines, the inset map, the
// absolute targets (bounded, on the fitted edge, misses not added up) and non-finite input.
#include "controller/edge_track.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "controller/controller_registry.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
using V2 = std::array<double, 2>;

// Points every step_mm of arc on a circle of radius_mm about the origin, from angle a0_rad, in
// the sense `sense` (+1 counter-clockwise), each moved across by Gaussian noise of noise_mm.
std::vector<V2> OnCircle(double radius_mm, double a0_rad, double step_mm, int n, double sense,
                         double noise_mm, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, noise_mm);
  std::vector<V2> pts;
  for (int i = 0; i < n; ++i) {
    const double a = a0_rad + sense * i * step_mm / radius_mm;
    const double r = radius_mm + (noise_mm > 0 ? noise(rng) : 0);
    pts.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return pts;
}

TEST(EdgeArcTest, PointsAndProjectionsAgreeOnCirclesAndLines) {
  for (double k : {0.0, 1 / 30.0, -1 / 12.0}) {
    EdgeArc arc;
    arc.point_mm = {3, -2};
    arc.tangent = {std::sqrt(0.5), std::sqrt(0.5)};
    arc.curvature_per_mm = k;
    for (double s : {-9.0, 0.0, 4.0, 17.0}) {
      const V2 p = arc.PointAt(s);
      EXPECT_NEAR(arc.Project(p), s, 1e-9) << "k " << k << " s " << s;
      // A point moved off the edge along its normal projects to the same arc length.
      const V2 t = arc.TangentAt(s);
      EXPECT_NEAR(std::hypot(t[0], t[1]), 1, 1e-12);
      EXPECT_NEAR(arc.Project({p[0] - 2 * t[1], p[1] + 2 * t[0]}), s, 1e-9);
    }
  }
  EdgeArc circle;  // the unit-speed parametrisation stays on the circle
  circle.point_mm = {10, 0};
  circle.tangent = {0, 1};
  circle.curvature_per_mm = 0.1;
  const V2 half = circle.PointAt(10 * kPi);
  EXPECT_NEAR(half[0], -10, 1e-9);
  EXPECT_NEAR(half[1], 0, 1e-9);
}

TEST(EdgeFitTest, FindsTheCircleItsSenseAndTheNewestPointUnderNoise) {
  const double radius = 32.5;
  for (double sense : {1.0, -1.0})
    for (unsigned seed = 1; seed <= 20; ++seed) {
      const std::vector<V2> pts = OnCircle(radius, 0.3 * seed, 8, 7, sense, 0.3, seed);
      EdgeArc arc;
      ASSERT_TRUE(FitEdgeArc(pts.data(), pts.size(), 5, &arc));
      EXPECT_NEAR(arc.curvature_per_mm, sense / radius, 0.3 / radius) << "seed " << seed;
      // The point is the newest position's projection: on the circle, near the newest angle.
      const double a = 0.3 * seed + sense * 6 * 8 / radius;
      EXPECT_NEAR(arc.point_mm[0], radius * std::cos(a), 0.8);
      EXPECT_NEAR(arc.point_mm[1], radius * std::sin(a), 0.8);
      // The tangent points in the sense of travel, within a few degrees.
      const V2 travel = {-sense * std::sin(a), sense * std::cos(a)};
      EXPECT_GT(arc.tangent[0] * travel[0] + arc.tangent[1] * travel[1], std::cos(0.12));
    }
  // Without noise, exact.
  const std::vector<V2> exact = OnCircle(radius, 1, 10, 5, 1, 0, 1);
  EdgeArc arc;
  ASSERT_TRUE(FitEdgeArc(exact.data(), exact.size(), 5, &arc));
  EXPECT_NEAR(arc.curvature_per_mm, 1 / radius, 1e-9);
}

TEST(EdgeFitTest, AStraightEdgeIsALineAndATightTurnIsClamped) {
  std::vector<V2> line;
  for (int i = 0; i < 6; ++i) line.push_back({5.0 + 7 * i, -3.0 - 7 * i});
  EdgeArc arc;
  ASSERT_TRUE(FitEdgeArc(line.data(), line.size(), 5, &arc));
  EXPECT_NEAR(arc.curvature_per_mm, 0, 1e-9);
  EXPECT_NEAR(arc.tangent[0], std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(arc.tangent[1], -std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(arc.point_mm[0], 40, 1e-9);
  const std::vector<V2> tight = OnCircle(2, 0, 1, 5, -1, 0, 1);
  ASSERT_TRUE(FitEdgeArc(tight.data(), tight.size(), 5, &arc));
  EXPECT_NEAR(arc.curvature_per_mm, -1 / 5.0, 1e-12);
}

TEST(EdgeFitTest, RefusesTooFewCoincidentOrNonFinitePoints) {
  EdgeArc arc;
  const std::vector<V2> two = {{0, 0}, {5, 0}};
  EXPECT_FALSE(FitEdgeArc(two.data(), two.size(), 5, &arc));
  const std::vector<V2> still = {{1, 1}, {1.2, 1}, {1.4, 1.1}};
  EXPECT_FALSE(FitEdgeArc(still.data(), still.size(), 5, &arc));
  std::vector<V2> bad = OnCircle(30, 0, 8, 5, 1, 0, 1);
  bad[2][1] = std::nan("");
  EXPECT_FALSE(FitEdgeArc(bad.data(), bad.size(), 5, &arc));
  bad[2][1] = INFINITY;
  EXPECT_FALSE(FitEdgeArc(bad.data(), bad.size(), 5, &arc));
}

TEST(InsetMapTest, IsMonotonicNearThePublishedPointsAndHeldBeyondItsEnds) {
  // The published static curve: 40 Pa at 0.7 mm, 100 Pa at 2.5 mm, 200 Pa at 3.2 mm inside.
  EXPECT_NEAR(InsetFromMeanVacuumMm(40), 0.7, 0.3);
  EXPECT_NEAR(InsetFromMeanVacuumMm(100), 2.5, 0.3);
  EXPECT_NEAR(InsetFromMeanVacuumMm(200), 3.2, 0.3);
  double last = -1e9;
  for (double p = 1; p < 1e5; p *= 1.1) {
    const double d = InsetFromMeanVacuumMm(p);
    EXPECT_GE(d, last) << p;
    EXPECT_TRUE(std::isfinite(d));
    last = d;
  }
  EXPECT_GT(InsetFromMeanVacuumMm(300), InsetFromMeanVacuumMm(100) + 0.5);  // it does vary
  // Below the curve's first point and above its last the inset stays put.
  EXPECT_EQ(InsetFromMeanVacuumMm(-50), InsetFromMeanVacuumMm(1));
  EXPECT_EQ(InsetFromMeanVacuumMm(1e6), InsetFromMeanVacuumMm(1e5));
  EXPECT_EQ(InsetFromMeanVacuumMm(std::nan("")), InsetFromMeanVacuumMm(100));
  EXPECT_EQ(InsetFromMeanVacuumMm(INFINITY), InsetFromMeanVacuumMm(100));
}

// The chambers of a cup whose object lies toward -y_tool, at mean vacuum p_mean_pa: SE, NE, NW,
// SW, the east chambers (-y) cover the object.
std::array<double, 4> OnEdge(double p_mean_pa) {
  return {1.6 * p_mean_pa, 1.6 * p_mean_pa, 0.4 * p_mean_pa, 0.4 * p_mean_pa};
}

ControllerInput At(std::uint64_t i, const V2& tool_mm, double p_mean_pa) {
  ControllerInput in;
  in.iteration = i;
  in.t_s = 0.15 * static_cast<double>(i);
  in.tool_m = {1e-3 * tool_mm[0], 1e-3 * tool_mm[1], 0.01};
  in.p_pa = OnEdge(p_mean_pa);
  in.tool_rotation = {1, 0, 0, 0, -1, 0, 0, 0, -1};  // the tool's z points down
  return in;
}

// A straight edge along +x world at y = 0: the object toward +y world (-y tool, on the left of
// the motion seen from above). The tool lands now 1.5 mm, now 3 mm inside (what the reading
// says), and lags its target.
TEST(EdgeTrackTest, TargetsAdvanceOnTheEdgeFromTheLastTargetSoMissesDoNotAddUp) {
  ControllerContext context;
  EdgeTrackParams p;
  p.speed_mm_s = 50;  // 7.5 mm per 0.15 s
  p.start_iterations = 3;
  p.start_step_mm = 7.5;
  p.inset_mm = 2;
  p.arm_reach = 1;
  p.tare_in_air = 0;
  EdgeTrackController c(context, p);
  double x = 0;
  V2 goal{};
  for (std::uint64_t i = 0; i < 10; ++i) {
    const double p_mean = (i % 2 == 0) ? 57 : 190;
    const double inset = InsetFromMeanVacuumMm(p_mean);
    const ControllerCommand cmd = c.Step(At(i, {x, inset}, p_mean));
    EXPECT_LE(1e3 * std::hypot(cmd.step_m[0], cmd.step_m[1]), 7.5 + p.max_lead_mm + 1e-9);
    // The rotation flips y: the world step is (x, -y) of the tool step.
    const V2 next_goal = {x + 1e3 * cmd.step_m[0], inset - 1e3 * cmd.step_m[1]};
    if (c.tracking()) {
      // inset_mm inside the edge, 7.5 mm beyond the last target, however the tool landed (the
      // path fit's normals tilt a little with the 1.5 mm zigzag).
      EXPECT_NEAR(next_goal[1], 2, 0.1) << "iteration " << i;
      EXPECT_NEAR(next_goal[0], goal[0] + 7.5, 0.05) << "iteration " << i;
      EXPECT_NEAR(c.edge().curvature_per_mm, 0, 2e-3);
      EXPECT_NEAR(c.edge().point_mm[1], 0, 0.1);
    }
    goal = next_goal;
    x += 0.6 * (goal[0] - x);  // the arm covers 60 % of the way per period
  }
  EXPECT_TRUE(c.tracking());
}

TEST(EdgeTrackTest, TheGoalMakesUpForTheArmsReachSoTheCupIsExpectedAtTheInset) {
  ControllerContext context;
  EdgeTrackParams p;
  p.start_iterations = 3;
  p.inset_mm = 2;
  p.arm_reach = 0.5;
  p.tare_in_air = 0;
  EdgeTrackController c(context, p);
  // The tool 3 mm inside a straight edge at y = 0: half way from there to a goal at 1 mm is 2.
  const double p_mean = 190;
  const double inset = InsetFromMeanVacuumMm(p_mean);
  ASSERT_NEAR(inset, 3, 1e-9);
  ControllerCommand cmd;
  for (std::uint64_t i = 0; i < 6; ++i)
    cmd = c.Step(At(i, {7.5 * static_cast<double>(i), 3}, p_mean));
  ASSERT_TRUE(c.tracking());
  EXPECT_NEAR(3 - 1e3 * cmd.step_m[1], 1, 1e-6);
  // Across the edge at most max_across_mm.
  p.inset_mm = -2;
  p.max_across_mm = 4;
  EdgeTrackController held(context, p);
  for (std::uint64_t i = 0; i < 6; ++i)
    cmd = held.Step(At(i, {7.5 * static_cast<double>(i), 3}, p_mean));
  ASSERT_TRUE(held.tracking());
  EXPECT_NEAR(1e3 * cmd.step_m[1], 4, 1e-6);  // toward -y world: outward
}

TEST(EdgeTrackTest, TheLeadAheadOfTheToolIsCapped) {
  ControllerContext context;
  EdgeTrackParams p;
  p.speed_mm_s = 50;
  p.start_iterations = 3;
  p.max_lead_mm = 10;
  p.tare_in_air = 0;
  EdgeTrackController c(context, p);
  // The arm barely moves (held): the target runs ahead no further than the cap.
  for (std::uint64_t i = 0; i < 12; ++i) {
    const V2 tool = {i < 4 ? 3.0 * static_cast<double>(i) : 9 + 0.1 * static_cast<double>(i), 0};
    const ControllerCommand cmd = c.Step(At(i, tool, 100));
    if (c.tracking()) {
      EXPECT_LE(1e3 * cmd.step_m[0], 10 + 1e-6) << "iteration " << i;
    }
  }
}

// A reading far from the fit's inset where the tool is (a corner the fit could not foresee)
// hands the steering back to `fast` for start_iterations, with restart_mm set; never without.
TEST(EdgeTrackTest, AReadingFarFromTheFitRestartsFromFast) {
  ControllerContext context;
  EdgeTrackParams p;
  p.start_iterations = 3;
  p.start_step_mm = 7.5;
  p.tare_in_air = 0;
  for (double restart_mm : {0.0, 1.0}) {
    p.restart_mm = restart_mm;
    EdgeTrackController c(context, p);
    const double inset = InsetFromMeanVacuumMm(57);
    for (std::uint64_t i = 0; i < 8; ++i) c.Step(At(i, {7.5 * static_cast<double>(i), inset}, 57));
    ASSERT_TRUE(c.tracking());
    // Still on the line, but the cup reads 3 mm deeper than the fit says.
    c.Step(At(8, {60, inset}, 1650));
    EXPECT_EQ(c.tracking(), restart_mm == 0) << restart_mm;
    // Within 0.5 mm of the fit, no restart: the reading agrees.
    EdgeTrackController calm(context, p);
    for (std::uint64_t i = 0; i < 8; ++i)
      calm.Step(At(i, {7.5 * static_cast<double>(i), inset}, 57));
    calm.Step(At(8, {60, inset}, 71));
    EXPECT_TRUE(calm.tracking());
    if (restart_mm == 0) continue;
    c.Step(At(9, {63, inset}, 57));
    c.Step(At(10, {66, inset}, 57));
    EXPECT_FALSE(c.tracking());  // `fast` for iterations 8, 9, 10
    c.Step(At(11, {69, inset}, 57));
    EXPECT_TRUE(c.tracking());
  }
}

TEST(EdgeTrackTest, NonFiniteInputHoldsStillAndStartsAfresh) {
  ControllerContext context;
  EdgeTrackParams p;
  p.tare_in_air = 0;
  EdgeTrackController c(context, p);
  for (std::uint64_t i = 0; i < 8; ++i) c.Step(At(i, {7.5 * static_cast<double>(i), 0}, 100));
  ASSERT_TRUE(c.tracking());
  for (int field = 0; field < 3; ++field) {
    ControllerInput in = At(8, {60, 0}, 100);
    if (field == 0) in.p_pa[2] = std::nan("");
    if (field == 1) in.tool_m[0] = INFINITY;
    if (field == 2) in.tool_rotation[4] = std::nan("");
    const ControllerCommand cmd = c.Step(in);
    EXPECT_EQ(cmd.step_m[0], 0);
    EXPECT_EQ(cmd.step_m[1], 0);
    EXPECT_TRUE(CheckControllerCommand(cmd).empty());
    EXPECT_FALSE(c.tracking());
  }
}

TEST(EdgeTrackTest, IsRegisteredWithItsKeys) {
  const ControllerType* t = FindControllerType("edge_track");
  ASSERT_NE(t, nullptr);
  ControllerChoice choice;
  std::string error;
  EXPECT_TRUE(ParseControllerChoice("edge_track", "speed_mm_s=60,fit_points=8", &choice, &error))
      << error;
  EXPECT_FALSE(ParseControllerChoice("edge_track", "fit_points=2", &choice, &error));
  EXPECT_NE(error.find("fit_points"), std::string::npos);
  // A fit that could never curve is refused, naming both keys.
  EXPECT_FALSE(
      ParseControllerChoice("edge_track", "fit_points=6,circle_points=8", &choice, &error));
  EXPECT_NE(error.find("circle_points"), std::string::npos) << error;
  EXPECT_NE(error.find("fit_points"), std::string::npos) << error;
  EXPECT_TRUE(ParseControllerChoice("edge_track", "fit_points=8,circle_points=4", &choice, &error))
      << error;
}

}  // namespace
}  // namespace ssc
