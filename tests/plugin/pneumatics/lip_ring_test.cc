// The lip ring's bending alone: no MuJoCo.
#include "plugin/pneumatics/lip_ring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 5.5e-3;
constexpr double kEi = 0.6e-6;  // N m^2, the default lip

std::vector<double> Angles(int n) {
  std::vector<double> theta(n);
  for (int i = 0; i < n; ++i) theta[i] = 2 * kPi * (i + 0.5) / n;
  return theta;
}

TEST(LipRingTest, BendingEnergyIsZeroOnAnyPlane) {
  for (int n : {8, 16, 32}) {
    const std::vector<double> theta = Angles(n);
    std::vector<double> u(n);
    // Compressed 1 mm and tilted 5 degrees about an arbitrary axis.
    for (int i = 0; i < n; ++i) {
      u[i] = -1e-3 + std::tan(5 * kPi / 180) * kRadius * std::cos(theta[i] - 0.7);
    }
    EXPECT_NEAR(RingBendingEnergy(u.data(), theta.data(), n, kEi, kRadius), 0.0, 1e-18) << n;
  }
}

TEST(LipRingTest, BendingEnergyIsPositiveOverACorner) {
  // Half the ring pressed 1 mm up (on the object), half hanging (over a corner's open side).
  const int n = 16;
  const std::vector<double> theta = Angles(n);
  std::vector<double> u(n);
  for (int i = 0; i < n; ++i) u[i] = std::cos(theta[i]) > -0.3 ? -1e-3 : 0.0;
  const double e = RingBendingEnergy(u.data(), theta.data(), n, kEi, kRadius);
  EXPECT_GT(e, 1e-7);  // J
  // Stiffer lip, more energy; the cap limits it.
  EXPECT_NEAR(RingBendingEnergy(u.data(), theta.data(), n, 2 * kEi, kRadius), 2 * e, 1e-12);
  EXPECT_LT(RingBendingEnergy(u.data(), theta.data(), n, kEi, kRadius, 10.0), e);
}

TEST(LipRingTest, ForceIsMinusTheEnergyGradient) {
  const int n = 16;
  const std::vector<double> theta = Angles(n);
  std::vector<double> u(n);
  for (int i = 0; i < n; ++i) u[i] = 1e-4 * std::sin(3.0 * i) + 2e-4 * std::cos(theta[i]);
  std::vector<double> f(n, 0.0);
  AddRingBendingForce(u.data(), theta.data(), n, kEi, kRadius, 300.0, f.data());
  for (int i = 0; i < n; ++i) {
    std::vector<double> up = u, down = u;
    up[i] += 1e-8;
    down[i] -= 1e-8;
    const double grad = (RingBendingEnergy(up.data(), theta.data(), n, kEi, kRadius, 300.0) -
                         RingBendingEnergy(down.data(), theta.data(), n, kEi, kRadius, 300.0)) /
                        2e-8;
    EXPECT_NEAR(f[i], -grad, 1e-6 * (1 + std::fabs(grad))) << i;
  }
}

TEST(LipRingTest, ModeStiffnessMatchesTheContinuousRing) {
  // u = a cos(2 theta): E = 1/2 EI pi k^4 / R^3 a^2 for a thin ring.
  const int n = 32;
  const std::vector<double> theta = Angles(n);
  std::vector<double> u(n);
  const double a = 1e-4;
  for (int i = 0; i < n; ++i) u[i] = a * std::cos(2 * theta[i]);
  const double expected = 0.5 * kEi * kPi * 16 / std::pow(kRadius, 3) * a * a;
  EXPECT_NEAR(RingBendingEnergy(u.data(), theta.data(), n, kEi, kRadius), expected,
              1e-9 * expected);
}

}  // namespace
}  // namespace ssc
