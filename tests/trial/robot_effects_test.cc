// The robot effects, each on its own (trial/robot_effects.h), against hand values.
#include "trial/robot_effects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "controller/contour_law.h"

namespace ssc {
namespace {

TEST(LoopTimingTest, JitterIsUniformWithTheStatedHalfWidth) {
  LoopTimingParams p;
  p.jitter_s = 0.04;
  const double period = 0.25;
  const int n = 40000;
  double sum = 0, sum2 = 0, lo = 1, hi = 0;
  int low_quarter = 0;
  for (int i = 0; i < n; ++i) {
    const double t = IterationPeriod(p, period, 7, static_cast<std::uint64_t>(i));
    sum += t;
    sum2 += (t - period) * (t - period);
    lo = std::fmin(lo, t);
    hi = std::fmax(hi, t);
    low_quarter += t < period - p.jitter_s / 2 ? 1 : 0;
  }
  EXPECT_GE(lo, period - p.jitter_s);
  EXPECT_LE(hi, period + p.jitter_s);
  // Uniform on [-j, j]: mean 0 (sd j/sqrt(3n)), variance j^2/3, a quarter below -j/2.
  EXPECT_NEAR(sum / n, period, 4 * p.jitter_s / std::sqrt(3.0 * n));
  EXPECT_NEAR(sum2 / n, p.jitter_s * p.jitter_s / 3, 0.03 * p.jitter_s * p.jitter_s / 3);
  EXPECT_NEAR(static_cast<double>(low_quarter) / n, 0.25, 0.01);
  EXPECT_LT(lo, period - 0.95 * p.jitter_s);  // the whole band is used
  // Off: exactly the period. Same seed and index: the same period (determinism).
  LoopTimingParams off;
  off.jitter_s = 0;
  EXPECT_EQ(IterationPeriod(off, period, 7, 3), period);
  EXPECT_EQ(IterationPeriod(p, period, 7, 3), IterationPeriod(p, period, 7, 3));
  EXPECT_NE(IterationPeriod(p, period, 7, 3), IterationPeriod(p, period, 8, 3));
}

TEST(ChamberSpreadTest, AGainSpreadRotatesTheDirectionAsComputedByHand) {
  // Cup on the east edge of a disk: the west chambers (3 = NW, 4 = SW) covered at 100 Pa.
  std::array<double, 4> p = {0, 0, 100, 100};
  ChamberSpreadParams params;  // no drift: only the gains act
  params.drift_pa = 0;
  params.drift_relative = 0;
  ChamberSpreadState s;
  s.gain = {1.0, 1.0, 1.2, 0.8};
  ApplyChamberSpread(params, 1, 0.0, &s, &p);
  EXPECT_DOUBLE_EQ(p[2], 120);
  EXPECT_DOUBLE_EQ(p[3], 80);
  // By hand: dPx = P_N - P_S = (0+120)/2 - (0+80)/2 = 20; dPy = P_W - P_E = 100 - 0 = 100.
  // g = 20 north + 100 west: atan(20/100) = 11.31 deg from west toward north.
  ContourLawParams law;
  const ContourStep step = ComputeContourStep(p, law);
  EXPECT_DOUBLE_EQ(step.dpx_pa, 20);
  EXPECT_DOUBLE_EQ(step.dpy_pa, 100);
  const double north = -step.correction[0], west = step.correction[1];  // north = -x_tool
  EXPECT_NEAR(std::atan2(north, west) * 180 / M_PI, std::atan(0.2) * 180 / M_PI, 1e-9);
  // Equal gains: straight west.
  std::array<double, 4> q = {0, 0, 100, 100};
  ChamberSpreadState equal;
  ApplyChamberSpread(params, 1, 0.0, &equal, &q);
  EXPECT_NEAR(ComputeContourStep(q, law).correction[0], 0.0, 1e-12);
}

TEST(ChamberSpreadTest, GainsAreDrawnPerTrialWithTheStatedSpread) {
  ChamberSpreadParams params;
  params.gain_spread = 0.1;
  double sum2 = 0;
  int n = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    ChamberSpreadState s;
    ResetChamberSpread(params, seed, &s);
    for (double g : s.gain) {
      sum2 += (g - 1) * (g - 1);
      ++n;
    }
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.1, 0.005);
  ChamberSpreadState off;
  ChamberSpreadParams no_spread;
  no_spread.gain_spread = 0;
  ResetChamberSpread(no_spread, 5, &off);
  for (double g : off.gain) EXPECT_EQ(g, 1.0);
}

TEST(ChamberSpreadTest, ACupSeedGivesEveryTrialThatCupsGainsAndLeavesTheRestPerTrial) {
  ChamberSpreadParams params;
  params.gain_spread = 0.1;
  params.offset_spread_pa = 5;
  params.cup_seed = 7;
  ChamberSpreadState a, b, per_trial;
  ResetChamberSpread(params, 11, &a);
  ResetChamberSpread(params, 12, &b);
  EXPECT_EQ(a.gain, b.gain);            // one cup: the same gains in trials 11 and 12
  EXPECT_NE(a.offset_pa, b.offset_pa);  // the tare stays per trial
  // They are cup 7's: what a per-trial draw with seed 7 gives.
  ChamberSpreadParams fresh = params;
  fresh.cup_seed = 0;
  ChamberSpreadState seven;
  ResetChamberSpread(fresh, 7, &seven);
  EXPECT_EQ(a.gain, seven.gain);
  // 0: per trial again.
  ResetChamberSpread(fresh, 12, &per_trial);
  EXPECT_NE(per_trial.gain, a.gain);
  for (double g : a.gain) EXPECT_NE(g, 1.0);
  // Only whole cup numbers in range.
  RobotEffectsParams bad;
  bad.chambers.cup_seed = 2.5;
  EXPECT_NE(bad.Validate(0.15).find("cup_seed"), std::string::npos);
  bad.chambers.cup_seed = 2e6;
  EXPECT_NE(bad.Validate(0.15).find("cup_seed"), std::string::npos);
}

TEST(ChamberSpreadTest, TareOffsetsAreDrawnPerTrialIndependentAndHeldThroughTheTrial) {
  ChamberSpreadParams params;
  params.offset_spread_pa = 6;
  double sum = 0, sum2 = 0, cross = 0;
  int n = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    ChamberSpreadState s;
    ResetChamberSpread(params, seed, &s);
    std::array<double, 4> first = {0, 0, 0, 0}, later = {0, 0, 0, 0};
    ApplyChamberSpread(params, seed, 0.0, &s, &first);
    ApplyChamberSpread(params, seed, 30.0, &s, &later);
    EXPECT_EQ(first, later) << "an offset is a per-trial constant, not noise";
    for (double o : first) {
      sum += o;
      sum2 += o * o;
      ++n;
    }
    cross += first[0] * first[1];
  }
  EXPECT_NEAR(sum / n, 0.0, 0.3);
  EXPECT_NEAR(std::sqrt(sum2 / n), 6.0, 0.3);
  EXPECT_NEAR(cross / 3000 / 36.0, 0.0, 0.06);  // chambers drawn independently
  // Off: a reading passes unchanged.
  ChamberSpreadParams off;
  ChamberSpreadState s;
  ResetChamberSpread(off, 9, &s);
  std::array<double, 4> p = {1, 2, 3, 4};
  ApplyChamberSpread(off, 9, 0.0, &s, &p);
  EXPECT_EQ(p, (std::array<double, 4>{1, 2, 3, 4}));
}

