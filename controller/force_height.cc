#include "controller/force_height.h"

#include <algorithm>
#include <cmath>

namespace ssc {

double NextHeightOffsetM(const ForceHeightParams& p, double offset_m, double force_n) {
  if (!std::isfinite(force_n)) return offset_m;  // no reading: hold the height
  const double next = offset_m - p.gain_mm_per_n * 1e-3 * (p.force_n - force_n);
  return std::clamp(next, -p.max_down_mm * 1e-3, p.max_up_mm * 1e-3);
}

ControllerCommand ForceHeightController::Step(const ControllerInput& in) {
  ControllerCommand c;
  c.step_m = ComputeContourStep(in.p_pa, law_).step_m;
  offset_m_ = NextHeightOffsetM(p_, offset_m_, in.ft_normal_n);
  c.height_offset_m = offset_m_;
  return c;
}

ControllerType ForceHeightControllerType() {
  using P = ForceHeightParams;
  return MakeControllerType<ForceHeightController, P>(
      "force_height",
      "the published law's step; the height follows a normal-force target on the F/T",
      {{"force_n", "N", 0.1, 20, "normal-force target", &P::force_n},
       {"gain_mm_per_n", "mm/N", 0, 5, "height change per newton of force error per iteration",
        &P::gain_mm_per_n},
       {"max_down_mm", "mm", 0, 10, "deepest below the approach's hold height", &P::max_down_mm},
       {"max_up_mm", "mm", 0, 50, "highest above it", &P::max_up_mm}});
}

}  // namespace ssc
