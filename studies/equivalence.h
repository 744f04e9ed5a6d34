// Whether two models of the cup give the same statistics on a published map's cells, as pure
// statistics (no MuJoCo). `ssc equivalence` runs both on the same cells and seeds
// (studies/equivalence_study.h) and hands the counts here.
//
// A trial of the twin is a draw (sensor noise, the robot effects' step errors), so two models
// that are equally faithful still give different rows; what must agree is the distribution.
// Three views, each against what chance alone gives:
//   cells     per cell the two success counts and Fisher's exact test of their difference; the
//             number of cells that differ at `alpha` against its distribution when the two
//             models are the same (each cell's exact chance of a false alarm given its margins:
//             Fisher's test is discrete, so that chance is below alpha and often 0);
//   score     the difference of the expected agreement with the published classes (the map
//             score of `ssc validate`, studies/scores/map_scores.h) with a 95 % posterior interval;
//   targets   the published Fig. 6 targets (means over the successful trials) side by side with
//             their standard errors and Welch's test of their difference.
// The two arms share their seeds, which makes their outcomes positively correlated; every test
// here treats them as independent samples, which for positively correlated arms overstates the
// variance of a difference: the tests are conservative, never anti-conservative.
#ifndef SSC_STUDIES_EQUIVALENCE_H_
#define SSC_STUDIES_EQUIVALENCE_H_

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "studies/scores/map_scores.h"

namespace ssc {

// Two-sided Fisher exact test of k_a successes in n_a trials against k_b in n_b: the total
// probability, given both margins, of the tables no more probable than the observed one
// (relative tolerance 1e-7, as R's fisher.test). 1 when either arm has no trials.
double FisherExactP(int k_a, int n_a, int k_b, int n_b);

// The chance that Fisher's test rejects at `alpha` when both arms share one success rate, given
// the arms' sizes and their total successes (exact: the hypergeometric law of the table). At
// most alpha; 0 when no table with these margins can reach alpha (e.g. 20 successes of 20).
double FisherFalseAlarmChance(int n_a, int n_b, int successes, double alpha);

// One arm's trials in a cell.
struct ArmCounts {
  int successes = 0, trials = 0;
};

struct CellDifference {
  MapCell cell;
  ArmCounts a, b;
  double rate_a = 0, rate_b = 0;            // successes / trials
  double agreement_a = 0, agreement_b = 0;  // P(3 trials land in the published class)
  double p_value = 1;                       // Fisher, two-sided
  bool differs = false;                     // p_value <= alpha
  double false_alarm_chance = 0;            // FisherFalseAlarmChance of its margins
};

// How many cells differ, against chance.
struct DifferingCells {
  int cells = 0, differing = 0;
  double alpha = 0.05;
  double nominal_by_chance = 0;   // alpha x cells: a continuous test's expectation
  double expected_by_chance = 0;  // sum of the cells' exact false-alarm chances (<= nominal)
  // P(at least `differing` cells | the two models are the same): the Poisson-binomial tail over
  // the cells' false-alarm chances. Small: more cells differ than chance gives.
  double p_at_least = 1;
};

// A shift of the success rate common to the cells: the Cochran-Mantel-Haenszel test (each cell a
// stratum, continuity-corrected, 1 degree of freedom). It pools the cells, so it finds a small
// shift in the same direction everywhere that no single cell's test can see at 10 seeds.
struct SuccessShift {
  int successes_a = 0, successes_b = 0, trials_a = 0, trials_b = 0;
  double p_value = 1;
};

struct ScoreDifference {
  double a = 0, b = 0;               // mean expected agreement of each arm
  double difference = 0;             // b - a
  std::array<double, 2> interval{};  // 95 %, b - a (each cell's rate from its Jeffreys posterior)
  // Two-sided posterior tail: 2 min(P(b - a <= 0), P(b - a >= 0)) over the draws.
  double p_value = 1;
};

// A Fig. 6 target as one arm measured it (MetricTarget's numbers, without MuJoCo types).
struct TargetMeasure {
  std::string name;
  double published = 0, tolerance = 0;
  double mean = std::numeric_limits<double>::quiet_NaN();
  double standard_error = std::numeric_limits<double>::quiet_NaN();
  int n = 0;  // successful trials the mean is over
};

struct TargetDifference {
  std::string name;
  double published = 0, tolerance = 0;
  TargetMeasure a, b;
  double difference = std::numeric_limits<double>::quiet_NaN();      // b - a
  double standard_error = std::numeric_limits<double>::quiet_NaN();  // of the difference
  double dof = std::numeric_limits<double>::quiet_NaN();             // Welch-Satterthwaite
  double p_value = std::numeric_limits<double>::quiet_NaN();         // Welch, two-sided
  bool tested = false;  // both arms have at least 2 successes and a spread
  bool differs = false;
};

struct EquivalenceOptions {
  double alpha = 0.05;
  int draws = 4000;             // posterior draws for the score interval
  unsigned long long seed = 1;  // of those draws (deterministic)
};

struct Equivalence {
  std::vector<CellDifference> cells;
  DifferingCells differing;
  SuccessShift shift;
  ScoreDifference score;
  std::vector<TargetDifference> targets;
  int targets_tested = 0, targets_differing = 0;
  double targets_p_at_least = 1;  // binomial tail of targets_differing at alpha
  // The verdict is one test of "the two models differ", of size alpha: each view's p-value
  // (the cells' tail, the common shift, the score's posterior tail, the targets' tail when any
  // target was tested) against alpha / views (Bonferroni). Each flag is that view's part.
  int views = 0;
  bool cells_beyond_chance = false, shift_differs = false, score_differs = false,
       targets_beyond_chance = false;
  bool same = true;
};

// Compares arm b with arm a (the reference) on the same cells (a[i], b[i] the cells[i] counts)
// and targets (matched by name; a target only one arm has is left out). False + *error when the
// lists differ in length, a cell has no trials, or alpha is not in (0, 1).
bool CompareArms(const std::vector<MapCell>& cells, const std::vector<ArmCounts>& a,
                 const std::vector<ArmCounts>& b, const std::vector<TargetMeasure>& targets_a,
                 const std::vector<TargetMeasure>& targets_b, const EquivalenceOptions& options,
                 Equivalence* result, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_EQUIVALENCE_H_
