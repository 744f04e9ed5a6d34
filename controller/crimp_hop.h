// Crimp recovery: the published law, and a hop away from the place where the lip crimped.
//
// At a concave corner the flex skirt's stretch over the drop is caught by the far wall, folds in
// under the throat across a chamber's mouth, and the cup seals (docs/flex_skirt.md, "The crimp":
// the scripted push 2 mm past the wall reads 6015-6776 Pa in every chamber, lowered there 318 Pa
// in the facing one). Under the law at dL 10 mm it comes within one or two control periods: an
// iteration that reads the edge (one chamber at 37 Pa), then 1.5-1.7 kPa, then 17 kPa in every
// chamber, and the trial ends as failure II (all chambers above the 10 kPa grasp threshold)
// before any stall could show. So the signature is the onset of that seal: every chamber above
// `seal_ratio` x P_ref on the iteration after one that was not. Following reads at most ~1.9 kPa
// in its least chamber (the skirt near an apex, a segment lip over one), so 20 x P_ref = 2 kPa
// parts the two, below the grasp threshold so that the hop comes before the failure check. A cup
// sealed since its last landing does not fire (no edge read since): no hop again on a top face.
// A long step onto a top face can read as a seal's start too: a hop there costs time only.
//
// The hop lifts the cup by lift_mm (the vacuum, and with it the fold's pull, is vented; lifted:
// the failure checks wait), takes it back over the position of the last iteration with a chamber
// open (below P_ref: the throat over the edge), comes down in steps of descend_mm to the hold
// height (the top face the approach found; not to an F/T force: with the skirt the F/T reads up
// to 1.0 N lifted 3 mm and 0.9-1.2 N back at the hold height), and resumes the law with
// resume_step_mm steps for resume_iterations iterations (the corner taken in short steps: at the
// object study's 0.5 mm the law turns every concave corner without crimping), then at the law's
// dL. Without a seal onset the commands are the law's.
#ifndef SSC_CONTROLLER_CRIMP_HOP_H_
#define SSC_CONTROLLER_CRIMP_HOP_H_

#include <array>

#include "controller/contour_law.h"
#include "controller/controller_registry.h"

namespace ssc {

struct CrimpHopParams {
  double seal_ratio = 20;         // crimped: every chamber above this x P_ref
  double lift_mm = 4.0;           // hop height above the hold height
  double descend_mm = 1.0;        // height change per iteration coming down
  double resume_step_mm = 0.5;    // the law's step after a hop ...
  double resume_iterations = 20;  // ... for this many iterations
};

// The crimp signature in one sample: every chamber sealed far above P_ref.
bool CrimpSignature(const CrimpHopParams& p, const std::array<double, 4>& p_pa, double p_ref_pa);

// Fires on the onset of the signature: a sample with it after a sample without it.
class CrimpDetector {
 public:
  explicit CrimpDetector(const CrimpHopParams& p) : p_(p) {}
  // One following iteration's pressures; true when a crimp is detected.
  bool Update(const std::array<double, 4>& p_pa, double p_ref_pa);
  // After a landing: the next sample is not an onset until one without the signature came.
  void Reset() { read_edge_ = false; }

 private:
  CrimpHopParams p_;
  bool read_edge_ = false;  // the last sample was without the signature
};

class CrimpHopController : public Controller {
 public:
  enum class Phase { kFollow, kLift, kReturn, kDescend };
  CrimpHopController(const ControllerContext& context, const CrimpHopParams& p)
      : law_(context.law), p_(p), detector_(p) {}
  ControllerCommand Step(const ControllerInput& in) override;
  Phase phase() const { return phase_; }
  int hops() const { return hops_; }

 private:
  // The law's step, at resume_step_mm while resuming after a hop.
  std::array<double, 2> FollowStep(const std::array<double, 4>& p_pa);
  // The planar move (tool frame, m) from the tool to where a chamber was last open.
  std::array<double, 2> ReturnStep(const ControllerInput& in) const;

  ContourLawParams law_;
  CrimpHopParams p_;
  CrimpDetector detector_;
  Phase phase_ = Phase::kFollow;
  std::array<double, 2> edge_xy_m_{};  // world position of the last iteration with an open chamber
  double offset_m_ = 0;
  int phase_iterations_ = 0, hops_ = 0, resume_left_ = 0;
};

ControllerType CrimpHopControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_CRIMP_HOP_H_
