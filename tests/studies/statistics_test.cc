// The studies' shared statistics (studies/statistics/intervals.h) against textbook values.
#include <gtest/gtest.h>

#include <array>

#include "studies/statistics/intervals.h"

namespace ssc {
namespace {

TEST(StatisticsTest, WilsonIntervalMatchesTheTextbook) {
  // 8 of 10: Wilson 95 % = [0.490, 0.943].
  const auto w = WilsonInterval(8, 10);
  EXPECT_NEAR(w[0], 0.4902, 1e-3);
  EXPECT_NEAR(w[1], 0.9433, 1e-3);
  EXPECT_EQ(WilsonInterval(0, 10)[0], 0.0);
  EXPECT_NEAR(WilsonInterval(0, 10)[1], 0.2775, 1e-3);
  EXPECT_EQ(WilsonInterval(10, 10)[1], 1.0);
  EXPECT_NEAR(WilsonInterval(10, 10)[0], 0.7225, 1e-3);
  // No trials: nothing known.
  EXPECT_EQ(WilsonInterval(0, 0), (std::array<double, 2>{0, 1}));
}

TEST(StatisticsTest, StudentTwoSidedPValuesMatchTheTables) {
  EXPECT_NEAR(StudentTwoSidedP(2.0, 10), 0.073388, 1e-6);
  EXPECT_NEAR(StudentTwoSidedP(2.228139, 10), 0.05, 1e-6);
  EXPECT_NEAR(StudentTwoSidedP(1.959964, 1e7), 0.05, 1e-6);
  EXPECT_NEAR(StudentTwoSidedP(-12.706205, 1), 0.05, 1e-6);
  EXPECT_DOUBLE_EQ(StudentTwoSidedP(0, 5), 1.0);
  EXPECT_NEAR(RegularizedIncompleteBeta(0.3, 2, 3), 0.3483, 1e-12);  // 1 - (0.7^4 + 4 0.3 0.7^3)
}

TEST(StatisticsTest, StudentT95IsTheTablesQuantile) {
  EXPECT_NEAR(StudentT95(1), 12.706, 1e-3);
  EXPECT_NEAR(StudentT95(5), 2.571, 1e-3);
  EXPECT_NEAR(StudentT95(29), 2.045, 1e-3);
  EXPECT_NEAR(StudentT95(1e6), 1.960, 1e-3);
  // The quantile and the p-value are one law: p at the quantile is 5 %.
  for (double dof : {2.0, 7.0, 40.0})
    EXPECT_NEAR(StudentTwoSidedP(StudentT95(dof), dof), 0.05, 1e-9);
}

}  // namespace
}  // namespace ssc
