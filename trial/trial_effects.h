// The robot effects' state through one trial (pure C++, no MuJoCo): what the trial keeps between
// control steps to apply trial/robot_effects.h — the lip's shear, the chambers' drawn
// gains and slow noise, the iteration count the loop's jitter is drawn for, and a step waiting for
// the pose read after the plot. The trial (runtime/trial.cc) measures the tool and the chambers and
// asks this object what the host reads and where the arm lands; with the same parameters and seed
// the same calls give the same answers on any thread.
#ifndef SSC_TRIAL_TRIAL_EFFECTS_H_
#define SSC_TRIAL_TRIAL_EFFECTS_H_

#include <array>
#include <cstdint>

#include "trial/robot_effects.h"

namespace ssc {

class TrialEffects {
 public:
  // Starts a trial: every state back to its start, the draws from `trial_seed` in streams apart
  // from the plugin's noise (which draws from the same seed).
  void Reset(const RobotEffectsParams& params, std::uint64_t trial_seed);

  // The tool moved by `move_tool_m` (tool frame, m) since the previous control step, pressed
  // with `press_n` (F/T compression, N): the lip drags along (DragLip).
  void MoveTool(const std::array<double, 2>& move_tool_m, double press_n);
  // The time from this iteration to the next, s: `period_s` with the loop's jitter.
  double NextIterationPeriod(double period_s);
  // What the host reads at an iteration at `time_s` from the plugin's filtered chamber vacuums:
  // the lip's tilt and peel, then the sensors' gains, slow noise and tare offsets (advanced to
  // `time_s`).
  std::array<double, 4> HostReading(double time_s, std::array<double, 4> p_pa);
  // The chambers as the lip drags them, without the sensors' part (between iterations).
  std::array<double, 4> ChamberReading(std::array<double, 4> p_pa) const;
  // Step `index` (tool frame, m) as the arm lands it: with its landing error, except a held
  // step (0, 0), which never moves.
  std::array<double, 2> LandedStep(std::array<double, 2> step_m, std::uint64_t index) const;

  // A step commanded at `time_s` waits for the pose read after the plot: true when it does (a
  // pose delay is on), and it is due from time_s + pose_delay_s.
  bool DeferStep(double time_s);
  // True once, at the first call at or after the waiting step's time.
  bool TakeDueStep(double time_s);

  // The lip's shear, which a trial resumed at its follow start (runtime/approach_cache.h) takes
  // over from the trial that ran the approach.
  const LipShearState& lip_shear() const { return lip_shear_; }
  void set_lip_shear(const LipShearState& s) { lip_shear_ = s; }

 private:
  RobotEffectsParams params_;
  std::uint64_t seed_ = 0;
  LipShearState lip_shear_;
  ChamberSpreadState chamber_spread_;
  std::uint64_t iteration_index_ = 0;
  bool step_pending_ = false;
  double step_due_s_ = 0;
};

}  // namespace ssc

#endif  // SSC_TRIAL_TRIAL_EFFECTS_H_