TEST(ChamberSpreadTest, SlowNoiseHasItsStationarySpreadAndCorrelationTime) {
  ChamberSpreadParams params;
  params.drift_pa = 8;
  params.drift_time_s = 0.2;
  ChamberSpreadState s;
  ResetChamberSpread(params, 3, &s);
  std::vector<double> x;
  for (int i = 0; i < 40000; ++i) {
    std::array<double, 4> p = {0, 0, 0, 0};
    ApplyChamberSpread(params, 3, i * 0.05, &s, &p);  // 50 ms apart: a quarter of tau
    x.push_back(p[0]);
  }
  const double n = static_cast<double>(x.size());
  double m = 0, v = 0, c = 0;
  for (double a : x) m += a;
  m /= n;
  for (double a : x) v += (a - m) * (a - m);
  v /= n;
  for (std::size_t i = 4; i < x.size(); ++i) c += (x[i] - m) * (x[i - 4] - m);
  c /= (n - 4) * v;
  EXPECT_NEAR(std::sqrt(v), 8.0, 0.4);
  EXPECT_NEAR(c, std::exp(-1.0), 0.05);  // lag 4 x 50 ms = tau
}

TEST(StepErrorTest, EachStepMissesByItsShareOfTheStepIndependentlyPerAxisAndZeroIsExact) {
  LoopTimingParams p;
  EXPECT_EQ(StepError(p, 0.005, 7, 3), (std::array<double, 2>{0, 0}));  // off: no draw, no error
  p.step_error_relative = 0.25;                                         // of a 5 mm step: 1.25 mm
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const std::array<double, 2> e = StepError(p, 0.005, 7, static_cast<std::uint64_t>(i));
    sx += e[0];
    sy += e[1];
    sxx += e[0] * e[0];
    syy += e[1] * e[1];
    sxy += e[0] * e[1];
  }
  // sigma 1.25 mm per axis (standard error of a variance estimate ~0.7 %), mean 0, uncorrelated.
  EXPECT_NEAR(std::sqrt(sxx / n), 1.25e-3, 0.03e-3);
  EXPECT_NEAR(std::sqrt(syy / n), 1.25e-3, 0.03e-3);
  EXPECT_NEAR(sx / n, 0, 0.03e-3);
  EXPECT_NEAR(sy / n, 0, 0.03e-3);
  EXPECT_NEAR(sxy / n / (1.25e-3 * 1.25e-3), 0, 0.03);
  // A pure function of (seed, step index): the same on any thread or rank; another seed differs.
  EXPECT_EQ(StepError(p, 0.005, 7, 11), StepError(p, 0.005, 7, 11));
  EXPECT_NE(StepError(p, 0.005, 7, 11), StepError(p, 0.005, 8, 11));
  // It scales with the step: half the step, half the error, the same draw.
  EXPECT_NEAR(StepError(p, 0.0025, 7, 11)[0], 0.5 * StepError(p, 0.005, 7, 11)[0], 1e-18);
}

