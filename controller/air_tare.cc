#include "controller/air_tare.h"

#include <cmath>

namespace ssc {

void AirTare::Add(const std::array<double, 4>& p_pa, double tool_z_m) {
  if (count_ >= kMaxReadings) return;
  for (double v : p_pa)
    if (!std::isfinite(v)) return;
  if (!std::isfinite(tool_z_m)) return;
  p_pa_[count_] = p_pa;
  z_m_[count_] = tool_z_m;
  ++count_;
}

std::size_t AirTare::Used(double hold_z_m, double clearance_m) const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < count_; ++i)
    if (z_m_[i] >= hold_z_m + clearance_m) ++n;
  return n;
}

std::array<double, 4> AirTare::Offsets(double hold_z_m, double clearance_m) const {
  std::array<double, 4> sum{};
  std::size_t n = 0;
  for (std::size_t i = 0; i < count_; ++i) {
    if (z_m_[i] < hold_z_m + clearance_m) continue;
    for (std::size_t k = 0; k < 4; ++k) sum[k] += p_pa_[i][k];
    ++n;
  }
  if (n == 0) return {0, 0, 0, 0};
  for (double& v : sum) v /= static_cast<double>(n);
  return sum;
}

}  // namespace ssc
