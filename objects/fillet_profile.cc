#include "objects/fillet_profile.h"

#include <cmath>

namespace ssc {
namespace {

constexpr size_t kN = kFilletStationsM.size();

// Fritsch-Carlson tangents at the stations: the mean of the neighbouring slopes, scaled back
// where needed so that every piece stays monotone.
std::array<double, kN> Tangents() {
  const auto& x = kFilletStationsM;
  const auto& y = kFilletRadiiM;
  std::array<double, kN - 1> d{};
  for (size_t i = 0; i + 1 < kN; ++i) d[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  std::array<double, kN> m{};
  m[0] = d[0];
  m[kN - 1] = d[kN - 2];
  for (size_t i = 1; i + 1 < kN; ++i) m[i] = d[i - 1] * d[i] <= 0 ? 0 : 0.5 * (d[i - 1] + d[i]);
  for (size_t i = 0; i + 1 < kN; ++i) {
    if (d[i] == 0) {
      m[i] = m[i + 1] = 0;
      continue;
    }
    const double a = m[i] / d[i], b = m[i + 1] / d[i], s = a * a + b * b;
    if (s > 9) {  // outside the circle of radius 3: scale back to keep the piece monotone
      const double tau = 3 / std::sqrt(s);
      m[i] = tau * a * d[i];
      m[i + 1] = tau * b * d[i];
    }
  }
  return m;
}

}  // namespace

double FilletRadius(double x_m) {
  const auto& x = kFilletStationsM;
  const auto& y = kFilletRadiiM;
  if (x_m <= x.front()) return y.front();
  if (x_m >= x.back()) return y.back();
  static const std::array<double, kN> m = Tangents();
  size_t k = 0;
  while (k + 2 < kN && x_m > x[k + 1]) ++k;
  const double h = x[k + 1] - x[k], u = (x_m - x[k]) / h;
  const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
  const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
  return h00 * y[k] + h10 * h * m[k] + h01 * y[k + 1] + h11 * h * m[k + 1];
}

}  // namespace ssc
