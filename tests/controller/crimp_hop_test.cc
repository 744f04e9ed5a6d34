// Crimp recovery as pure logic: the detector on synthetic signatures (a crimped lip, a straight
// edge, a grasp, a moving cup) and the hop's sequence.
#include "controller/crimp_hop.h"

#include <gtest/gtest.h>

namespace ssc {
namespace {

// Synthetic signatures at P_ref 100 Pa: one chamber leaking behind a fold while three stay
// sealed; a cup straddling a straight edge (two covered, two open); a full grasp.
constexpr std::array<double, 4> kCrimped = {900, 850, 40, 1000};
constexpr std::array<double, 4> kStraddling = {300, 280, 8, 10};
constexpr std::array<double, 4> kGrasp = {20000, 20100, 19900, 20050};

TEST(CrimpDetectorTest, OneChamberLeakingWhileThreeAreSealedIsTheSignature) {
  const CrimpHopParams p;
  EXPECT_TRUE(CrimpSignature(p, kCrimped, 100));
  EXPECT_FALSE(CrimpSignature(p, kStraddling, 100));
  EXPECT_FALSE(CrimpSignature(p, kGrasp, 100));
  EXPECT_FALSE(CrimpSignature(p, {90, 85, 4, 95}, 100));  // the three below P_ref: on the edge
  EXPECT_FALSE(CrimpSignature(p, {900, 850, 400, 1000}, 100));  // no chamber leaks
}

TEST(CrimpDetectorTest, FiresOnlyWhenTheSignatureHoldsWhileTheCupStalls) {
  CrimpHopParams p;
  p.stall_iterations = 4;
  p.stall_share = 0.25;
  const double step = 0.5e-3;  // the law's dL on the test objects
  CrimpDetector stalled(p);    // 0.3 mm over three steps of 0.5 mm: stalled
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(stalled.Update(kCrimped, 100, {0.1e-3 * i, 0}, step));
  EXPECT_TRUE(stalled.Update(kCrimped, 100, {0.3e-3, 0}, step));
  // The same signature while the cup passes a concave corner at half the law's pace: no crimp.
  CrimpDetector moving(p);
  for (int i = 0; i < 8; ++i) EXPECT_FALSE(moving.Update(kCrimped, 100, {0.25e-3 * i, 0}, step));
  CrimpDetector interrupted(p);  // a sample without it starts the count again
  for (int i = 0; i < 3; ++i) interrupted.Update(kCrimped, 100, {0, 0}, step);
  EXPECT_FALSE(interrupted.Update(kStraddling, 100, {0, 0}, step));
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(interrupted.Update(kCrimped, 100, {0, 0}, step));
  EXPECT_TRUE(interrupted.Update(kCrimped, 100, {0, 0}, step));
}

TEST(CrimpHopTest, AHopLiftsMovesPastComesDownToTheForceAndResumes) {
  ControllerContext context;
  CrimpHopParams p;
  p.stall_iterations = 2;
  p.lift_mm = 4;
  p.hop_mm = 10;
  p.descend_mm = 2;
  p.force_n = 1.0;
  CrimpHopController c(context, p);
  ControllerInput in;
  in.p_pa = kStraddling;
  in.ft_normal_n = 1.5;
  ControllerCommand cmd = c.Step(in);  // following: the law's step learns the edge's direction
  EXPECT_EQ(cmd.step_m, ComputeContourStep(kStraddling, context.law).step_m);
  EXPECT_FALSE(cmd.lifted);
  in.p_pa = kCrimped;
  c.Step(in);
  cmd = c.Step(in);  // the signature twice in place: the hop starts
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kLift);
  EXPECT_EQ(c.hops(), 1);
  EXPECT_TRUE(cmd.lifted);
  EXPECT_DOUBLE_EQ(cmd.height_offset_m, 4e-3);
  EXPECT_EQ(cmd.step_m[0], 0.0);
  in.ft_normal_n = 0;  // in the air
  in.p_pa = {1, 1, 1, 1};
  c.Step(in);
  cmd = c.Step(in);  // lifted long enough: the move past, along the edge as last followed
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kPass);
  const ContourStep law = ComputeContourStep(kStraddling, context.law);
  EXPECT_NEAR(cmd.step_m[0], 10e-3 * law.along_edge[0], 1e-12);
  EXPECT_NEAR(cmd.step_m[1], 10e-3 * law.along_edge[1], 1e-12);
  EXPECT_TRUE(cmd.lifted);
  cmd = c.Step(in);
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kDescend);
  double last = cmd.height_offset_m;
  for (int i = 0; i < 3; ++i) {  // coming down, still lifted, until the force returns
    cmd = c.Step(in);
    EXPECT_TRUE(cmd.lifted);
    EXPECT_LT(cmd.height_offset_m, last);
    last = cmd.height_offset_m;
  }
  in.ft_normal_n = 1.2;
  in.p_pa = kStraddling;
  cmd = c.Step(in);  // in contact: following again, at the height where contact came back
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kFollow);
  EXPECT_FALSE(cmd.lifted);
  EXPECT_DOUBLE_EQ(cmd.height_offset_m, last);
  EXPECT_EQ(cmd.step_m, law.step_m);
}

}  // namespace
}  // namespace ssc
