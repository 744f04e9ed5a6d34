// The robot effects' per-trial state (trial/trial_effects.h): off is the ideal loop,
// a reset starts every trial afresh (same seed, same answers), a held step never misses, a step
// waits for the pose read after the plot, and the lip's shear shows in both readings.
#include "trial/trial_effects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ssc {
namespace {

// The F/T compression the trial's lip is dragged with: pressed (trial/robot_effects.h).
constexpr double kPressN = 1.5;

// Every mechanism on, at values inside their ranges.
RobotEffectsParams AllOn() {
  RobotEffectsParams p;
  p.loop.jitter_s = 0.04;
  p.loop.pose_delay_s = 0.1;
  p.loop.step_error_relative = 0.2;
  p.loop.step_error_max_mm = 1.0;
  p.loop.step_error_corr = 0.3;
  p.lip.slip_mm = 1.0;
  p.lip.tilt_decades = 0.3;
  p.lip.peel_decades = 0.5;
  p.chambers.gain_spread = 0.1;
  p.chambers.offset_spread_pa = 8;
  p.chambers.drift_pa = 10;
  p.chambers.drift_relative = 0.1;
  return p;
}

// What a trial asks of the effects over a few iterations, flattened.
std::vector<double> Trace(TrialEffects* e) {
  std::vector<double> out;
  double t = 0;
  for (int k = 0; k < 6; ++k) {
    e->MoveTool({0.4e-3 * k, -0.2e-3}, kPressN);
    t += e->NextIterationPeriod(0.25);
    const std::array<double, 4> host = e->HostReading(t, {10, 200, 150, 20});
    const std::array<double, 4> chambers = e->ChamberReading({10, 200, 150, 20});
    const std::array<double, 2> step = e->LandedStep({1e-3, 2e-3}, static_cast<std::uint64_t>(k));
    out.push_back(t);
    out.insert(out.end(), host.begin(), host.end());
    out.insert(out.end(), chambers.begin(), chambers.end());
    out.insert(out.end(), step.begin(), step.end());
  }
  return out;
}

TEST(TrialEffectsTest, OffIsTheIdealLoop) {
  TrialEffects e;
  e.Reset(RobotEffectsParams(), 5);
  const std::array<double, 4> p = {10, 200, 150, 20};
  e.MoveTool({3e-3, -2e-3}, kPressN);
  EXPECT_EQ(e.NextIterationPeriod(0.25), 0.25);
  EXPECT_EQ(e.HostReading(1.0, p), p);
  EXPECT_EQ(e.ChamberReading(p), p);
  EXPECT_EQ(e.LandedStep({1e-3, 2e-3}, 3), (std::array<double, 2>{1e-3, 2e-3}));
  EXPECT_FALSE(e.DeferStep(1.0));
  EXPECT_FALSE(e.TakeDueStep(100.0));
}

TEST(TrialEffectsTest, AResetStartsEveryTrialAfreshFromItsSeed) {
  TrialEffects a;
  a.Reset(AllOn(), 11);
  const std::vector<double> first = Trace(&a);
  // The same object after a trial's worth of state: reset, the same answers.
  a.Reset(AllOn(), 11);
  EXPECT_EQ(Trace(&a), first);
  TrialEffects fresh;
  fresh.Reset(AllOn(), 11);
  EXPECT_EQ(Trace(&fresh), first);
  // The clock, the host's reading and the landings are drawn from the seed: another seed
  // changes each of them (the chambers as the lip drags them depend on the path alone).
  TrialEffects other;
  other.Reset(AllOn(), 12);
  const std::vector<double> second = Trace(&other);
  ASSERT_EQ(second.size(), first.size());
  for (size_t i = 0; i < first.size(); ++i) {
    const size_t field = i % 11;  // t, host x4, chambers x4, step x2
    if (field >= 5 && field <= 8) {
      EXPECT_EQ(first[i], second[i]) << i;
    } else {
      EXPECT_NE(first[i], second[i]) << i;
    }
  }
}

TEST(TrialEffectsTest, AHeldStepNeverMissesAndATakenStepMissesByItsOwnDraw) {
  RobotEffectsParams p;
  p.loop.step_error_relative = 0.2;
  TrialEffects e;
  e.Reset(p, 3);
  EXPECT_EQ(e.LandedStep({0, 0}, 4), (std::array<double, 2>{0, 0}));
  const std::array<double, 2> step = {3e-3, -4e-3};  // 5 mm: sigma 1 mm per axis
  EXPECT_EQ(e.LandedStep(step, 4), e.LandedStep(step, 4));
  EXPECT_NE(e.LandedStep(step, 4), e.LandedStep(step, 5));
  double sum2 = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const std::array<double, 2> landed = e.LandedStep(step, static_cast<std::uint64_t>(k));
    sum2 += std::pow(landed[0] - step[0], 2) + std::pow(landed[1] - step[1], 2);
  }
  EXPECT_NEAR(std::sqrt(sum2 / (2 * n)), 1e-3, 0.05e-3);
}

TEST(TrialEffectsTest, AStepWaitsForThePoseReadAfterThePlotAndIsTakenOnce) {
  RobotEffectsParams p;
  p.loop.pose_delay_s = 0.1;
  TrialEffects e;
  e.Reset(p, 1);
  EXPECT_FALSE(e.TakeDueStep(0.5));  // nothing waits yet
  EXPECT_TRUE(e.DeferStep(1.0));
  EXPECT_FALSE(e.TakeDueStep(1.05));
  EXPECT_TRUE(e.TakeDueStep(1.1 - 5e-10));  // a sum of time steps a little short of 1.1 s
  EXPECT_FALSE(e.TakeDueStep(1.2));
  // A reset drops a waiting step.
  EXPECT_TRUE(e.DeferStep(2.0));
  e.Reset(p, 1);
  EXPECT_FALSE(e.TakeDueStep(10.0));
}

TEST(TrialEffectsTest, TheLipsShearShowsInBothReadingsAndCarriesOver) {
  RobotEffectsParams p;
  p.lip.slip_mm = 1.0;
  p.lip.tilt_decades = 0.3;
  TrialEffects e;
  e.Reset(p, 1);
  const std::array<double, 4> chambers = {100, 100, 100, 100};
  e.MoveTool({2e-3, 0}, kPressN);  // past the slip: full shear along +x
  const std::array<double, 4> dragged = e.ChamberReading(chambers);
  EXPECT_NE(dragged, chambers);
  // No sensor effects on: the host reads the dragged chambers.
  EXPECT_EQ(e.HostReading(0.25, chambers), dragged);
  // A trial resumed at its follow start takes the shear over.
  TrialEffects resumed;
  resumed.Reset(p, 1);
  resumed.set_lip_shear(e.lip_shear());
  EXPECT_EQ(resumed.ChamberReading(chambers), dragged);
  e.Reset(p, 1);
  EXPECT_EQ(e.ChamberReading(chambers), chambers);
}

}  // namespace
}  // namespace ssc
