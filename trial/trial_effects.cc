#include "trial/trial_effects.h"

#include <cmath>

namespace ssc {

void TrialEffects::Reset(const RobotEffectsParams& params, std::uint64_t trial_seed) {
  params_ = params;
  seed_ = trial_seed ^ 0x5EEDEFFEC7ULL;
  lip_shear_ = LipShearState();
  ResetChamberSpread(params_.chambers, seed_, &chamber_spread_);
  iteration_index_ = 0;
  step_pending_ = false;
  step_due_s_ = 0;
}

void TrialEffects::MoveTool(const std::array<double, 2>& move_tool_m, double press_n) {
  DragLip(params_.lip, move_tool_m, press_n, &lip_shear_);
}

double TrialEffects::NextIterationPeriod(double period_s) {
  return IterationPeriod(params_.loop, period_s, seed_, iteration_index_++);
}

std::array<double, 4> TrialEffects::HostReading(double time_s, std::array<double, 4> p_pa) {
  ApplyLipTilt(params_.lip, lip_shear_, &p_pa);
  ApplyChamberSpread(params_.chambers, seed_, time_s, &chamber_spread_, &p_pa);
  return p_pa;
}

std::array<double, 4> TrialEffects::ChamberReading(std::array<double, 4> p_pa) const {
  ApplyLipTilt(params_.lip, lip_shear_, &p_pa);
  return p_pa;
}

std::array<double, 2> TrialEffects::LandedStep(std::array<double, 2> step_m,
                                               std::uint64_t index) const {
  if (step_m[0] == 0 && step_m[1] == 0) return step_m;  // held by the dead band: no miss
  const std::array<double, 2> e =
      StepError(params_.loop, std::hypot(step_m[0], step_m[1]), seed_, index);
  return {step_m[0] + e[0], step_m[1] + e[1]};
}

bool TrialEffects::DeferStep(double time_s) {
  if (params_.loop.pose_delay_s <= 0) return false;
  step_pending_ = true;
  step_due_s_ = time_s + params_.loop.pose_delay_s;
  return true;
}

bool TrialEffects::TakeDueStep(double time_s) {
  // (1e-9 s: the control steps' times are sums of the time step, with their round-off.)
  if (!step_pending_ || time_s + 1e-9 < step_due_s_) return false;
  step_pending_ = false;
  return true;
}

}  // namespace ssc
