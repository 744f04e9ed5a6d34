// The published contour law (controller/contour_law.h) as a controller: each iteration's
// step is ComputeContourStep's with the trial's ContourLawParams; the height is held. It has no
// parameters of its own (P_ref, beta, dL, P_n and P_g are the law's options).
#ifndef SSC_CONTROLLER_PUBLISHED_CONTROLLER_H_
#define SSC_CONTROLLER_PUBLISHED_CONTROLLER_H_

#include "controller/contour_law.h"
#include "controller/controller_registry.h"

namespace ssc {

struct PublishedControllerParams {};

class PublishedController : public Controller {
 public:
  PublishedController(const ControllerContext& context, const PublishedControllerParams&)
      : law_(context.law) {}
  ControllerCommand Step(const ControllerInput& in) override;

 private:
  ContourLawParams law_;
};

ControllerType PublishedControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_PUBLISHED_CONTROLLER_H_
