#include "studies/statistics/intervals.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

// Continued fraction of the incomplete beta (modified Lentz).
double BetaContinuedFraction(double x, double a, double b) {
  constexpr double kTiny = 1e-300, kEps = 1e-15;
  double c = 1, d = 1 - (a + b) * x / (a + 1);
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const double m2 = 2.0 * m;
    double num = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
    d = 1 + num * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1 + num / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    h *= d * c;
    num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
    d = 1 + num * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1 + num / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1) < kEps) break;
  }
  return h;
}

}  // namespace

std::array<double, 2> WilsonInterval(int k, int n) {
  if (n <= 0) return {0, 1};
  const double z = 1.959963984540054, p = static_cast<double>(k) / n;
  const double denom = 1 + z * z / n;
  const double centre = (p + z * z / (2.0 * n)) / denom;
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4.0 * n * n)) / denom;
  return {k == 0 ? 0.0 : std::max(0.0, centre - half), k == n ? 1.0 : std::min(1.0, centre + half)};
}

double RegularizedIncompleteBeta(double x, double a, double b) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  // The continued fraction converges fast for x < (a + 1) / (a + b + 2); else use the symmetry.
  if (x < (a + 1) / (a + b + 2)) return front * BetaContinuedFraction(x, a, b) / a;
  return 1 - front * BetaContinuedFraction(1 - x, b, a) / b;
}

double StudentTwoSidedP(double t, double dof) {
  if (!std::isfinite(t)) return 0;
  return RegularizedIncompleteBeta(dof / (dof + t * t), dof / 2, 0.5);
}

double StudentT95(double dof) {
  double lo = 1.0, hi = 100.0;  // t_0.975 lies in (1.96, 12.71] for dof >= 1
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (StudentTwoSidedP(mid, dof) > 0.05 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace ssc
