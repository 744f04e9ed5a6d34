// Crimp recovery as pure logic: the detector on chamber readings measured in the flex tier (the
// crimp at a concave corner, following on a straight edge and round a corner, a segment lip over
// a corner's apex) and the hop's sequence. The hop in a trial: tests/objects/crimp_trial_test.cc.
#include "controller/crimp_hop.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

// Pa, at P_ref 100 Pa (docs/flex_skirt.md, "The crimp"). The crimp: corner_a330 seed 1 and
// corner_a315 seed 3 under the law at dL 10 mm, the iteration the cup sealed (the 315 deg one
// just past 2 kPa, then dragged off the edge); the scripted push 2 mm past the far wall.
constexpr std::array<double, 4> kCrimpA330 = {17248, 17403, 17432, 17420};
constexpr std::array<double, 4> kCrimpA315 = {2132, 2249, 2277, 2040};
constexpr std::array<double, 4> kCrimpPush = {6776, 6015, 6181, 6774};
// Not a crimp: the skirt on a straight edge; the skirt at the 330 deg apex two periods and one
// period before its seal (the lobe already folded in); the segment lip over the same apex.
constexpr std::array<double, 4> kStraightEdge = {28, 211, 224, -2};
constexpr std::array<double, 4> kAtTheApex = {439, 435, 325, 37};
constexpr std::array<double, 4> kBeforeCrimp = {1741, 1672, 1688, 1451};
constexpr std::array<double, 4> kSegmentApex = {3272, 3273, 1476, 3276};

TEST(CrimpDetectorTest, EveryChamberSealedFarAboveTheSetPointIsTheSignature) {
  const CrimpHopParams p;
  for (const auto& crimp : {kCrimpA330, kCrimpA315, kCrimpPush})
    EXPECT_TRUE(CrimpSignature(p, crimp, 100));
  for (const auto& following : {kStraightEdge, kAtTheApex, kBeforeCrimp, kSegmentApex})
    EXPECT_FALSE(CrimpSignature(p, following, 100));
  // Relative to P_ref: at a 1 kPa set point the push's 6 kPa is no seal.
  EXPECT_FALSE(CrimpSignature(p, kCrimpPush, 1000));
}

TEST(CrimpDetectorTest, FiresOnTheSealsOnsetAfterAnEdgeNotOnACupThatStaysSealed) {
  const CrimpHopParams p;
  CrimpDetector crimp(p);  // following, then sealed in one period: the crimp
  EXPECT_FALSE(crimp.Update(kStraightEdge, 100));
  EXPECT_FALSE(crimp.Update(kBeforeCrimp, 100));
  EXPECT_TRUE(crimp.Update(kCrimpA330, 100));
  EXPECT_FALSE(crimp.Update(kCrimpA330, 100));  // still sealed: not a new onset
  // A cup sealed from its landing on, moving across the top face, never reads an edge: no crimp.
  CrimpDetector on_top(p);
  on_top.Reset();
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(on_top.Update(kCrimpA315, 100));
  EXPECT_FALSE(on_top.Update(kAtTheApex, 100));  // an edge again, then sealed: an onset
  EXPECT_TRUE(on_top.Update(kCrimpA315, 100));
  CrimpDetector landed(p);  // a landing forgets the edge read before the hop
  EXPECT_FALSE(landed.Update(kStraightEdge, 100));
  landed.Reset();
  EXPECT_FALSE(landed.Update(kCrimpPush, 100));
}

ControllerInput Reading(const std::array<double, 4>& p_pa, double x_m, double y_m) {
  ControllerInput in;
  in.p_pa = p_pa;
  in.tool_m = {x_m, y_m, 0};
  in.tool_rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1};  // tool x along world y, tool y along -x
  return in;
}

