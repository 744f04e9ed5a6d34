// Crimp recovery: the published law, and a hop over the place where the lip crimps.
//
// At a concave corner the published cup stalled: its lip folded (crimped) where the corner
// pressed it, and the chamber behind the fold leaked while the others stayed sealed. The
// detector reads that signature: for `stall_iterations` iterations in a row, one chamber below
// `leak_ratio` times the least of the other three, those three above P_ref, and the cup moved
// less than `stall_share` of what its steps (the law's dL) would have taken it over the window
// (a concave corner passed at the law's pace shows the same chambers, but moves). The hop then
// lifts the cup by lift_mm (lifted: the failure checks wait), moves it hop_mm along the edge as
// last followed, comes down in steps of descend_mm until the F/T reads force_n again (the
// approach's force band), and resumes.
#ifndef SSC_CONTROLLER_CRIMP_HOP_H_
#define SSC_CONTROLLER_CRIMP_HOP_H_

#include <array>
#include <deque>

#include "controller/contour_law.h"
#include "controller/controller_registry.h"

namespace ssc {

struct CrimpHopParams {
  double leak_ratio = 0.2;      // a crimped chamber reads below this x the least other one
  double stall_iterations = 4;  // iterations in a row with the signature
  double stall_share = 0.25;    // ... while it moved less than this share of its steps
  double lift_mm = 4.0;         // hop height above the hold height
  double hop_mm = 10.0;         // move along the edge while lifted
  double descend_mm = 1.0;      // height change per iteration coming down
  double force_n = 1.0;         // F/T force that ends the descent (back in contact)
};

// The crimp signature in one sample: one chamber leaking while the other three are sealed.
bool CrimpSignature(const CrimpHopParams& p, const std::array<double, 4>& p_pa, double p_ref_pa);

// The signature held for stall_iterations while the cup stalls.
class CrimpDetector {
 public:
  explicit CrimpDetector(const CrimpHopParams& p) : p_(p) {}
  // One iteration's pressures, tool position (world, m) and step length (m); true when a crimp
  // is detected.
  bool Update(const std::array<double, 4>& p_pa, double p_ref_pa, const std::array<double, 2>& xy,
              double step_m);
  void Reset() { window_.clear(); }

 private:
  CrimpHopParams p_;
  std::deque<std::array<double, 2>> window_;  // positions while the signature holds
};

class CrimpHopController : public Controller {
 public:
  enum class Phase { kFollow, kLift, kPass, kDescend };
  CrimpHopController(const ControllerContext& context, const CrimpHopParams& p)
      : law_(context.law), p_(p), detector_(p) {}
  ControllerCommand Step(const ControllerInput& in) override;
  Phase phase() const { return phase_; }
  int hops() const { return hops_; }

 private:
  ContourLawParams law_;
  CrimpHopParams p_;
  CrimpDetector detector_;
  Phase phase_ = Phase::kFollow;
  std::array<double, 2> along_{};  // the last direction along the edge, tool frame
  double offset_m_ = 0;
  int phase_iterations_ = 0, hops_ = 0;
};

ControllerType CrimpHopControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_CRIMP_HOP_H_
