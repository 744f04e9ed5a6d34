// Pure statistics the studies share: the Wilson interval of a success rate, Student's t (its
// two-sided p-value and 95 % quantile) and the regularised incomplete beta function behind it.
// No MuJoCo, no trials: numbers in, numbers out (tests/studies/statistics_test.cc).
#ifndef SSC_STUDIES_STATISTICS_INTERVALS_H_
#define SSC_STUDIES_STATISTICS_INTERVALS_H_

#include <array>

namespace ssc {

// Wilson score interval (95 %) of k successes in n trials ({0, 1} for n <= 0).
std::array<double, 2> WilsonInterval(int successes, int trials);

// The regularised incomplete beta function I_x(a, b) (a, b > 0, x in [0, 1]).
double RegularizedIncompleteBeta(double x, double a, double b);
// Two-sided p-value of Student's t with `dof` degrees of freedom (dof > 0).
double StudentTwoSidedP(double t, double dof);
// The two-sided 95 % Student t quantile for `dof` degrees of freedom (dof >= 1).
double StudentT95(double dof);

}  // namespace ssc

#endif  // SSC_STUDIES_STATISTICS_INTERVALS_H_
