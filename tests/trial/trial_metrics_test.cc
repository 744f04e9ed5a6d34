#include "trial/trial_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "trial/trial_goal.h"
#include "trial/trial_outcome.h"

namespace ssc {
namespace {

std::vector<Point2> Circle(double cx, double cy, double r, int n, double ripple = 0, int k = 0) {
  std::vector<Point2> p;
  for (int i = 0; i <= n; ++i) {
    const double th = 2 * M_PI * i / n;
    const double rr = r + ripple * std::sin(k * th);
    p.push_back({cx + rr * std::cos(th), cy + rr * std::sin(th)});
  }
  return p;
}

TEST(TrialMetricsTest, PerfectCircle) {
  const int n = 20000;
  const auto path = Circle(0.65, 0, 0.0325, n);
  std::vector<double> t(path.size());
  for (size_t i = 0; i < t.size(); ++i) t[i] = 10.0 * static_cast<double>(i) / n;
  const DiskTrialMetrics m = ComputeDiskMetrics(path, t, {0.65, 0}, 0.035);
  EXPECT_NEAR(m.s_mm, 2 * M_PI * 32.5, 1e-3);
  EXPECT_NEAR(m.r_mean_mm, 32.5, 1e-9);
  EXPECT_NEAR(m.dr_mm, -2.5, 1e-9);
  EXPECT_NEAR(m.sigma_r_mm, 0.0, 1e-6);
  EXPECT_NEAR(m.s_c, 32.5 / 35 - 1, 1e-6);
  EXPECT_NEAR(m.duration_s, 10.0, 1e-12);
  EXPECT_NEAR(m.speed_mm_s, 2 * M_PI * 32.5 / 10, 1e-3);
  EXPECT_NEAR(m.speed_body_d_s, m.speed_mm_s / 23.0, 1e-12);
  EXPECT_NEAR(m.contour_mean_mm, 2.5, 1e-9);
  EXPECT_NEAR(m.contour_max_mm, 2.5, 1e-9);
}

TEST(TrialMetricsTest, SinusoidalRipple) {
  const double r0 = 0.033, a = 0.0015;
  const int k = 7, n = 70000;
  const auto path = Circle(0, 0, r0, n, a, k);
  const DiskTrialMetrics m = ComputeDiskMetrics(path, {}, {0, 0}, 0.035);
  // sigma of a sin over whole periods: a / sqrt(2); mean radius r0.
  EXPECT_NEAR(m.r_mean_mm, r0 * 1e3, 1e-3);
  EXPECT_NEAR(m.sigma_r_mm, a / std::sqrt(2.0) * 1e3, 1e-3);
  // Length: integral of sqrt(r^2 + r'^2) dtheta, by fine quadrature.
  double s = 0;
  const int q = 400000;
  for (int i = 0; i < q; ++i) {
    const double th = 2 * M_PI * (i + 0.5) / q;
    const double r = r0 + a * std::sin(k * th), dr = a * k * std::cos(k * th);
    s += std::sqrt(r * r + dr * dr) * 2 * M_PI / q;
  }
  EXPECT_NEAR(m.s_mm / (s * 1e3), 1.0, 1e-6);
  EXPECT_NEAR(m.contour_max_mm, (0.035 - (r0 - a)) * 1e3, 1e-3);
}

TEST(TrialMetricsTest, GenericContourDistance) {
  // A straight contour y = 0: distances are |y|.
  const std::vector<Point2> path = {{0, 0.001}, {0.01, -0.003}, {0.02, 0.002}};
  const auto e = ContourError(path, [](double, double y) { return std::fabs(y); });
  EXPECT_NEAR(e[0], 0.002, 1e-15);
  EXPECT_NEAR(e[1], 0.003, 1e-15);
}

TEST(SweepTrackerTest, CountsCounterClockwisePositiveAndUnwraps) {
  SweepTracker ccw;
  ccw.Reset(0, 0, 1, 0);
  for (int i = 1; i <= 720; ++i) ccw.Add(std::cos(i * M_PI / 360), std::sin(i * M_PI / 360));
  EXPECT_NEAR(ccw.swept_deg(), 360.0, 1e-9);
  SweepTracker cw;
  cw.Reset(5, 5, 4, 5);  // start west of the centre, at 180 deg: crosses the +-180 cut at once
  for (int i = 1; i <= 360; ++i) {
    cw.Add(5 + std::cos(M_PI + i * M_PI / 180), 5 - std::sin(M_PI + i * M_PI / 180));
  }
  EXPECT_NEAR(cw.swept_deg(), -360.0, 1e-9);
}

TEST(TrialOutcomeTest, ClassifiesEachEnd) {
  TrialThresholds t;
  auto cls = [&](std::array<double, 4> p, double force, bool reached, double elapsed) {
    return ClassifySample(t, p, force, reached ? GoalStatus::kReached : GoalStatus::kPending,
                          elapsed, 100)
        .outcome;
  };
  EXPECT_EQ(cls({100, 0, 0, 100}, 1.5, false, 10), Outcome::kRunning);
  EXPECT_EQ(cls({100, 0, 0, 100}, 1.5, true, 10), Outcome::kSuccess);
  EXPECT_EQ(cls({1, 2, 3, 4}, 1.5, false, 10), Outcome::kFailureOffEdge);  // mean 2.5 < 5
  EXPECT_EQ(cls({5, 5, 5, 5}, 1.5, false, 10), Outcome::kRunning);         // mean 5: not below
  EXPECT_EQ(cls({20000, 20000, 20000, 20000}, 1.5, false, 10), Outcome::kFailureGrasp);
  EXPECT_EQ(cls({20000, 20000, 20000, 9000}, 1.5, false, 10), Outcome::kRunning);  // not all
  EXPECT_EQ(cls({100, 0, 0, 100}, 101, true, 10), Outcome::kUnstable);             // before success
  EXPECT_EQ(cls({NAN, 0, 0, 100}, 1.5, false, 10), Outcome::kUnstable);
  EXPECT_EQ(cls({100, 0, 0, 100}, 1.5, false, 101), Outcome::kTimeout);
  // A lost goal ends the trial before success and before the pressure failures.
  EXPECT_EQ(
      ClassifySample(t, {20000, 20000, 20000, 20000}, 1.5, GoalStatus::kLost, 10, 100).outcome,
      Outcome::kLostEdge);
  EXPECT_STREQ(OutcomeName(Outcome::kFailureOffEdge), "failure_I");
  EXPECT_STREQ(OutcomeName(Outcome::kFailureGrasp), "failure_II");
  EXPECT_STREQ(OutcomeName(Outcome::kLostEdge), "lost_edge");
}

// A circle of radius r about c, walked from angle a0 over `sweep` rad in n steps.
std::vector<Point2> Arc(const Point2& c, double r, double a0, double sweep, int n) {
  std::vector<Point2> p;
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + sweep * i / n;
    p.push_back({c[0] + r * std::cos(a), c[1] + r * std::sin(a)});
  }
  return p;
}

// The stall rule at the object trials' settings: the law's speed at dL 0.5 mm (2.1 mm/s) never
// stalls; a cup held in place stalls once the window has passed since its last real progress.
TEST(StallWatchTest, AHeldCupStallsAfterTheWindowAndAMovingOneNever) {
  const double period_s = 0.15, speed_m_s = 0.5e-3 * (1 - std::exp(-1.0)) / period_s;
  StallWatch moving;
  moving.Start(1e-3 * kObjectStallMm, kObjectStallWindowS, 0, 0);
  for (int i = 1; i <= 2000; ++i) {
    ASSERT_FALSE(moving.Add(i * period_s, speed_m_s * i * period_s)) << i;
  }
  // Moves 30 mm, then held at 30 mm with the arm's landing jitter (+-1.4 mm, under stall_mm).
  StallWatch held;
  held.Start(1e-3 * kObjectStallMm, kObjectStallWindowS, 0, 0);
  double stalled_at_s = -1, reached_s = 0;
  for (int i = 1; i <= 1000 && stalled_at_s < 0; ++i) {
    const double t = i * period_s;
    double s = std::min(speed_m_s * t, 0.030);
    if (s >= 0.030 && reached_s == 0) reached_s = t;
    if (s >= 0.030) s += 1.4e-3 * std::sin(0.7 * i);
    if (held.Add(t, s)) stalled_at_s = t;
  }
  ASSERT_GT(stalled_at_s, 0);
  // The last mark is set within the last stall_mm before 30 mm or by the jitter's first peak
  // after it (the window then runs from there): about one window after the cup stopped.
  EXPECT_GE(stalled_at_s, reached_s - 1e-3 * kObjectStallMm / speed_m_s + kObjectStallWindowS);
  EXPECT_LE(stalled_at_s, reached_s + kObjectStallWindowS + 2.0);
  EXPECT_NE(held.Detail().find("furthest 31.4"), std::string::npos) << held.Detail();
}

TEST(StallWatchTest, BackingUpIsNoProgressAndSlowProgressIsProgress) {
  // Backs up 5 mm and returns: only passing the furthest point by more than stall_mm counts.
  StallWatch back;
  back.Start(0.002, 10, 0, 0.010);
  EXPECT_FALSE(back.Add(4, 0.005));
  EXPECT_FALSE(back.Add(8, 0.0115));  // 1.5 mm past the furthest: not yet progress
  EXPECT_TRUE(back.Add(10, 0.0118));
  // 2.1 mm every 9.9 s: each passes the mark before the window ends.
  StallWatch slow;
  slow.Start(0.002, 10, 0, 0);
  for (int i = 1; i <= 50; ++i) ASSERT_FALSE(slow.Add(9.9 * i, 0.0021 * i)) << i;
  // A window of 0 is off.
  StallWatch off;
  off.Start(0.002, 0, 0, 0);
  EXPECT_FALSE(off.Add(3000, 0));
  EXPECT_STREQ(OutcomeName(Outcome::kStalled), "stalled");
  EXPECT_EQ(ValidateStallRule(2, 20), "");
  EXPECT_NE(ValidateStallRule(0, 20).find("stall_mm"), std::string::npos);
  EXPECT_NE(ValidateStallRule(2, -1).find("stall_window_s"), std::string::npos);
  EXPECT_NE(ValidateStallRule(2, NAN).find("[0, 3600]"), std::string::npos);
}

TEST(TrialGoalTest, ProgressIsTheArcOrTheSweptShareOfTheLoop) {
  const Point2 c{0.65, 0};
  const double r = 0.033;
  const auto arc = Arc(c, r, 0, M_PI / 2, 100);  // a quarter turn counter-clockwise
  GoalTracker ccw, cw;
  ccw.Start(TrialGoal::SweptAngle(c, kLoopSweepDeg), nullptr, arc[0]);
  cw.Start(TrialGoal::SweptAngle(c, -kLoopSweepDeg), nullptr, arc[0]);
  for (size_t i = 1; i < arc.size(); ++i) {
    ccw.Add(arc[i]);
    cw.Add(arc[i]);
  }
  EXPECT_NEAR(ccw.progress_m(), M_PI / 2 * r, 1e-9);
  EXPECT_NEAR(cw.progress_m(), -M_PI / 2 * r, 1e-9);  // the wrong way round
}

TEST(TrialGoalTest, SweptAngleIsReachedOnlyInItsSense) {
  const Point2 c{0.65, 0};
  const auto loop = Arc(c, 0.033, 0, 2 * M_PI * 356 / 360, 712);
  GoalTracker ccw;
  ccw.Start(TrialGoal::SweptAngle(c, kLoopSweepDeg), nullptr, loop[0]);
  GoalTracker cw;  // a hole's goal: clockwise
  cw.Start(TrialGoal::SweptAngle(c, -kLoopSweepDeg), nullptr, loop[0]);
  for (size_t i = 1; i < loop.size(); ++i) {
    EXPECT_FALSE(ccw.reached() && i < 700) << i;
    ccw.Add(loop[i]);
    cw.Add(loop[i]);
  }
  EXPECT_TRUE(ccw.reached());
  EXPECT_FALSE(cw.reached());
  EXPECT_EQ(ccw.Detail(), "swept 356 deg");
}

TEST(TrialGoalTest, GoalPointFollowsTheEdgeAndIgnoresNearbyParts) {
  // A hairpin: out along y = 0 to x = 0.1, back along y = 0.004. The cup walks the first leg
  // only; the second leg passes 4 mm away, and a goal on it must not be reached by jumping.
  auto edge = std::make_shared<ContourPath>(
      ContourPath::Polygon({{0, 0}, {0.1, 0}, {0.1, 0.004}, {0, 0.004}}, false));
  GoalTracker goal_on_first_leg, goal_on_second_leg;
  goal_on_first_leg.Start(TrialGoal::GoalPoint(0.08), edge, {0.001, 0.0015});
  goal_on_second_leg.Start(TrialGoal::GoalPoint(0.1 + 0.004 + 0.06), edge, {0.001, 0.0015});
  for (int i = 1; i <= 90; ++i) {
    const Point2 p{0.001 * i, 0.0021};  // nearer the second leg than the first
    goal_on_first_leg.Add(p);
    goal_on_second_leg.Add(p);
  }
  EXPECT_NEAR(goal_on_first_leg.arc_m(), 0.090, 1e-9);
  EXPECT_TRUE(goal_on_first_leg.reached());
  EXPECT_FALSE(goal_on_second_leg.reached());
  // Without an edge nothing is reached.
  GoalTracker blind;
  blind.Start(TrialGoal::GoalPoint(0.0), nullptr, {0, 0});
  EXPECT_FALSE(blind.reached());
}

// A wedge thinner than the cup: its far side, and the goal on it, pass under the body at the
// start. The tracked position starts at the start's own arc, and the goal counts only after the
// cup moved along the edge; standing still, nothing is reached.
TEST(TrialGoalTest, AGoalPointNeedsAPathFromTheStart) {
  const double a = M_PI / 180;  // a 1 deg wedge, apex at the origin, edges 60 mm long
  auto edge = std::make_shared<ContourPath>(ContourPath::Polygon(
      {{-0.060, 0}, {0, 0}, {-0.060 * std::cos(a), 0.060 * std::sin(a)}}, false));
  TrialGoal goal = TrialGoal::GoalPoint(0.100);
  goal.band_m = kFollowBandM;
  goal.start_arc_m = 0.040;
  ASSERT_EQ(goal.Validate(), "");
  GoalTracker still;
  const Point2 start{-0.020, 0.005};  // 20 mm before the apex, 5 mm toward the far side
  still.Start(goal, edge, start);
  EXPECT_NEAR(still.arc_m(), 0.040, 1e-9);  // its own edge, not the far side that passes nearer
  for (int i = 0; i < 50; ++i) still.Add(start);
  EXPECT_NE(still.status(), GoalStatus::kReached) << still.Detail();
  EXPECT_EQ(still.path_m(), 0);
  // A start arc past the goal is refused.
  goal.start_arc_m = 0.2;
  EXPECT_NE(goal.Validate().find("start_arc_m"), std::string::npos);
}

// Issue 12: following means the edge stays under the cup body all the way round.
TEST(TrialGoalTest, LeavingTheBandLosesTheGoal) {
  const Point2 c{0.65, 0};
  const double r = 0.035;
  auto edge = std::make_shared<ContourPath>(ContourPath::Circle(c, r));
  const TrialGoal goal = TrialGoal::AroundDisk(c, r);
  ASSERT_NEAR(goal.band_m, 0.0115, 1e-12);
  // 3 mm inside the edge all the way round: followed.
  GoalTracker inside;
  const auto near = Arc(c, r - 0.003, 0, 2 * M_PI * 356 / 360, 712);
  inside.Start(goal, edge, near[0]);
  for (size_t i = 1; i < near.size(); ++i) inside.Add(near[i]);
  EXPECT_EQ(inside.status(), GoalStatus::kReached) << inside.Detail();
  EXPECT_NEAR(inside.max_distance_m(), 0.003, 1e-6);
  // The same loop, but half-way round the cup cuts 12 mm in toward the centre and back.
  GoalTracker cut;
  cut.Start(goal, edge, near[0]);
  for (size_t i = 1; i < near.size(); ++i) {
    const double a = 2 * M_PI * 356 / 360 * static_cast<double>(i) / 712;
    const double rr = (i > 340 && i < 360) ? r - 0.0125 : r - 0.003;
    cut.Add({c[0] + rr * std::cos(a), c[1] + rr * std::sin(a)});
    if (i == 345) {
      EXPECT_EQ(cut.status(), GoalStatus::kLost);
    }
  }
  EXPECT_EQ(cut.status(), GoalStatus::kLost) << "swept " << cut.swept_deg();
  EXPECT_NE(cut.Detail().find("left the 11.5 mm band"), std::string::npos) << cut.Detail();
  // A band without an edge to measure against is never followed.
  GoalTracker blind;
  blind.Start(goal, nullptr, near[0]);
  EXPECT_EQ(blind.status(), GoalStatus::kLost);
}

// A sharp convex corner: the first edge runs east to the apex at the origin, the second leaves
// back at 180 - a deg; the cup turns back from the first edge at `turn_m` before the apex, 3 mm
// inside, and walks the second edge back 3 mm inside it. The goal is 23 mm past the apex.
GoalStatus RoundSharpCorner(double angle_deg, double turn_m) {
  const double a = (180 - angle_deg) * M_PI / 180;
  auto edge = std::make_shared<ContourPath>(
      ContourPath::Polygon({{-0.06, 0}, {0, 0}, {0.06 * std::cos(a), 0.06 * std::sin(a)}}, false));
  TrialGoal goal = TrialGoal::GoalPoint(0.083);
  goal.band_m = kFollowBandM;
  GoalTracker t;
  t.Start(goal, edge, {-0.04, 0.003});
  for (double x = -0.04; x <= -turn_m; x += 0.0005) t.Add({x, 0.003});
  // Inward normal of the second edge (object on the left of its direction).
  const Point2 n{-std::sin(a), std::cos(a)};
  const double along0 = turn_m / std::cos(M_PI - a);  // where the turn meets the second edge
  for (double u = along0; u <= 0.06 && t.status() == GoalStatus::kPending; u += 0.0005) {
    t.Add({u * std::cos(a) - 0.003 * n[0], u * std::sin(a) - 0.003 * n[1]});
  }
  return t.status();
}

// The apex passes under the cup body (within the band): the corner is followed round however
// sharp the turn; a cup that turns back with the apex beyond its body has not followed it.
TEST(TrialGoalTest, ASharpCornerIsFollowedWhenItsApexPassesUnderTheBody) {
  EXPECT_EQ(RoundSharpCorner(45, 0.0084), GoalStatus::kReached);  // apex 9 mm from the cup
  EXPECT_EQ(RoundSharpCorner(15, 0.029), GoalStatus::kLost);      // apex 29 mm away
  EXPECT_EQ(RoundSharpCorner(30, 0.0134), GoalStatus::kLost);     // apex 13.7 mm away
}

TEST(TrialGoalTest, ADiskSmallerThanTheOpeningIsNeverFollowed) {
  const Point2 c{0.65, 0};
  // 10 mm disk, opening 11 mm: the cup sits over it and turns about its centre, 1 mm off it.
  const double small = 0.005;
  auto small_edge = std::make_shared<ContourPath>(ContourPath::Circle(c, small));
  const TrialGoal small_goal = TrialGoal::AroundDisk(c, small);
  EXPECT_FALSE(small_goal.never_followed.empty());
  GoalTracker over;
  const auto wobble = Arc(c, 0.001, 0, 2 * M_PI * 377 / 360, 754);
  over.Start(small_goal, small_edge, wobble[0]);
  for (size_t i = 1; i < wobble.size(); ++i) over.Add(wobble[i]);
  EXPECT_EQ(over.status(), GoalStatus::kLost) << over.Detail();
  EXPECT_NE(over.Detail().find("smaller than the cup's 11 mm opening"), std::string::npos);
  // Before the sweep completes it is still pending (the trial goes on).
  GoalTracker part;
  part.Start(small_goal, small_edge, wobble[0]);
  for (size_t i = 1; i < 300; ++i) part.Add(wobble[i]);
  EXPECT_EQ(part.status(), GoalStatus::kPending);
  // 12 mm disk, wider than the opening, followed 3 mm outside its edge: counts.
  const double wide = 0.006;
  const TrialGoal wide_goal = TrialGoal::AroundDisk(c, wide);
  EXPECT_TRUE(wide_goal.never_followed.empty());
  GoalTracker round;
  const auto loop = Arc(c, wide + 0.003, 0, 2 * M_PI * 356 / 360, 712);
  round.Start(wide_goal, std::make_shared<ContourPath>(ContourPath::Circle(c, wide)), loop[0]);
  for (size_t i = 1; i < loop.size(); ++i) round.Add(loop[i]);
  EXPECT_EQ(round.status(), GoalStatus::kReached) << round.Detail();
}

// The thresholds at their edges: each just below and just above.
TEST(TrialOutcomeTest, ThresholdsAtTheirEdges) {
  const TrialThresholds t;
  auto cls = [&](std::array<double, 4> p) {
    return ClassifySample(t, p, 1.5, GoalStatus::kPending, 10, 100).outcome;
  };
  // Failure II when all four chambers exceed 10 kPa; one chamber just under keeps it running.
  EXPECT_EQ(cls({10000.5, 10000.5, 10000.5, 10000.5}), Outcome::kFailureGrasp);
  EXPECT_EQ(cls({10000.5, 10000.5, 10000.5, 9999.5}), Outcome::kRunning);
  EXPECT_EQ(cls({9999.5, 10000.5, 10000.5, 10000.5}), Outcome::kRunning);
  EXPECT_EQ(cls({10000, 10000, 10000, 10000}), Outcome::kRunning);  // "exceed": not at
  // Failure I when the mean falls below 5 Pa; just above keeps it running.
  EXPECT_EQ(cls({4.9, 4.9, 4.9, 4.9}), Outcome::kFailureOffEdge);
  EXPECT_EQ(cls({5.1, 5.1, 5.1, 5.1}), Outcome::kRunning);
  EXPECT_EQ(cls({0, 0, 0, 19.6}), Outcome::kFailureOffEdge);  // the mean decides: 4.9 Pa
  EXPECT_EQ(cls({0, 0, 0, 20.4}), Outcome::kRunning);         // 5.1 Pa
  // Success is checked before the failures: a reached goal on a sealed cup is a success.
  EXPECT_EQ(
      ClassifySample(t, {20000, 20000, 20000, 20000}, 1.5, GoalStatus::kReached, 10, 100).outcome,
      Outcome::kSuccess);
}

TEST(TrialGoalTest, LoopIsReachedAt355DegreesNotBefore) {
  // 354.9 deg swept: running; 355 deg: reached (fine steps, so the edge is resolved).
  const Point2 c{0.65, 0};
  GoalTracker goal;
  const double r = 0.033;
  goal.Start(TrialGoal::SweptAngle(c, kLoopSweepDeg), nullptr, {c[0] + r, c[1]});
  auto at = [&](double deg) {
    const double a = deg * M_PI / 180;
    return Point2{c[0] + r * std::cos(a), c[1] + r * std::sin(a)};
  };
  for (int i = 1; i <= 3549; ++i) goal.Add(at(0.1 * i));
  EXPECT_NEAR(goal.swept_deg(), 354.9, 1e-9);
  EXPECT_FALSE(goal.reached());
  goal.Add(at(355.0 + 1e-9));
  EXPECT_TRUE(goal.reached()) << goal.swept_deg();
}

TEST(TrialGoalTest, BandAndDiskSizeAtTheirEdges) {
  // The band is the cup body's radius (11.5 mm): a loop 11.4 mm inside the edge is followed,
  // one that dips to 11.6 mm for a few samples is lost.
  const Point2 c{0.65, 0};
  const double r = 0.035;
  auto edge = std::make_shared<ContourPath>(ContourPath::Circle(c, r));
  const TrialGoal goal = TrialGoal::AroundDisk(c, r);
  for (double depth_mm : {11.4, 11.6}) {
    GoalTracker t;
    const auto loop = Arc(c, r - 0.003, 0, 2 * M_PI * 356 / 360, 712);
    t.Start(goal, edge, loop[0]);
    for (size_t i = 1; i < loop.size(); ++i) {
      const double a = 2 * M_PI * 356 / 360 * static_cast<double>(i) / 712;
      const double rr = (i > 300 && i < 305) ? r - depth_mm * 1e-3 : r - 0.003;
      t.Add({c[0] + rr * std::cos(a), c[1] + rr * std::sin(a)});
    }
    EXPECT_EQ(t.status(), depth_mm < 11.5 ? GoalStatus::kReached : GoalStatus::kLost)
        << depth_mm << " mm: " << t.Detail();
  }
  // The opening is 11 mm: a 10.9 mm disk is never followed, an 11.1 mm disk can be.
  EXPECT_FALSE(TrialGoal::AroundDisk(c, 0.5 * 10.9e-3).never_followed.empty());
  EXPECT_TRUE(TrialGoal::AroundDisk(c, 0.5 * 11.1e-3).never_followed.empty());
}

TEST(TrialGoalTest, ValidateNamesTheField) {
  EXPECT_EQ(TrialGoal::SweptAngle({0, 0}, 355).Validate(), "");
  EXPECT_NE(TrialGoal::SweptAngle({0, 0}, 0.5).Validate().find("sweep_deg"), std::string::npos);
  EXPECT_NE(TrialGoal::GoalPoint(-1).Validate().find("goal_arc_m"), std::string::npos);
}

}  // namespace
}  // namespace ssc
