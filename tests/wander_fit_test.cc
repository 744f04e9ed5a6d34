// The wander calibration's machinery on a tiny budget: trials run with the candidate sensor
// chain, the objective is deterministic, and Nelder-Mead never makes it worse than the start.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <unistd.h>

#include "studies/dynamic_calibration.h"
#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

TEST(WanderFitTest, FitsOnATinyBudgetWithoutGettingWorse) {
  const std::string work = (std::filesystem::temp_directory_path() /
                            ("ssc_wander_" + std::to_string(::getpid()))).string();
  const std::vector<WanderTarget> targets = {{3.5, 1.89, 0.31}};
  std::string error;
  WanderFit start, fit;
  // Budget 1: only the starting point is evaluated.
  ASSERT_TRUE(FitWander(SourceDir() + "/scenes/disk_benchmark_gantry.xml", work, targets, 5.0, 1,
                        1, 6.0, 20.0, &start, &error)) << error;
  ASSERT_TRUE(FitWander(SourceDir() + "/scenes/disk_benchmark_gantry.xml", work, targets, 5.0, 1,
                        6, 6.0, 20.0, &fit, &error)) << error;
  ASSERT_EQ(fit.model.size(), 1u);
  EXPECT_TRUE(std::isfinite(fit.model[0].sigma_r_mm) && std::isfinite(fit.model[0].s_c));
  EXPECT_GT(fit.noise_pa, 0);
  EXPECT_GE(fit.lag_ms, -1e-9);
  EXPECT_LE(fit.cost, start.cost + 1e-9);
  std::filesystem::remove_all(work);
}

}  // namespace
}  // namespace ssc