TEST(StepErrorTest, CorrelatedMissesKeepTheirSigmaAndCarryRhoFromOneStepToTheNext) {
  LoopTimingParams p;
  p.step_error_relative = 1.0;  // of a 1 mm step: sigma 1 mm, the draws in mm
  const std::array<double, 2> n0 = StepError(p, 1e-3, 7, 0), n1 = StepError(p, 1e-3, 7, 1);
  p.step_error_corr = 0.6;
  // By hand: u_0 = n_0 (the sequence starts stationary), u_1 = 0.6 n_0 + 0.8 n_1.
  EXPECT_NEAR(StepError(p, 1e-3, 7, 0)[0], n0[0], 1e-15);
  EXPECT_NEAR(StepError(p, 1e-3, 7, 1)[1], 0.6 * n0[1] + 0.8 * n1[1], 1e-15);
  // Over many trials (seeds): unit sigma at every step, lag-1 correlation rho, lag-3 rho^3.
  const int n = 20000;
  double s20 = 0, s21 = 0, c1 = 0, c3 = 0, s0 = 0;
  for (int seed = 0; seed < n; ++seed) {
    const auto e = [&](std::uint64_t k) { return 1e3 * StepError(p, 1e-3, seed, k)[0]; };
    const double a = e(40), b = e(41), d = e(43);
    s0 += e(0) * e(0);
    s20 += a * a;
    s21 += b * b;
    c1 += a * b;
    c3 += a * d;
  }
  EXPECT_NEAR(std::sqrt(s0 / n), 1.0, 0.02);
  EXPECT_NEAR(std::sqrt(s20 / n), 1.0, 0.02);
  EXPECT_NEAR(std::sqrt(s21 / n), 1.0, 0.02);
  EXPECT_NEAR(c1 / n, 0.6, 0.03);
  EXPECT_NEAR(c3 / n, 0.216, 0.03);
  // Out of range is refused by name.
  RobotEffectsParams bad;
  bad.loop.step_error_corr = 0.99;
  EXPECT_NE(bad.Validate(0.15).find("step_error_corr"), std::string::npos);
}

