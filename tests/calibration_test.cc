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

}  // namespace
}  // namespace ssc
