// A re-tare of the four chambers in air, as a host can do it before following: the chambers'
// readings while the cup is still well above the object (all four then see the open cup's
// vacuum, about 0 Pa at the following pump duty) are each chamber's residual tare offset.
//
// The host records its readings on the way down (the approach), each with the tool's height;
// once the approach has settled (the hold height known), the readings taken at least
// clearance_m above the hold height are averaged per chamber. Nearer the object the cup's flow
// already builds a few Pa of vacuum, so those readings are left out. Allocation-free: the first
// kMaxReadings readings are kept.
#ifndef SSC_CONTROLLER_AIR_TARE_H_
#define SSC_CONTROLLER_AIR_TARE_H_

#include <array>
#include <cstddef>

namespace ssc {

class AirTare {
 public:
  static constexpr std::size_t kMaxReadings = 64;
  void Add(const std::array<double, 4>& p_pa, double tool_z_m);
  // Each chamber's offset, Pa: the mean reading of the readings at least clearance_m above
  // hold_z_m; zeros when there is none (nothing is subtracted then).
  std::array<double, 4> Offsets(double hold_z_m, double clearance_m) const;
  // How many readings Offsets averages.
  std::size_t Used(double hold_z_m, double clearance_m) const;

 private:
  std::array<std::array<double, 4>, kMaxReadings> p_pa_{};
  std::array<double, kMaxReadings> z_m_{};
  std::size_t count_ = 0;
};

}  // namespace ssc

#endif  // SSC_CONTROLLER_AIR_TARE_H_