TEST(StepErrorTest, TheCapBoundsTheErrorOfLongStepsAndLeavesShortStepsTheirShare) {
  LoopTimingParams p;
  p.step_error_relative = 0.5;
  p.step_error_max_mm = 1.0;  // 1 mm: reached at a 2 mm step
  // Below the cap the share rules (0.5 mm step: sigma 0.25 mm); above it the cap (the same draw
  // scaled): 2.5 and 7.5 mm steps both miss by sigma 1 mm, not 1.25 and 3.75 mm.
  const std::array<double, 2> unit = [&] {
    LoopTimingParams q;
    q.step_error_relative = 1.0;
    return StepError(q, 1e-3, 7, 11);  // sigma 1 mm: the draw in mm
  }();
  EXPECT_NEAR(StepError(p, 0.0005, 7, 11)[0], 0.25 * unit[0], 1e-15);
  EXPECT_NEAR(StepError(p, 0.0025, 7, 11)[1], unit[1], 1e-15);
  EXPECT_NEAR(StepError(p, 0.0075, 7, 11)[0], unit[0], 1e-15);
  // 0 = no cap: the share again.
  p.step_error_max_mm = 0;
  EXPECT_NEAR(StepError(p, 0.0075, 7, 11)[0], 3.75 * unit[0], 1e-15);
  // The cap alone does nothing: the share switches the mechanism on.
  p.step_error_relative = 0;
  p.step_error_max_mm = 1.0;
  EXPECT_EQ(StepError(p, 0.0075, 7, 11), (std::array<double, 2>{0, 0}));
  RobotEffectsParams e;
  e.loop.step_error_max_mm = 3.5;
  EXPECT_NE(e.Validate(0.25).find("step_error_max_mm"), std::string::npos);
}

TEST(StepErrorTest, TheFittedDefaultIsTheStepErrorAndTheTareOffsetAndOffSwitchesThemOff) {
  RobotEffectsParams p = FittedRobotEffects();
  EXPECT_EQ(p.Validate(0.15), "");
  EXPECT_TRUE(p.AnyOn());
  EXPECT_GT(p.loop.step_error_relative, 0);
  EXPECT_GT(p.loop.step_error_max_mm, 0);
  EXPECT_GT(p.loop.step_error_corr, 0);
  EXPECT_LT(p.loop.step_error_corr, 0.5);  // persistent, not a drift: half-life under a step
  EXPECT_GT(p.chambers.offset_spread_pa, 0);
  // Nothing else: the fit put the peel at 0.02 decades, and no other effect was fitted on.
  RobotEffectsParams fitted_only;
  fitted_only.loop.step_error_relative = p.loop.step_error_relative;
  fitted_only.loop.step_error_max_mm = p.loop.step_error_max_mm;
  fitted_only.loop.step_error_corr = p.loop.step_error_corr;
  fitted_only.chambers.offset_spread_pa = p.chambers.offset_spread_pa;
  EXPECT_EQ(FormatRobotEffects(p), FormatRobotEffects(fitted_only));
  std::string error;
  ASSERT_TRUE(ParseRobotEffects("off", &p, &error)) << error;
  EXPECT_FALSE(p.AnyOn());
  EXPECT_EQ(StepError(p.loop, 0.005, 7, 3), (std::array<double, 2>{0, 0}));
}

