// Along the edge, turned toward the object by how far the mean vacuum is below P_ref.
#include "controller/example_controller.h"

#include <cmath>

namespace ssc {
struct ExampleParams {
  double gain = 2.0;  // turn toward the object per decade of mean vacuum below P_ref
};

class ExampleController : public Controller {
 public:
  ExampleController(const ControllerContext& c, const ExampleParams& p) : law_(c.law), p_(p) {}
  ControllerCommand Step(const ControllerInput& in) override {
    const auto& p = in.p_pa;  // chambers SE, NE, NW, SW; tool frame: +x south, +y west
    const double gx = -0.5 * (p[1] + p[2] - p[0] - p[3]), gy = 0.5 * (p[2] + p[3] - p[0] - p[1]);
    const double g = std::hypot(gx, gy);  // toward the object
    ControllerCommand c;
    if (g < law_.p_noise_pa) return c;  // no edge in sight: hold
    const double mean = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    const double toward = p_.gain * std::log10(law_.p_ref_pa / std::fmax(mean, 1.0));
    const double fx = (-gy + toward * gx) / g, fy = (gx + toward * gy) / g;  // object on the left
    const double scale = law_.step_mm * 1e-3 / std::hypot(fx, fy);
    c.step_m = {fx * scale, fy * scale};
    return c;
  }

 private:
  ContourLawParams law_;
  ExampleParams p_;
};

ControllerType ExampleControllerType() {
  return MakeControllerType<ExampleController, ExampleParams>(
      "example", "the worked example of docs/controllers.md (along the edge, toward P_ref)",
      {{"gain", "1", 0, 20, "turn toward the object per decade below P_ref",
        &ExampleParams::gain}});
}
}  // namespace ssc
