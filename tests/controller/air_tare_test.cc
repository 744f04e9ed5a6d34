// The air re-tare: which readings it averages, and what it does without any.
#include "controller/air_tare.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

TEST(AirTareTest, AveragesTheReadingsHighEnoughAboveTheHoldHeight) {
  AirTare tare;
  tare.Add({4, -2, 0, 10}, 0.030);
  tare.Add({6, -4, 2, 6}, 0.020);
  tare.Add({50, 40, 45, 60}, 0.012);  // 2 mm above the hold height: the cup's flow reads here
  const std::array<double, 4> o = tare.Offsets(0.010, 0.004);
  EXPECT_EQ(tare.Used(0.010, 0.004), 2u);
  EXPECT_DOUBLE_EQ(o[0], 5);
  EXPECT_DOUBLE_EQ(o[1], -3);
  EXPECT_DOUBLE_EQ(o[2], 1);
  EXPECT_DOUBLE_EQ(o[3], 8);
  // A larger clearance keeps only the highest reading.
  EXPECT_DOUBLE_EQ(tare.Offsets(0.010, 0.015)[3], 10);
}

TEST(AirTareTest, WithoutAReadingHighEnoughItSubtractsNothing) {
  AirTare tare;
  EXPECT_EQ(tare.Offsets(0, 0.004), (std::array<double, 4>{0, 0, 0, 0}));
  tare.Add({9, 9, 9, 9}, 0.001);
  EXPECT_EQ(tare.Used(0, 0.004), 0u);
  EXPECT_EQ(tare.Offsets(0, 0.004), (std::array<double, 4>{0, 0, 0, 0}));
}

TEST(AirTareTest, IgnoresNonFiniteReadingsAndKeepsTheFirstReadingsWhenFull) {
  AirTare tare;
  tare.Add({std::nan(""), 0, 0, 0}, 0.03);
  tare.Add({1, 1, 1, 1}, std::nan(""));
  EXPECT_EQ(tare.Used(0, 0), 0u);
  for (std::size_t i = 0; i < AirTare::kMaxReadings; ++i) tare.Add({2, 2, 2, 2}, 0.03);
  tare.Add({100, 100, 100, 100}, 0.03);  // beyond the capacity: dropped
  EXPECT_EQ(tare.Used(0, 0), AirTare::kMaxReadings);
  EXPECT_DOUBLE_EQ(tare.Offsets(0, 0)[0], 2);
}

}  // namespace
}  // namespace ssc
