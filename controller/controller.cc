#include "controller/controller.h"

#include <cmath>
#include <sstream>

namespace ssc {

std::string CheckControllerCommand(const ControllerCommand& c) {
  std::ostringstream os;
  const double step = std::hypot(c.step_m[0], c.step_m[1]);
  if (!std::isfinite(c.step_m[0]) || !std::isfinite(c.step_m[1])) {
    os << "step (" << c.step_m[0] << ", " << c.step_m[1] << ") m is not finite";
  } else if (step > kMaxCommandStepM) {
    os << "step length " << step << " m is out of range [0, " << kMaxCommandStepM << "] m";
  } else if (!std::isfinite(c.height_offset_m) || c.height_offset_m < kMinHeightOffsetM ||
             c.height_offset_m > kMaxHeightOffsetM) {
    os << "height offset " << c.height_offset_m << " m is out of range [" << kMinHeightOffsetM
       << ", " << kMaxHeightOffsetM << "] m";
  }
  return os.str();
}

}  // namespace ssc
