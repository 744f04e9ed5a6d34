#include "controller/crimp_hop.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

// The lift takes the servo this many iterations.
constexpr int kLiftIterations = 2;

}  // namespace

bool CrimpSignature(const CrimpHopParams& p, const std::array<double, 4>& p_pa, double p_ref_pa) {
  return *std::min_element(p_pa.begin(), p_pa.end()) > p.seal_ratio * p_ref_pa;
}

bool CrimpDetector::Update(const std::array<double, 4>& p_pa, double p_ref_pa) {
  const bool sealed = CrimpSignature(p_, p_pa, p_ref_pa);
  const bool onset = sealed && read_edge_;
  read_edge_ = !sealed;
  return onset;
}

std::array<double, 2> CrimpHopController::FollowStep(const std::array<double, 4>& p_pa) {
  const ContourStep law = ComputeContourStep(p_pa, law_);
  if (resume_left_ <= 0) return law.step_m;
  --resume_left_;
  const double step_m = p_.resume_step_mm * 1e-3;
  return {step_m * law.direction[0], step_m * law.direction[1]};
}

std::array<double, 2> CrimpHopController::ReturnStep(const ControllerInput& in) const {
  // World to tool frame: the transpose of the tool's rotation (row-major), in the plane.
  const double wx = edge_xy_m_[0] - in.tool_m[0], wy = edge_xy_m_[1] - in.tool_m[1];
  const auto& R = in.tool_rotation;
  return {R[0] * wx + R[3] * wy, R[1] * wx + R[4] * wy};
}

ControllerCommand CrimpHopController::Step(const ControllerInput& in) {
  ControllerCommand c;
  ++phase_iterations_;
  auto enter = [this](Phase next) {
    phase_ = next;
    phase_iterations_ = 0;
  };
  switch (phase_) {
    case Phase::kFollow:
      if (detector_.Update(in.p_pa, law_.p_ref_pa)) {
        ++hops_;
        enter(Phase::kLift);
        offset_m_ = p_.lift_mm * 1e-3;
        c.lifted = true;
        break;
      }
      // An open chamber: the throat lies over the edge here.
      if (*std::min_element(in.p_pa.begin(), in.p_pa.end()) < law_.p_ref_pa)
        edge_xy_m_ = {in.tool_m[0], in.tool_m[1]};
      c.step_m = FollowStep(in.p_pa);
      break;
    case Phase::kLift:
      c.lifted = true;
      if (phase_iterations_ >= kLiftIterations) {
        enter(Phase::kReturn);
        c.step_m = ReturnStep(in);
      }
      break;
    case Phase::kReturn:
      c.lifted = true;
      c.step_m = ReturnStep(in);  // the servo covers part of a move per period: aimed again
      enter(Phase::kDescend);
      break;
    case Phase::kDescend:
      c.lifted = true;
      // A period after the set point came back to the hold height: on the surface the approach
      // found (the F/T tells no contact here: the skirt's bellows reads about 1 N in the air).
      if (offset_m_ <= 0) {
        enter(Phase::kFollow);
        c.lifted = false;
        detector_.Reset();
        resume_left_ = static_cast<int>(p_.resume_iterations);
        c.step_m = FollowStep(in.p_pa);
      } else {
        c.step_m = ReturnStep(in);
        offset_m_ = std::max(offset_m_ - p_.descend_mm * 1e-3, 0.0);
      }
      break;
  }
  c.height_offset_m = offset_m_;
  return c;
}

ControllerType CrimpHopControllerType() {
  using P = CrimpHopParams;
  return MakeControllerType<CrimpHopController, P>(
      "crimp_hop",
      "the published law; on a crimped lip's signature (every chamber sealed far above P_ref "
      "right after an iteration that read the edge) a hop: lift, back over where the edge was "
      "last read, down to the hold height, resume in short steps",
      {{"seal_ratio", "1", 2, 99, "crimped: every chamber above this x P_ref", &P::seal_ratio},
       {"lift_mm", "mm", 0.5, 20, "hop height above the hold height", &P::lift_mm},
       {"descend_mm", "mm", 0.1, 10, "height change per iteration coming down", &P::descend_mm},
       {"resume_step_mm", "mm", 0.1, 100, "the law's step after a hop ...", &P::resume_step_mm},
       {"resume_iterations", "1", 0, 200, "... for this many iterations", &P::resume_iterations,
        true}});
}

}  // namespace ssc
