#include "calibration/nelder_mead.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ssc {

NelderMeadResult NelderMead(const std::function<double(const std::vector<double>&)>& f,
                            const std::vector<double>& x0, const std::vector<double>& step,
                            double tolerance, int max_evaluations) {
  const size_t n = x0.size();
  std::vector<std::vector<double>> s(n + 1, x0);
  for (size_t i = 0; i < n; ++i) s[i + 1][i] += step[i];
  std::vector<double> v(n + 1);
  NelderMeadResult r;
  auto eval = [&](const std::vector<double>& x) {
    ++r.evaluations;
    const double y = f(x);
    return std::isfinite(y) ? y : 1e300;
  };
  for (size_t i = 0; i <= n; ++i) v[i] = eval(s[i]);
  std::vector<size_t> order(n + 1);
  while (r.evaluations < max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
    const size_t best = order[0], worst = order[n], second = order[n - 1];
    if (std::fabs(v[worst] - v[best]) <= tolerance * (1 + std::fabs(v[best]))) {
      r.converged = true;
      break;
    }
    std::vector<double> c(n, 0.0);
    for (size_t i = 0; i <= n; ++i) {
      if (i == worst) continue;
      for (size_t k = 0; k < n; ++k) c[k] += s[i][k] / static_cast<double>(n);
    }
    auto along = [&](double t) {
      std::vector<double> p(n);
      for (size_t k = 0; k < n; ++k) p[k] = c[k] + t * (s[worst][k] - c[k]);
      return p;
    };
    const std::vector<double> xr = along(-1.0);
    const double fr = eval(xr);
    if (fr < v[best]) {
      const std::vector<double> xe = along(-2.0);
      const double fe = eval(xe);
      if (fe < fr) {
        s[worst] = xe;
        v[worst] = fe;
      } else {
        s[worst] = xr;
        v[worst] = fr;
      }
    } else if (fr < v[second]) {
      s[worst] = xr;
      v[worst] = fr;
    } else {
      const std::vector<double> xc = along(fr < v[worst] ? -0.5 : 0.5);
      const double fc = eval(xc);
      if (fc < std::min(fr, v[worst])) {
        s[worst] = xc;
        v[worst] = fc;
      } else {  // shrink toward the best vertex
        for (size_t i = 0; i <= n; ++i) {
          if (i == best) continue;
          for (size_t k = 0; k < n; ++k) s[i][k] = s[best][k] + 0.5 * (s[i][k] - s[best][k]);
          v[i] = eval(s[i]);
        }
      }
    }
  }
  const size_t best = static_cast<size_t>(std::min_element(v.begin(), v.end()) - v.begin());
  r.x = s[best];
  r.value = v[best];
  return r;
}

}  // namespace ssc
