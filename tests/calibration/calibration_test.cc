#include <gtest/gtest.h>

#include <cmath>

#include "calibration/nelder_mead.h"
#include "calibration/pneumatic_fit.h"

namespace ssc {
namespace {

TEST(NelderMeadTest, FindsTheMinimumOfRosenbrock) {
  auto rosen = [](const std::vector<double>& x) {
    return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
  };
  const NelderMeadResult r = NelderMead(rosen, {-1.2, 1.0}, {0.5, 0.5}, 1e-14, 5000);
  EXPECT_NEAR(r.x[0], 1.0, 1e-3);
  EXPECT_NEAR(r.x[1], 1.0, 2e-3);
}

TEST(PneumaticFitTest, DefaultsMeetThePublishedTargets) {
  for (const FitTarget& t : EvaluatePublishedTargets(PneumaticModel{})) {
    if (t.name == "air_mean_pa") {
      EXPECT_LT(t.model, 5.0);
    } else if (t.name == "plate_min_pa") {
      EXPECT_GT(t.model, 10000.0);
    } else {
      EXPECT_LT(std::fabs(t.residual()), 2.0) << t.name << " model " << t.model;
    }
  }
}

TEST(PneumaticFitTest, RecoversTheTargetsFromAPerturbedStart) {
  PneumaticModel start;
  start.pneumatics.pump_free_flow_m3_s *= 2.5;  // far off: the curve moves by millimetres
  start.pneumatics.port_area_m2 *= 0.6;
  start.pneumatics.jet_area_m2 *= 1.8;
  start.geometry.lip_roughness_gap_m *= 0.4;
  const double before = [&] {
    double c = 0;
    for (const FitTarget& t : EvaluatePublishedTargets(start)) c += t.residual() * t.residual();
    return c;
  }();
  const PneumaticFit fit = FitPublishedTargets(start);
  EXPECT_GT(before, 20.0);
  EXPECT_LT(fit.cost, 1.0);
  for (const FitTarget& t : fit.targets) {
    if (t.name.rfind("offset_at", 0) == 0) {
      EXPECT_NEAR(t.model, t.target, 0.3) << t.name;
    }
  }
  ASSERT_EQ(fit.parameters.size(), 4u);
  EXPECT_EQ(fit.parameters[0].key, "pump_free_flow_lpm");
}

TEST(PneumaticFitTest, DepthPressuresReadAtThePublishedOffsetsGiveThoseOffsets) {
  const PneumaticModel m;
  StaticDepthPressures q{};
  for (int k = 0; k < 3; ++k) q[k] = StaticMeanVacuum(m, kDepthTargetOffsetMm[k] * 1e-3);
  // The static curve rises inward: deeper reads more vacuum.
  EXPECT_LT(q[0], q[1]);
  EXPECT_LT(q[1], q[2]);
  const std::vector<FitTarget> t = EvaluatePublishedTargets(m, q);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k].model, kDepthTargetOffsetMm[k], 1e-3) << t[k].name;
}

TEST(PneumaticFitTest, FitsMovedDepthPressuresThatAnotherPumpDraws) {
  // A curve the model can draw: the pressures a 30 % weaker pump reads at the published offsets.
  PneumaticModel weak;
  weak.pneumatics.pump_free_flow_m3_s *= 0.7;
  StaticDepthPressures q{};
  for (int k = 0; k < 3; ++k) q[k] = StaticMeanVacuum(weak, kDepthTargetOffsetMm[k] * 1e-3);
  const PneumaticModel defaults;
  ASSERT_GT(std::fabs(q[1] - StaticMeanVacuum(defaults, 2.5e-3)), 10.0);  // the curves differ
  const PneumaticFit fit = FitPublishedTargets(defaults, q);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(fit.targets[k].model, kDepthTargetOffsetMm[k], 0.3) << fit.targets[k].name;
  }
}

TEST(PneumaticFitTest, NextDepthPressuresMoveTowardWhereTheLoopRode) {
  const PneumaticModel m;
  const StaticDepthPressures q = kOpenLoopDepthPressures;
  // The loop rode at the published depths: nothing moves.
  const StaticDepthPressures same = NextDepthPressures(m, q, {-0.7, -2.5, -3.2});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(same[k], q[k], 1e-9 * q[k]);
  // Deeper than published at 40 Pa, shallower at 200 Pa: the next curve must read more at 0.7 mm
  // and less at 3.2 mm, by the static ratio between the two depths (hand value from the curve).
  const StaticDepthPressures next = NextDepthPressures(m, q, {-1.2, -2.5, -3.0});
  const double ratio40 = StaticMeanVacuum(m, 1.2e-3) / StaticMeanVacuum(m, 0.7e-3);
  EXPECT_GT(ratio40, 1.0);
  EXPECT_NEAR(next[0], q[0] * ratio40, 1e-9 * q[0]);
  EXPECT_NEAR(next[1], q[1], 1e-9 * q[1]);
  EXPECT_LT(next[2], q[2]);
  // A loop far off the curve (off the edge) moves a pressure by at most a factor of two.
  const StaticDepthPressures wild = NextDepthPressures(m, q, {-6.0, 3.0, -3.2});
  EXPECT_DOUBLE_EQ(wild[0], 2 * q[0]);
  EXPECT_DOUBLE_EQ(wild[1], 0.5 * q[1]);
}

}  // namespace
}  // namespace ssc