TEST(LipShearTest, NoFrictionNoShearNoTilt) {
  LipShearParams p;
  p.slip_mm = 0;  // no friction: the footprint never sticks
  p.tilt_decades = 0.3;
  LipShearState s;
  AdvanceLipShear(p, {0.004, 0.0}, &s);
  EXPECT_EQ(s.shear_m[0], 0.0);
  std::array<double, 4> pa = {10, 20, 30, 40};
  ApplyLipTilt(p, s, &pa);
  EXPECT_EQ(pa, (std::array<double, 4>{10, 20, 30, 40}));
}

TEST(LipShearTest, TheLipDragsOnlyWhilePressedAndLandsUnsheared) {
  LipShearParams p;
  p.slip_mm = 1.0;
  LipShearState s;
  DragLip(p, {0.0004, 0.0}, 1.5, &s);  // pressed: sticks, as AdvanceLipShear
  EXPECT_NEAR(s.shear_m[0], 0.0004, 1e-15);
  DragLip(p, {0.004, 0.0}, 0.2 * kLipPressedN, &s);  // lifted: hangs free
  EXPECT_EQ(s.shear_m[0], 0.0);
  EXPECT_EQ(s.shear_m[1], 0.0);
  DragLip(p, {0.0, 0.0003}, kLipPressedN, &s);  // landed anew: the shear starts from there
  EXPECT_EQ(s.shear_m[0], 0.0);
  EXPECT_NEAR(s.shear_m[1], 0.0003, 1e-15);
}

TEST(LipShearTest, ShearSaturatesAtSlipAndTiltsLeadingUpTrailingDown) {
  LipShearParams p;
  p.slip_mm = 1.0;
  p.tilt_decades = 0.2;
  LipShearState s;
  AdvanceLipShear(p, {0.0004, 0.0}, &s);  // 0.4 mm south: sticks
  EXPECT_NEAR(s.shear_m[0], 0.0004, 1e-15);
  AdvanceLipShear(p, {0.004, 0.0}, &s);  // on to 4.4 mm: slides at the 1 mm limit
  EXPECT_NEAR(s.shear_m[0], 0.001, 1e-15);
  std::array<double, 4> pa = {100, 100, 100, 100};
  ApplyLipTilt(p, s, &pa);
  // Moving south (+x_tool): SE and SW lead (x 10^(0.2 cos 45)), NE and NW trail.
  const double f = std::pow(10.0, 0.2 * std::sqrt(0.5));
  EXPECT_NEAR(pa[0], 100 * f, 1e-9);
  EXPECT_NEAR(pa[3], 100 * f, 1e-9);
  EXPECT_NEAR(pa[1], 100 / f, 1e-9);
  EXPECT_NEAR(pa[2], 100 / f, 1e-9);
  // Reversing by 1 mm unloads the shear to zero: no tilt.
  AdvanceLipShear(p, {-0.001, 0.0}, &s);
  std::array<double, 4> flat = {100, 100, 100, 100};
  ApplyLipTilt(p, s, &flat);
  EXPECT_NEAR(flat[0], 100, 1e-9);
}

TEST(LipShearTest, PeelLowersOnlyTrailingChambers) {
  LipShearParams p;
  p.slip_mm = 1.0;
  p.peel_decades = 0.6;
  LipShearState s;
  AdvanceLipShear(p, {0.003, 0.0}, &s);  // south (+x_tool): SE, SW lead; NE, NW trail
  std::array<double, 4> pa = {200, 200, 200, 200};
  ApplyLipTilt(p, s, &pa);
  const double trail = 200 * std::pow(10.0, -0.6 * std::sqrt(0.5));
  EXPECT_EQ(pa[0], 200.0);
  EXPECT_EQ(pa[3], 200.0);
  EXPECT_NEAR(pa[1], trail, 1e-9);
  EXPECT_NEAR(pa[2], trail, 1e-9);
  // With a tilt too, the two add in decades on the trailing side.
  p.tilt_decades = 0.2;
  std::array<double, 4> both = {200, 200, 200, 200};
  ApplyLipTilt(p, s, &both);
  EXPECT_NEAR(both[0], 200 * std::pow(10.0, 0.2 * std::sqrt(0.5)), 1e-9);
  EXPECT_NEAR(both[1], 200 * std::pow(10.0, -0.8 * std::sqrt(0.5)), 1e-9);
  // Without friction (no shear) the peel is off.
  p.slip_mm = 0;
  std::array<double, 4> still = {200, 200, 200, 200};
  AdvanceLipShear(p, {0.003, 0.0}, &s);
  ApplyLipTilt(p, s, &still);
  EXPECT_EQ(still, (std::array<double, 4>{200, 200, 200, 200}));
}