TEST(CrimpHopTest, WithoutACrimpTheCommandsAreTheLaws) {
  ControllerContext context;
  CrimpHopController c(context, CrimpHopParams{});
  for (const auto& p_pa : {kStraightEdge, kAtTheApex, kSegmentApex, kBeforeCrimp, kStraightEdge}) {
    const ControllerCommand cmd = c.Step(Reading(p_pa, 0, 0));
    EXPECT_EQ(cmd.step_m, ComputeContourStep(p_pa, context.law).step_m);
    EXPECT_FALSE(cmd.lifted);
    EXPECT_EQ(cmd.height_offset_m, 0.0);
  }
  EXPECT_EQ(c.hops(), 0);
}

TEST(CrimpHopTest, AHopLiftsGoesBackOverTheEdgeComesDownAndResumesInShortSteps) {
  ControllerContext context;
  CrimpHopParams p;
  p.lift_mm = 4;
  p.descend_mm = 2;
  p.resume_step_mm = 0.5;
  p.resume_iterations = 3;
  CrimpHopController c(context, p);
  c.Step(Reading(kStraightEdge, 0.010, 0.020));  // a chamber open here: the edge under the throat
  c.Step(Reading(kBeforeCrimp, 0.013, 0.020));   // none open: not where the edge was read
  ControllerCommand cmd = c.Step(Reading(kCrimpA330, 0.015, 0.021));
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kLift);
  EXPECT_EQ(c.hops(), 1);
  EXPECT_TRUE(cmd.lifted);
  EXPECT_DOUBLE_EQ(cmd.height_offset_m, 4e-3);
  EXPECT_EQ(cmd.step_m[0], 0.0);  // straight up first
  c.Step(Reading({1, 1, 1, 1}, 0.015, 0.021));
  cmd = c.Step(Reading({1, 1, 1, 1}, 0.015, 0.021));
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kReturn);
  // Back over (10, 20) mm: world (-5, -1) mm is tool (-1, +5) mm with this rotation.
  EXPECT_NEAR(cmd.step_m[0], -1e-3, 1e-12);
  EXPECT_NEAR(cmd.step_m[1], 5e-3, 1e-12);
  EXPECT_TRUE(cmd.lifted);
  cmd = c.Step(Reading({1, 1, 1, 1}, 0.012, 0.0205));  // part of the way: aimed again
  EXPECT_NEAR(cmd.step_m[0], -0.5e-3, 1e-12);
  EXPECT_NEAR(cmd.step_m[1], 2e-3, 1e-12);
  EXPECT_EQ(c.phase(), CrimpHopController::Phase::kDescend);
  EXPECT_DOUBLE_EQ(cmd.height_offset_m, 4e-3);
  for (const double offset : {2e-3, 0.0}) {  // down to the hold height, still lifted
    cmd = c.Step(Reading({1, 1, 1, 1}, 0.010, 0.020));
    EXPECT_TRUE(cmd.lifted);
    EXPECT_DOUBLE_EQ(cmd.height_offset_m, offset);
  }
  for (int i = 0; i < 3; ++i) {  // landed: the law's direction in short steps
    cmd = c.Step(Reading(kStraightEdge, 0.010, 0.020));
    EXPECT_EQ(c.phase(), CrimpHopController::Phase::kFollow);
    EXPECT_FALSE(cmd.lifted);
    EXPECT_DOUBLE_EQ(cmd.height_offset_m, 0.0);
    const ContourStep law = ComputeContourStep(kStraightEdge, context.law);
    EXPECT_NEAR(cmd.step_m[0], 0.5e-3 * law.direction[0], 1e-15);
    EXPECT_NEAR(cmd.step_m[1], 0.5e-3 * law.direction[1], 1e-15);
  }
  cmd = c.Step(Reading(kStraightEdge, 0.010, 0.020));  // then the law's dL again
  EXPECT_EQ(cmd.step_m, ComputeContourStep(kStraightEdge, context.law).step_m);
  // Sealed on the first reading after the landing would not be a new crimp (no edge read since).
  EXPECT_EQ(c.hops(), 1);
}

}  // namespace
}  // namespace ssc
