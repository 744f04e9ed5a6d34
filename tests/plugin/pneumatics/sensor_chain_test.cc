#include "plugin/pneumatics/sensor_chain.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

SensorChainState Fresh() {
  SensorChainState s;
  ResetSensorChain(&s);
  return s;
}

TEST(SensorChainTest, SampleIndexIsZeroOrderHold) {
  SensorChainParams p;
  p.sample_rate_hz = 160;
  EXPECT_EQ(SampleIndexAt(p, 0.0), 0);
  EXPECT_EQ(SampleIndexAt(p, 1.0 / 160 - 1e-6), 0);
  EXPECT_EQ(SampleIndexAt(p, 1.0 / 160), 1);
  EXPECT_EQ(SampleIndexAt(p, 10 * (1.0 / 160)), 10);  // rounding of k / rate stays in sample k
}

TEST(SensorChainTest, SameIndexNeverAdvances) {
  SensorChainParams p;
  SensorChainState s = Fresh();
  const std::array<double, 4> tap = {100, 0, 50, 200};
  EXPECT_EQ(TakeSamples(p, 0, tap, &s), 1);
  const auto first = FilteredOutput(s);
  EXPECT_EQ(TakeSamples(p, 0, tap, &s), 0);
  const auto again = FilteredOutput(s);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(first[c], again[c]);
}

TEST(SensorChainTest, MovingAverageOfTheLastSevenSamples) {
  SensorChainParams p;
  p.noise_pa = 0;
  SensorChainState s = Fresh();
  for (int k = 0; k < 20; ++k) {
    const double v = k;
    TakeSamples(p, k, {v, 2 * v, 0, 1}, &s);
  }
  // Samples 13..19 remain: mean 16.
  const auto out = FilteredOutput(s);
  EXPECT_DOUBLE_EQ(out[0], 16.0);
  EXPECT_DOUBLE_EQ(out[1], 32.0);
  EXPECT_DOUBLE_EQ(out[3], 1.0);
}

TEST(SensorChainTest, MissedSamplesAreFilledWithTheHeldValue) {
  SensorChainParams p;
  p.noise_pa = 0;
  SensorChainState s = Fresh();
  TakeSamples(p, 0, {0, 0, 0, 0}, &s);
  EXPECT_EQ(TakeSamples(p, 3, {70, 70, 70, 70}, &s), 3);  // samples 1, 2, 3
  EXPECT_DOUBLE_EQ(FilteredOutput(s)[0], 70.0 * 3 / 4);
}

TEST(SensorChainTest, NoiseIsCounterBasedAndHasTheConfiguredSigma) {
  EXPECT_EQ(CounterGaussian(7, 123, 2), CounterGaussian(7, 123, 2));
  EXPECT_NE(CounterGaussian(7, 123, 2), CounterGaussian(8, 123, 2));
  EXPECT_NE(CounterGaussian(7, 123, 2), CounterGaussian(7, 124, 2));
  EXPECT_NE(CounterGaussian(7, 123, 2), CounterGaussian(7, 123, 3));
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double g = CounterGaussian(3, k, k % 4);
    sum += g;
    sum2 += g * g;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(std::sqrt(sum2 / n), 1.0, 0.01);
}

TEST(SensorChainTest, OutputNoiseHasTheConfiguredSigmaBeforeAndAfterTheAverage) {
  // A constant tap pressure through the chain: single samples scatter with noise_pa around it,
  // the 7-sample average with noise_pa / sqrt(7) (disjoint windows are independent).
  // 20,000 samples: the sample sigma's relative standard error is 1 / sqrt(2 n) = 0.5 %, so 3 %
  // is six standard errors.
  for (int window : {1, 7}) {
    SensorChainParams p;
    p.noise_pa = 6.0;
    p.average_samples = window;
    SensorChainState s = Fresh();
    double sum = 0, sum2 = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < window; ++j) TakeSamples(p, k * window + j, {100, 100, 100, 100}, &s);
      const double v = FilteredOutput(s)[k % 4];
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
    const double expected = 6.0 / std::sqrt(static_cast<double>(window));
    EXPECT_NEAR(mean, 100.0, 5 * expected / std::sqrt(static_cast<double>(n))) << window;
    EXPECT_NEAR(sigma, expected, 0.03 * expected) << window;
  }
}

TEST(SensorChainTest, LagSmoothsASteps) {
  SensorChainParams p;
  p.noise_pa = 0;
  p.average_samples = 1;
  p.lag_s = 0.05;
  SensorChainState s = Fresh();
  TakeSamples(p, 0, {0, 0, 0, 0}, &s);
  TakeSamples(p, 1, {100, 100, 100, 100}, &s);
  const double expected = 100 * (1 - std::exp(-(1.0 / 160) / 0.05));
  EXPECT_NEAR(FilteredOutput(s)[0], expected, 1e-9);
}

TEST(SensorChainTest, ReseedGivesTheStateOfARunWithThatSeedToTheBit) {
  // A lagged chain fed a changing pressure, with gaps, through a wrapped window: reseeding the
  // state of seed 1 for seed 2 must give exactly the state of a run with seed 2.
  for (int window : {1, 7}) {
    SensorChainParams a, b;
    a.lag_s = b.lag_s = 0.02;
    a.average_samples = b.average_samples = window;
    a.seed = 1;
    b.seed = 2;
    SensorChainState sa = Fresh(), sb = Fresh();
    for (int k : {0, 1, 2, 5, 6, 7, 8, 9, 10, 11, 13, 30, 31}) {
      const double v = 100 + 10 * k;
      const std::array<double, 4> tap = {v, 2 * v, 0.5 * v, 1};
      TakeSamples(a, k, tap, &sa);
      TakeSamples(b, k, tap, &sb);
    }
    ASSERT_NE(FilteredOutput(sa)[0], FilteredOutput(sb)[0]);  // the seeds give other noise
    ReseedSensorChain(b, &sa);
    const auto oa = FilteredOutput(sa), ob = FilteredOutput(sb);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(oa[c], ob[c]) << window << " chamber " << c;
    const auto* ra = reinterpret_cast<const double*>(&sa);
    const auto* rb = reinterpret_cast<const double*>(&sb);
    for (int i = 0; i < kSensorChainStateSize; ++i) EXPECT_EQ(ra[i], rb[i]) << window << " " << i;
  }
}

TEST(SensorChainTest, ValidateNamesTheBadField) {
  SensorChainParams p;
  p.average_samples = 0;
  EXPECT_NE(p.Validate().find("average_samples"), std::string::npos);
  p = SensorChainParams{};
  p.sample_rate_hz = std::nan("");
  EXPECT_NE(p.Validate().find("sample_rate_hz"), std::string::npos);
}

}  // namespace
}  // namespace ssc
