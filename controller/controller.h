// The contour-following controller as the host runs it, one call per control iteration, as plain
// C++ (no MuJoCo): what the real host can read in, the next command out. The trial
// (runtime/trial.h) owns the approach, the move to the start point and the failure checks; a
// controller decides only while following. A fresh instance runs each trial, so a controller
// keeps its own state between iterations in members.
//
// Frames: the step is in the tool frame of controller/contour_law.h (+x toward the south
// chambers, +y toward the west chambers, +z down into the object); the pose is in the world
// (z up). The trial adds the step to the measured tool position (the host's pose read), lands
// it with the robot effects' step error and clamps the height at the approach's depth limit.
#ifndef SSC_CONTROLLER_CONTROLLER_H_
#define SSC_CONTROLLER_CONTROLLER_H_

#include <array>
#include <cstdint>
#include <string>

namespace ssc {

// What the host reads at one control iteration.
struct ControllerInput {
  double t_s = 0;               // host clock (simulated), s
  double follow_s = 0;          // since following started, s
  std::uint64_t iteration = 0;  // 0 at the first iteration of following
  // The four chamber vacuums as the sensor chain delivers them (the plugin's filtered output
  // through the robot effects), Pa, positive = vacuum; chambers SE, NE, NW, SW.
  std::array<double, 4> p_pa{};
  // The F/T along the cup axis, tared in air: pressing on the object reads positive, N.
  double ft_normal_n = 0;
  std::array<double, 3> tool_m{};  // measured tool position, world, m
  // Tool frame -> world rotation, row-major (a world vector = R * a tool vector).
  std::array<double, 9> tool_rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  double hold_z_m = 0;  // the tool height the approach settled at, world, m (0 before)
};

// The next command.
struct ControllerCommand {
  std::array<double, 2> step_m{};  // planar step, tool frame, m; |step| <= kMaxCommandStepM
  // Tool height above the approach's hold height, m (+ up): [kMinHeightOffsetM,
  // kMaxHeightOffsetM]. The trial never takes it below the approach's depth limit.
  double height_offset_m = 0;
  // The cup is deliberately off the surface (a hop): the off-edge and grasp checks wait, for at
  // most TrialThresholds::max_lifted_s at a time.
  bool lifted = false;
};

// The command's valid range: a command outside it (or not finite) ends the trial with the
// outcome controller_fault.
inline constexpr double kMaxCommandStepM = 0.1;
inline constexpr double kMinHeightOffsetM = -0.01, kMaxHeightOffsetM = 0.05;

// "" when `c` is finite and within range, else what is wrong, with the value and range.
std::string CheckControllerCommand(const ControllerCommand& c);

class Controller {
 public:
  virtual ~Controller() = default;
  virtual ControllerCommand Step(const ControllerInput& in) = 0;
  // Why the last command is out of range, when the controller knows (e.g. the exception a
  // Python callable raised); "" otherwise.
  virtual std::string FaultDetail() const { return ""; }
  // True when the fault is the host's stop reaching the controller (Ctrl-C inside a Python
  // controller): the trial is not a finished one, and studies write no row for it.
  virtual bool Interrupted() const { return false; }
  // A controller that reads the host's sensors before following (the approach from the air and
  // the move to the start point: e.g. to re-tare the chambers in air at the following pump
  // duty) says so here; it then gets ObserveBeforeFollowing once per control period of those
  // phases, with iteration and follow_s 0. Its trials simulate their own approach (they are not
  // resumed from a shared one, runtime/approach_cache.h).
  virtual bool ObservesBeforeFollowing() const { return false; }
  virtual void ObserveBeforeFollowing(const ControllerInput& in) { (void)in; }
};

}  // namespace ssc

#endif  // SSC_CONTROLLER_CONTROLLER_H_
