// The wander calibration's machinery on a tiny budget: trials run with the candidate sensor
// chain, the reported cost is the objective of the reported model, and Nelder-Mead improves on
// its initial simplex.
#include "studies/wander_fit.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

TEST(WanderFitTest, FitsOnATinyBudgetAndImprovesOnTheInitialSimplex) {
  const std::vector<WanderTarget> targets = {{3.5, 1.89, 0.31}};
  std::string error;
  WanderFit start, fit;
  // Budget 1: only the initial simplex is evaluated.
  ASSERT_TRUE(FitWander(SourceDir() + "/scenes/disk_benchmark_gantry.xml", targets, 5.0,
                        RobotEffectsParams(), 1, 1, 6.0, 20.0, &start, &error))
      << error;
  ASSERT_TRUE(FitWander(SourceDir() + "/scenes/disk_benchmark_gantry.xml", targets, 5.0,
                        RobotEffectsParams(), 1, 10, 6.0, 20.0, &fit, &error))
      << error;
  ASSERT_EQ(fit.model.size(), 1u);
  EXPECT_TRUE(std::isfinite(fit.model[0].sigma_r_mm) && std::isfinite(fit.model[0].s_c));
  EXPECT_GT(fit.noise_pa, 0);
  EXPECT_GE(fit.lag_ms, -1e-9);
  // The reported cost is the documented objective of the reported model: squared misses
  // scaled by 0.2 mm (sigma_r) and 0.05 (s_c).
  for (const WanderFit* f : {&start, &fit}) {
    ASSERT_EQ(f->model.size(), 1u);
    const double expected = std::pow((f->model[0].sigma_r_mm - 1.89) / 0.2, 2) +
                            std::pow((f->model[0].s_c - 0.31) / 0.05, 2);
    EXPECT_NEAR(f->cost, expected, 1e-9 * (1 + expected));
  }
  // Budget 1 stops after the initial simplex (the start and one step along each of noise and
  // lag: 3 evaluations) and returns its best vertex. Budget 10 must then reach a strictly better
  // point: a simplex that never accepts a step, or one that climbs, fails here. (The budget is
  // checked between iterations, so one iteration may pass it by up to n = 2 evaluations.)
  EXPECT_EQ(start.evaluations, 3);
  EXPECT_GT(fit.evaluations, 3);
  EXPECT_LE(fit.evaluations, 10 + 2);
  EXPECT_LT(fit.cost, start.cost);
}

}  // namespace
}  // namespace ssc
