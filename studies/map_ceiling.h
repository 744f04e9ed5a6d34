// What any twin can expect to score against a published success map, as pure statistics (no
// MuJoCo).
//
// The published class of a cell is one draw of 3 robot trials. Even a twin with the robot's own
// success rate p in every cell lands in the published class only with probability P_p(class),
// so the map's scores have a ceiling set by the robot's repeatability, not by the twin. Nothing
// here sees the twin: it needs the published classes and a prior on the robot's rates.
//
// p ~ Beta(a, b) independently per cell (the prior); given the published class c the posterior
// is proportional to P_p(c) Beta(p; a, b). Two twins are scored against the published classes:
//   re-run   a twin with the robot's own rates p (the robot run again): E[P_p(c) | c];
//   oracle   a twin that knows p and reports the rate q*(p) that maximises the expected
//            agreement with a fresh 3-trial draw of the robot; no twin that does not see the
//            published draw can expect more: E[P_q*(p)(c) | c].
// Class match with 3 twin trials has the same expectation as the expected agreement.
#ifndef SSC_STUDIES_MAP_CEILING_H_
#define SSC_STUDIES_MAP_CEILING_H_

#include <array>
#include <string>
#include <vector>

#include "studies/scores/map_scores.h"

namespace ssc {

// Beta(a, b) on the robot's success rate in a cell. The functions below expect a and b in
// [kMinBetaPrior, kMaxBetaPrior]: the oracle's integrand sin^(2a-1) is finite from a = 0.5.
struct BetaPrior {
  double a = 1, b = 1;
};
constexpr double kMinBetaPrior = 0.5, kMaxBetaPrior = 1000;
// The goal for the class match (#11), which the ceilings are compared with.
constexpr double kClassMatchGoal = 0.75;

// P(class c) when p ~ Beta(a, b) and 3 trials are run (beta-binomial), exact.
double PriorClassProbability(MapClass c, const BetaPrior& prior);
// E[P_p(c) | c published]: the chance a re-run of the robot lands in its published class. Exact.
double RerunAgreement(MapClass c, const BetaPrior& prior);
// The rate q in [0, 1] that maximises sum_c P_p(c) P_q(c) (exact: the cubic's stationary point
// or an end).
double OracleRate(double p_success);
// E[P_q*(p)(c) | c published] (midpoint rule on p = sin^2(theta), 4000 nodes; |error| < 1e-4).
double OracleAgreement(MapClass c, const BetaPrior& prior);

// The maximum-likelihood prior for a map's class counts {3, 2, <=1} (the beta-binomial on the
// classes; Sbplx on log a, log b within the valid range). False + *error on an empty count.
bool FitClassPrior(const std::array<int, 3>& counts, BetaPrior* prior, std::string* error);

// P(at least k of the independent events happen), exact (Poisson-binomial).
double ProbabilityAtLeast(const std::vector<double>& probabilities, int k);

// A smooth surface for the robot's success rate over a map: logit p = w . (1, b, l, b^2, l^2, b l)
// with b, l the cell's beta and log10(P_ref) standardised over the map (the step is not a
// feature: a map of one step). Fitted by maximum likelihood of the published classes (Sbplx,
// weights within +-30). It borrows strength from neighbouring cells, which the per-cell priors
// do not: the in-sample figures are what a smooth robot would give, the leave-one-out agreement
// is how well 6 numbers fitted to the other cells predict each one (a baseline any twin with
// physics should beat).
struct SurfaceCeiling {
  double step_mm = 0;   // the step whose cells it was fitted to (one surface per step)
  bool fitted = false;  // false when the step has fewer than 8 cells or one beta or one P_ref
  std::array<double, 6> weights{};
  double negative_log_likelihood = 0;
  double rerun_agreement = 0, oracle_agreement = 0;        // in sample
  double loo_agreement = 0;                                // each cell from a fit to the others
  double rerun_reaches_goal = 0, oracle_reaches_goal = 0;  // in sample, as MapCeiling's
};
// The surface's success rate at each cell, from given weights.
std::vector<double> SurfaceRates(const std::vector<MapCell>& cells,
                                 const std::array<double, 6>& weights);
SurfaceCeiling FitSurfaceCeiling(const std::vector<MapCell>& cells, double class_match_goal);

struct MapCeiling {
  std::string prior_name;  // "fitted to the map's classes", "uniform", "Jeffreys"
  BetaPrior prior;
  double rerun_agreement = 0;   // mean over cells
  double oracle_agreement = 0;  // mean over cells
  // P(class match >= class_match_goal) for each twin (cells independent).
  double rerun_reaches_goal = 0, oracle_reaches_goal = 0;
};

struct MapCeilings {
  // Per-cell priors: fitted to the map's classes, uniform, Jeffreys.
  std::vector<MapCeiling> priors;
  // One surface per step of the map, in order of first appearance: the features hold no step,
  // so cells of different steps are never fitted together.
  std::vector<SurfaceCeiling> surfaces;
};
// Each cell's rate on its step's surface; NaN where that surface was not fitted.
std::vector<double> SurfaceRatesOfMap(const std::vector<MapCell>& cells,
                                      const MapCeilings& ceilings);
// Every ceiling of a map. False + *error when the map has no cells.
bool ComputeMapCeilings(const std::vector<MapCell>& cells, double class_match_goal,
                        MapCeilings* ceilings, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_MAP_CEILING_H_
