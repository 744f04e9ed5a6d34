// Force-regulated height: the published law's planar step, and a tool height that follows a
// normal-force target read on the F/T instead of holding the approach's height, so the lip
// keeps its compression where the surface falls away (a rounding) or rises.
//
// Per iteration: offset <- clamp(offset - gain_mm_per_n x (force_n - F), -max_down_mm,
// max_up_mm), an integral loop at the iteration rate: too little force takes the cup down.
// Against a contact of stiffness k (N/mm) it settles without overshoot while gain x k < 1.
#ifndef SSC_CONTROLLER_FORCE_HEIGHT_H_
#define SSC_CONTROLLER_FORCE_HEIGHT_H_

#include "controller/contour_law.h"
#include "controller/controller_registry.h"

namespace ssc {

struct ForceHeightParams {
  double force_n = 1.5;        // normal-force target (the start-up compression's), N
  double gain_mm_per_n = 0.3;  // height change per newton of force error per iteration
  double max_down_mm = 2.0;    // deepest below the approach's hold height
  double max_up_mm = 3.0;      // highest above it
};

// The next height offset, m (+ up), from the last one and the force read.
double NextHeightOffsetM(const ForceHeightParams& p, double offset_m, double force_n);

class ForceHeightController : public Controller {
 public:
  ForceHeightController(const ControllerContext& context, const ForceHeightParams& p)
      : law_(context.law), p_(p) {}
  ControllerCommand Step(const ControllerInput& in) override;

 private:
  ContourLawParams law_;
  ForceHeightParams p_;
  double offset_m_ = 0;
};

ControllerType ForceHeightControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_FORCE_HEIGHT_H_