TEST(LipShearTest, ForwardTiltTurnsTheTravelAwayFromTheObject) {
  // East edge, object west, moving north (object on the left): the NW chamber leads.
  LipShearParams p;
  p.slip_mm = 1;
  p.tilt_decades = 0.2;
  LipShearState s;
  AdvanceLipShear(p, {-0.003, 0.0}, &s);  // north = -x_tool
  std::array<double, 4> pa = {0, 0, 100, 100};
  ApplyLipTilt(p, s, &pa);
  EXPECT_GT(pa[2], pa[3]);
  ContourLawParams law;
  law.beta = 0;  // travel direction only
  const ContourStep step = ComputeContourStep(pa, law);
  // Without tilt the travel is due north (-x); the tilt gives it an eastward (-y) component:
  // away from the object, the drift behind failure I.
  EXPECT_LT(step.direction[0], 0);
  EXPECT_LT(step.direction[1], -0.05);
}

TEST(RobotEffectsKeysTest, ParseIsStrictAndOffTurnsEverythingOff) {
  RobotEffectsParams p;
  std::string error;
  ASSERT_TRUE(ParseRobotEffects("jitter_s=0.02,tilt_decades=0.1", &p, &error)) << error;
  EXPECT_EQ(p.loop.jitter_s, 0.02);
  EXPECT_EQ(p.lip.tilt_decades, 0.1);
  for (const char* bad :
       {"jitter_s=", "jitter_s=0x10", "tilt_decades=2", "nope=1", "jitter_s=0.1,", "slip_mm=nan",
        "drift_pa=1e3", "gain_spread", "slip_mm=1,slip_mm=2", "drift_pa=5Pa", "drift_pa= "}) {
    RobotEffectsParams q = p;
    EXPECT_FALSE(ParseRobotEffects(bad, &q, &error)) << bad;
    EXPECT_FALSE(error.empty());
  }
  EXPECT_FALSE(ParseRobotEffects("tilt_decades=2", &p, &error));
  EXPECT_NE(error.find("tilt_decades"), std::string::npos);
  EXPECT_NE(error.find("[0, 1]"), std::string::npos);
  p.chambers.gain_spread = 0.1;
  p.lip.slip_mm = 1;
  ASSERT_TRUE(ParseRobotEffects("off", &p, &error));
  EXPECT_FALSE(p.AnyOn());
  EXPECT_GT(p.chambers.drift_time_s, 0);  // a time constant, not an effect
  // Round trip through the text form.
  RobotEffectsParams r;
  r.loop.pose_delay_s = 0.05;
  r.chambers.drift_pa = 3;
  RobotEffectsParams back;
  ASSERT_TRUE(ParseRobotEffects(FormatRobotEffects(r), &back, &error)) << error;
  EXPECT_EQ(FormatRobotEffects(back), FormatRobotEffects(r));
}

TEST(RobotEffectsKeysTest, ValidateBoundsTheTimingByThePeriod) {
  RobotEffectsParams p;
  EXPECT_EQ(p.Validate(0.25), "");
  p.loop.jitter_s = 0.2;
  EXPECT_NE(p.Validate(0.25).find("jitter_s"), std::string::npos);
  p.loop.jitter_s = 0.05;
  p.loop.pose_delay_s = 0.25;
  EXPECT_NE(p.Validate(0.25).find("pose_delay_s"), std::string::npos);
}

}  // namespace
}  // namespace ssc
