#include "controller/published_controller.h"

namespace ssc {

ControllerCommand PublishedController::Step(const ControllerInput& in) {
  ControllerCommand c;
  c.step_m = ComputeContourStep(in.p_pa, law_).step_m;
  return c;
}

ControllerType PublishedControllerType() {
  ControllerType t;
  t.name = "published";
  t.what =
      "the published contour law (P_ref, beta, dL, P_n, P_g from the law's options); height held";
  t.make = [](const ControllerContext& context, const ControllerValues&) {
    return std::unique_ptr<Controller>(new PublishedController(context, {}));
  };
  return t;
}

}  // namespace ssc
