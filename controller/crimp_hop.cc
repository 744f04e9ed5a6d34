#include "controller/crimp_hop.h"

#include <algorithm>
#include <cmath>

namespace ssc {
namespace {

// The lift takes the servo this many iterations; the descent is given up after this many.
constexpr int kLiftIterations = 2, kMaxDescendIterations = 30;

}  // namespace

bool CrimpSignature(const CrimpHopParams& p, const std::array<double, 4>& p_pa, double p_ref_pa) {
  const auto low = std::min_element(p_pa.begin(), p_pa.end());
  double least_other = 1e300;
  for (auto it = p_pa.begin(); it != p_pa.end(); ++it)
    if (it != low) least_other = std::min(least_other, *it);
  return least_other > p_ref_pa && *low < p.leak_ratio * least_other;
}

bool CrimpDetector::Update(const std::array<double, 4>& p_pa, double p_ref_pa,
                           const std::array<double, 2>& xy, double step_m) {
  if (!CrimpSignature(p_, p_pa, p_ref_pa)) {
    window_.clear();
    return false;
  }
  window_.push_back(xy);
  const auto n = static_cast<std::size_t>(std::max(1.0, p_.stall_iterations));
  while (window_.size() > n) window_.pop_front();
  if (window_.size() < n) return false;
  const double moved =
      std::hypot(window_.back()[0] - window_.front()[0], window_.back()[1] - window_.front()[1]);
  return moved < p_.stall_share * static_cast<double>(n - 1) * step_m;
}

ControllerCommand CrimpHopController::Step(const ControllerInput& in) {
  ControllerCommand c;
  ++phase_iterations_;
  auto enter = [this](Phase next) {
    phase_ = next;
    phase_iterations_ = 0;
  };
  switch (phase_) {
    case Phase::kFollow: {
      const ContourStep law = ComputeContourStep(in.p_pa, law_);
      // The edge as followed before the crimp: the fold's own differential points elsewhere.
      if (law.moving && !CrimpSignature(p_, in.p_pa, law_.p_ref_pa)) along_ = law.along_edge;
      if (detector_.Update(in.p_pa, law_.p_ref_pa, {in.tool_m[0], in.tool_m[1]},
                           law_.step_mm * 1e-3)) {
        ++hops_;
        detector_.Reset();
        enter(Phase::kLift);
        offset_m_ = p_.lift_mm * 1e-3;
        c.lifted = true;
        break;
      }
      c.step_m = law.step_m;
      break;
    }
    case Phase::kLift:
      c.lifted = true;
      if (phase_iterations_ >= kLiftIterations) {
        enter(Phase::kPass);
        c.step_m = {p_.hop_mm * 1e-3 * along_[0], p_.hop_mm * 1e-3 * along_[1]};
      }
      break;
    case Phase::kPass:
      c.lifted = true;
      enter(Phase::kDescend);
      break;
    case Phase::kDescend:
      c.lifted = true;
      if (in.ft_normal_n >= p_.force_n || phase_iterations_ > kMaxDescendIterations) {
        enter(Phase::kFollow);  // back in contact (or given up: the checks decide)
        c.lifted = false;
        c.step_m = ComputeContourStep(in.p_pa, law_).step_m;
      } else {
        offset_m_ = std::max(offset_m_ - p_.descend_mm * 1e-3, kMinHeightOffsetM);
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
      "the published law; on a crimped lip's signature (one chamber leaking, the cup stalled) "
      "a hop: lift, move past along the edge, come down to the force, resume",
      {{"leak_ratio", "1", 0.01, 1, "a crimped chamber reads below this x the least other one",
        &P::leak_ratio},
       {"stall_iterations", "1", 1, 50, "iterations in a row with the signature",
        &P::stall_iterations, true},
       {"stall_share", "1", 0, 1, "... while it moved less than this share of its steps",
        &P::stall_share},
       {"lift_mm", "mm", 0.5, 20, "hop height above the hold height", &P::lift_mm},
       {"hop_mm", "mm", 0, 50, "move along the edge while lifted", &P::hop_mm},
       {"descend_mm", "mm", 0.1, 10, "height change per iteration coming down", &P::descend_mm},
       {"force_n", "N", 0.05, 20, "F/T force that ends the descent", &P::force_n}});
}

}  // namespace ssc
