// Small dense linear systems (the least-squares fits' normal equations). Pure C++, header-only.
#ifndef SSC_GEOMETRY_LINEAR_SOLVE_H_
#define SSC_GEOMETRY_LINEAR_SOLVE_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace ssc {

// Solves the n x n system a x = b (n <= 3) by elimination with partial pivoting; false when
// singular relative to the matrix's scale.
template <std::size_t N>
inline bool Solve(std::array<std::array<double, N>, N> a, std::array<double, N> b,
                  std::array<double, N>* x) {
  double scale = 0;
  for (const auto& row : a)
    for (double v : row) scale = std::max(scale, std::fabs(v));
  if (!(scale > 0)) return false;
  for (std::size_t c = 0; c < N; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < N; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    if (std::fabs(a[pivot][c]) < 1e-12 * scale) return false;
    std::swap(a[c], a[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < N; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < N; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = N; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < N; ++k) s -= a[c][k] * (*x)[k];
    (*x)[c] = s / a[c][c];
  }
  return true;
}

}  // namespace ssc

#endif  // SSC_GEOMETRY_LINEAR_SOLVE_H_
