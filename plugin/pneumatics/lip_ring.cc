#include "plugin/pneumatics/lip_ring.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Visits modes k = 2 .. n/2 with the segments' projections onto them: for 2 <= k < n/2 the
// cosine and sine coefficients (2/n) sum u cos, (2/n) sum u sin; at k = n/2 (even n) the
// alternating mode (-1)^i with coefficient (1/n) sum u (-1)^i, which sampled rings cannot tell
// from its sine twin. visit(k, a, b, nyquist, cos_k, sin_k) sees the coefficients and the mode's
// shape at the segments.
template <typename Visit>
void ForEachBendingMode(const double* u, const RingModeShapes& shapes, Visit visit) {
  const int n = shapes.n;
  for (int k = 2; 2 * k <= n; ++k) {
    const bool nyquist = 2 * k == n;
    const double* cos_k = shapes.cos_k.data() + (k - 2) * n;
    const double* sin_k = shapes.sin_k.data() + (k - 2) * n;
    double a = 0, b = 0;
    for (int i = 0; i < n; ++i) {
      if (nyquist) {
        a += (i % 2 == 0 ? u[i] : -u[i]);
      } else {
        a += u[i] * cos_k[i];
        b += u[i] * sin_k[i];
      }
    }
    const double scale = nyquist ? 1.0 / n : 2.0 / n;
    visit(k, a * scale, b * scale, nyquist, cos_k, sin_k);
  }
}

}  // namespace

double RingModeStiffness(int k, int n_segments, double bending_stiffness_nm2, double radius_m) {
  if (n_segments <= 0 || radius_m <= 0) return 0.0;
  const double k2 = double(k) * k;
  return 2.0 * kPi * bending_stiffness_nm2 * k2 * k2 /
         (n_segments * radius_m * radius_m * radius_m);
}

RingModeShapes MakeRingModeShapes(const double* theta_rad, int n) {
  RingModeShapes shapes;
  shapes.n = n;
  const int modes = n >= 4 ? n / 2 - 1 : 0;
  shapes.cos_k.resize(static_cast<std::size_t>(modes * n));
  shapes.sin_k.resize(static_cast<std::size_t>(modes * n));
  for (int k = 2; 2 * k <= n; ++k) {
    for (int i = 0; i < n; ++i) {
      const std::size_t at = static_cast<std::size_t>((k - 2) * n + i);
      shapes.cos_k[at] = std::cos(k * theta_rad[i]);
      shapes.sin_k[at] = std::sin(k * theta_rad[i]);
    }
  }
  return shapes;
}

double RingBendingEnergy(const double* u, const RingModeShapes& shapes,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m) {
  const int n = shapes.n;
  double energy = 0.0;
  ForEachBendingMode(
      u, shapes, [&](int k, double a, double b, bool nyquist, const double*, const double*) {
        const double lambda =
            std::min(RingModeStiffness(k, n, bending_stiffness_nm2, radius_m), mode_cap_n_per_m);
        // 1/2 u.K u with K = lambda P_k: |P_k u|^2 = (n/2)(a^2 + b^2), or n a^2 for the alternating
        // mode.
        const double norm2 = nyquist ? n * a * a : 0.5 * n * (a * a + b * b);
        energy += 0.5 * lambda * norm2;
      });
  return energy;
}

void AddRingBendingForce(const double* u, const RingModeShapes& shapes,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m,
                         double* force) {
  const int n = shapes.n;
  ForEachBendingMode(
      u, shapes,
      [&](int k, double a, double b, bool nyquist, const double* cos_k, const double* sin_k) {
        const double lambda =
            std::min(RingModeStiffness(k, n, bending_stiffness_nm2, radius_m), mode_cap_n_per_m);
        for (int i = 0; i < n; ++i) {
          const double projected = nyquist ? (i % 2 == 0 ? a : -a) : a * cos_k[i] + b * sin_k[i];
          force[i] -= lambda * projected;
        }
      });
}

double RingBendingEnergy(const double* u, const double* theta_rad, int n,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m) {
  return RingBendingEnergy(u, MakeRingModeShapes(theta_rad, n), bending_stiffness_nm2, radius_m,
                           mode_cap_n_per_m);
}

void AddRingBendingForce(const double* u, const double* theta_rad, int n,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m,
                         double* force) {
  AddRingBendingForce(u, MakeRingModeShapes(theta_rad, n), bending_stiffness_nm2, radius_m,
                      mode_cap_n_per_m, force);
}

}  // namespace ssc
