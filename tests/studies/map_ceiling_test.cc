// What any twin can expect against a map of 3-trial classes (studies/map_ceiling.h), against
// values worked by hand.
#include "studies/map_ceiling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ssc {
namespace {

constexpr MapClass kThree = MapClass::kThreeOfThree;
constexpr MapClass kTwo = MapClass::kTwoOfThree;
constexpr MapClass kAtMostOne = MapClass::kAtMostOne;

TEST(MapCeilingTest, BetaBinomialClassProbabilitiesByHand) {
  // Uniform prior: every k of 3 has probability 1/4.
  EXPECT_NEAR(PriorClassProbability(kThree, {1, 1}), 0.25, 1e-12);
  EXPECT_NEAR(PriorClassProbability(kTwo, {1, 1}), 0.25, 1e-12);
  EXPECT_NEAR(PriorClassProbability(kAtMostOne, {1, 1}), 0.5, 1e-12);
  // Jeffreys: P(3) = B(3.5, 0.5) / B(0.5, 0.5) = 5/16; P(2) = 3 B(2.5, 1.5) / pi = 3/16.
  EXPECT_NEAR(PriorClassProbability(kThree, {0.5, 0.5}), 5.0 / 16, 1e-12);
  EXPECT_NEAR(PriorClassProbability(kTwo, {0.5, 0.5}), 3.0 / 16, 1e-12);
  EXPECT_NEAR(PriorClassProbability(kAtMostOne, {0.5, 0.5}), 0.5, 1e-12);
}

TEST(MapCeilingTest, RerunAgreementUnderTheUniformPriorByHand) {
  // Published 3/3: posterior Beta(4, 1), E[p^3] = 4/7.
  EXPECT_NEAR(RerunAgreement(kThree, {1, 1}), 4.0 / 7, 1e-12);
  // Published 2/3: posterior Beta(3, 2), 3 (E[p^2] - E[p^3]) = 3 (2/5 - 2/7) = 12/35.
  EXPECT_NEAR(RerunAgreement(kTwo, {1, 1}), 12.0 / 35, 1e-12);
  // Published <= 1/3: P = 1 - 3p^2 + 2p^3; int P^2 dp = 13/35 over int P dp = 1/2.
  EXPECT_NEAR(RerunAgreement(kAtMostOne, {1, 1}), 26.0 / 35, 1e-12);
}

TEST(MapCeilingTest, OracleRateIsTheBestReplyToADraw) {
  EXPECT_EQ(OracleRate(1.0), 1.0);
  EXPECT_EQ(OracleRate(0.9), 1.0);
  EXPECT_EQ(OracleRate(0.1), 0.0);
  // At p = 0.5 the cubic's q^3 term vanishes and f falls from q = 0: report "at most 1 of 3".
  EXPECT_EQ(OracleRate(0.5), 0.0);
  // At p = 0.6, (A, B, C) = (0.216, 0.432, 0.352): stationary point -2 (B - C) / (A - 3B + 2C)
  // = 0.16 / 0.376, where f = 0.3665 beats f(0) = 0.352 and f(1) = 0.216.
  EXPECT_NEAR(OracleRate(0.6), 0.16 / 0.376, 1e-12);
  // No rate does better against a fresh draw than the oracle's, on a grid.
  for (double p = 0; p <= 1.0; p += 0.05) {
    const double q_star = OracleRate(p);
    const auto agreement = [&](double q) {
      return ClassProbability(kThree, p) * ClassProbability(kThree, q) +
             ClassProbability(kTwo, p) * ClassProbability(kTwo, q) +
             ClassProbability(kAtMostOne, p) * ClassProbability(kAtMostOne, q);
    };
    for (double q = 0; q <= 1.0; q += 0.01) EXPECT_GE(agreement(q_star), agreement(q) - 1e-12);
  }
}

TEST(MapCeilingTest, OracleAgreementOnAConcentratedPriorAndOnAverage) {
  // Every cell at p = 0.5: the oracle always says "<= 1", right exactly when that was published.
  const BetaPrior half{1000, 1000};
  EXPECT_NEAR(OracleAgreement(kAtMostOne, half), 1.0, 1e-6);
  EXPECT_NEAR(OracleAgreement(kThree, half), 0.0, 1e-6);
  EXPECT_NEAR(OracleAgreement(kTwo, half), 0.0, 1e-6);
  // Against an independent quadrature (numpy, 2 million nodes in theta, the same candidates for
  // q*): uniform prior 0.77683 / 0.10210 / 0.91068, Jeffreys 0.88181 / 0.09176 / 0.93463.
  EXPECT_NEAR(OracleAgreement(kThree, {1, 1}), 0.77683, 1e-4);
  EXPECT_NEAR(OracleAgreement(kTwo, {1, 1}), 0.10210, 1e-4);
  EXPECT_NEAR(OracleAgreement(kAtMostOne, {1, 1}), 0.91068, 1e-4);
  EXPECT_NEAR(OracleAgreement(kThree, {0.5, 0.5}), 0.88181, 1e-4);
  EXPECT_NEAR(OracleAgreement(kTwo, {0.5, 0.5}), 0.09176, 1e-4);
  EXPECT_NEAR(OracleAgreement(kAtMostOne, {0.5, 0.5}), 0.93463, 1e-4);
  // Averaged over what the prior publishes, knowing p never does worse than being the robot.
  for (BetaPrior prior : {BetaPrior{1, 1}, BetaPrior{0.5, 0.5}, BetaPrior{2.1, 1.5}}) {
    double oracle = 0, rerun = 0;
    for (MapClass c : {kThree, kTwo, kAtMostOne}) {
      oracle += PriorClassProbability(c, prior) * OracleAgreement(c, prior);
      rerun += PriorClassProbability(c, prior) * RerunAgreement(c, prior);
    }
    EXPECT_GT(oracle, rerun) << prior.a << ", " << prior.b;
  }
}

TEST(MapCeilingTest, FittedPriorReproducesTheClassFrequencies) {
  // Two parameters, two free frequencies: the maximum-likelihood prior reproduces them.
  for (std::array<int, 3> counts : {std::array<int, 3>{13, 14, 18}, std::array<int, 3>{25, 25, 50},
                                    std::array<int, 3>{2000, 2400, 2600}}) {
    BetaPrior prior;
    std::string error;
    ASSERT_TRUE(FitClassPrior(counts, &prior, &error)) << error;
    const double n = counts[0] + counts[1] + counts[2];
    EXPECT_NEAR(PriorClassProbability(kThree, prior), counts[0] / n, 1e-4);
    EXPECT_NEAR(PriorClassProbability(kTwo, prior), counts[1] / n, 1e-4);
  }
  // A quarter, a quarter, a half is the uniform prior; 2/7, 12/35, 13/35 is Beta(3, 2)'s.
  BetaPrior prior;
  std::string error;
  ASSERT_TRUE(FitClassPrior({25, 25, 50}, &prior, &error));
  EXPECT_NEAR(prior.a, 1.0, 1e-3);
  EXPECT_NEAR(prior.b, 1.0, 1e-3);
  ASSERT_TRUE(FitClassPrior({2000, 2400, 2600}, &prior, &error));
  EXPECT_NEAR(prior.a, 3.0, 1e-2);
  EXPECT_NEAR(prior.b, 2.0, 1e-2);
  // Too few 2/3 cells for any Beta prior in range (it would need a, b < 0.5): the fit stops at
  // the range's edge.
  ASSERT_TRUE(FitClassPrior({30, 10, 20}, &prior, &error));
  EXPECT_NEAR(std::min(prior.a, prior.b), kMinBetaPrior, 1e-6);
  EXPECT_FALSE(FitClassPrior({0, 0, 0}, &prior, &error));
  EXPECT_NE(error.find("class counts"), std::string::npos) << error;
}

TEST(MapCeilingTest, ProbabilityAtLeastIsPoissonBinomial) {
  EXPECT_NEAR(ProbabilityAtLeast({0.5, 0.5}, 1), 0.75, 1e-15);
  EXPECT_NEAR(ProbabilityAtLeast({0.5, 0.5}, 2), 0.25, 1e-15);
  EXPECT_NEAR(ProbabilityAtLeast({0.2, 0.5, 0.9}, 2),
              0.2 * 0.5 * 0.1 + 0.2 * 0.5 * 0.9 + 0.2 * 0.5 * 0.9 + 0.8 * 0.5 * 0.9, 1e-15);
  EXPECT_EQ(ProbabilityAtLeast({0.3}, 0), 1.0);
  EXPECT_EQ(ProbabilityAtLeast({0.3}, 2), 0.0);
}

TEST(MapCeilingTest, CeilingsOfAMap) {
  // 4 cells published 3/3, 4 at 2/3, 8 at <= 1/3: the fitted prior is the uniform one.
  std::vector<MapCell> cells;
  for (int i = 0; i < 16; ++i) {
    cells.push_back({5, 1, 100, i < 4 ? kThree : (i < 8 ? kTwo : kAtMostOne)});
  }
  MapCeilings all;
  std::string error;
  ASSERT_TRUE(ComputeMapCeilings(cells, 0.75, &all, &error)) << error;
  const std::vector<MapCeiling>& ceilings = all.priors;
  ASSERT_EQ(ceilings.size(), 3u);
  const double rerun = (4 * 4.0 / 7 + 4 * 12.0 / 35 + 8 * 26.0 / 35) / 16;
  EXPECT_NEAR(ceilings[0].rerun_agreement, rerun, 1e-3);  // fitted = uniform, to the fit
  EXPECT_NEAR(ceilings[1].rerun_agreement, rerun, 1e-12);
  EXPECT_EQ(ceilings[2].prior.a, 0.5);
  for (const MapCeiling& c : ceilings) {
    EXPECT_GT(c.rerun_reaches_goal, 0.0);
    EXPECT_LT(c.rerun_reaches_goal, 1.0);
    EXPECT_GE(c.oracle_agreement, 0.0);
    EXPECT_LE(c.oracle_agreement, 1.0);
  }
  ASSERT_EQ(all.surfaces.size(), 1u);
  EXPECT_FALSE(all.surfaces[0].fitted);  // one beta, one P_ref
  EXPECT_FALSE(ComputeMapCeilings({}, 0.75, &all, &error));
  EXPECT_NE(error.find("no cells"), std::string::npos);
}

// The map's classes drawn as the likeliest class of a known smooth surface: the fit explains
// them at least as well as that surface does, and borrows strength the per-cell prior cannot.
TEST(MapCeilingTest, SurfaceFitsAMapDrawnFromASurface) {
  std::vector<MapCell> cells;
  for (double beta = 0.5; beta <= 4.0; beta += 0.5) {
    for (double pref : {40.0, 70.0, 100.0, 150.0, 200.0, 300.0}) {
      cells.push_back({5, beta, pref, kThree});
    }
  }
  const std::array<double, 6> truth = {2.0, 0.5, -1.5, -1.5, -0.5, -0.5};
  const std::vector<double> p_true = SurfaceRates(cells, truth);
  double truth_nll = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double p3 = ClassProbability(kThree, p_true[i]), p2 = ClassProbability(kTwo, p_true[i]);
    const double p1 = ClassProbability(kAtMostOne, p_true[i]);
    cells[i].published = p3 >= p2 && p3 >= p1 ? kThree : (p2 >= p1 ? kTwo : kAtMostOne);
    truth_nll -= std::log(ClassProbability(cells[i].published, p_true[i]));
  }
  const SurfaceCeiling s = FitSurfaceCeiling(cells, 0.75);
  ASSERT_TRUE(s.fitted);
  EXPECT_LE(s.negative_log_likelihood, truth_nll + 1e-9);
  double rerun = 0;
  const std::vector<double> p_fit = SurfaceRates(cells, s.weights);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    rerun += ClassProbability(cells[i].published, p_fit[i]) / static_cast<double>(cells.size());
  }
  EXPECT_NEAR(s.rerun_agreement, rerun, 1e-12);
  MapCeilings all;
  std::string error;
  ASSERT_TRUE(ComputeMapCeilings(cells, 0.75, &all, &error)) << error;
  EXPECT_GT(s.rerun_agreement, all.priors[0].rerun_agreement);
  EXPECT_GT(s.loo_agreement, 0.0);
  EXPECT_LE(s.loo_agreement, s.rerun_agreement + 0.05);

  // The same map at a second step with every class "<= 1": one surface per step, each the fit
  // of its own cells alone, and each cell's rate from its own step's surface.
  std::vector<MapCell> two_steps = cells;
  for (MapCell cell : cells) {
    cell.step_mm = 7.5;
    cell.published = kAtMostOne;
    two_steps.push_back(cell);
  }
  ASSERT_TRUE(ComputeMapCeilings(two_steps, 0.75, &all, &error)) << error;
  ASSERT_EQ(all.surfaces.size(), 2u);
  EXPECT_EQ(all.surfaces[0].step_mm, 5.0);
  EXPECT_EQ(all.surfaces[1].step_mm, 7.5);
  EXPECT_DOUBLE_EQ(all.surfaces[0].negative_log_likelihood, s.negative_log_likelihood);
  const std::vector<double> rates = SurfaceRatesOfMap(two_steps, all);
  EXPECT_NEAR(rates[0], p_fit[0], 1e-12);
  for (std::size_t i = cells.size(); i < two_steps.size(); ++i) EXPECT_LT(rates[i], 0.05);
}

}  // namespace
}  // namespace ssc
