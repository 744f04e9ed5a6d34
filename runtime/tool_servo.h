// Moving the tool: a Cartesian target for the tool site (lip-plane centre), smoothed the way the
// UR's servoL look-ahead smooths it, and tracked by the scene's actuators.
//
// Two implementations share the smoothing: GantryServo drives x/y/z slide joints (the light
// scene); Ur10Servo solves the UR-10's inverse kinematics each control call and commands the
// joint position servos (the full scene). Orientation is held at its value when Init ran.
#ifndef SSC_RUNTIME_TOOL_SERVO_H_
#define SSC_RUNTIME_TOOL_SERVO_H_

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <string>

namespace ssc {

using Vec3 = std::array<double, 3>;

// A world x/y displacement in the tool frame, given the tool site's rotation (row-major, as
// mjData.site_xmat holds it): what the lip's footprint feels as the tool slides.
inline std::array<double, 2> WorldToTool(const mjtNum* R, double wx, double wy) {
  return {R[0] * wx + R[3] * wy, R[1] * wx + R[4] * wy};
}
// The inverse: a tool-frame x/y displacement (a step) in world x/y.
inline std::array<double, 2> ToolToWorld(const mjtNum* R, double tx, double ty) {
  return {R[0] * tx + R[1] * ty, R[3] * tx + R[4] * ty};
}

struct ServoParams {
  // First-order smoothing of the commanded tool position toward the target, s: the UR servoL
  // look-ahead (0.2 s on the robot). Each iteration re-bases the target on the measured pose, so
  // the arm realises only part of each step before the next one (1 - e^-1 = 63 % with the
  // default 0.15 s control period); see docs/trials.md for why this, not a 4 Hz loop with full
  // steps, reproduces both the published speeds and the stability at dL = 7.5 mm.
  double smoothing_s = 0.15;
  // Speed limit of the commanded point, m/s (UR servoL never jumps).
  double max_speed_m_s = 0.25;
  // Damping ratio of a second-order tracking of the target, [0, 2]; 0 = the first-order
  // smoothing above (the default). Above 0 the command follows target'' = w^2 (target - command)
  // - 2 zeta w command' with w = 1 / smoothing_s: the arm with the tool's payload carries its
  // velocity into the next step and, below 1, overshoots (UR servoL at gain 100 with 0.2 s
  // look-ahead is a soft tracker; its damping is not published).
  double damping = 0.0;
};

class ToolServo {
 public:
  // What the smoothing carries from one step to the next (everything else is fixed at Init).
  struct State {
    Vec3 target{};
    Vec3 command{};
    Vec3 velocity{};  // of the command, m/s (second-order tracking only)
    double last_time_s = -1;
  };

  virtual ~ToolServo() = default;
  // Binds to the model (finds joints/actuators/site); holds the current pose. False + *error
  // when the scene lacks what this servo drives.
  virtual bool Init(const mjModel* m, mjData* d, int tool_site, std::string* error) = 0;
  // Writes actuator controls for the current smoothed command; call every physics step.
  void Track(const mjModel* m, mjData* d);
  void SetTarget(const Vec3& tool_site_world) { target_ = tool_site_world; }
  const Vec3& target() const { return target_; }
  const Vec3& command() const { return command_; }
  Vec3 Measured(const mjData* d) const;
  void set_params(const ServoParams& p) { params_ = p; }
  State state() const { return {target_, command_, velocity_, last_time_}; }
  void set_state(const State& s) {
    target_ = s.target;
    command_ = s.command;
    velocity_ = s.velocity;
    last_time_ = s.last_time_s;
  }

 protected:
  // Sets controls so that the tool site goes to `tool_site_world` with the held orientation.
  virtual void Command(const mjModel* m, mjData* d, const Vec3& tool_site_world) = 0;
  int site_ = -1;
  ServoParams params_;
  Vec3 target_{};
  Vec3 command_{};
  Vec3 velocity_{};
  double last_time_ = -1;
};

// Picks the servo the scene supports: a gantry if it has joints gantry_x/y/z, else the UR-10.
std::unique_ptr<ToolServo> MakeToolServo(const mjModel* m);

class GantryServo : public ToolServo {
 public:
  bool Init(const mjModel* m, mjData* d, int tool_site, std::string* error) override;

 protected:
  void Command(const mjModel* m, mjData* d, const Vec3& tool_site_world) override;

 private:
  int actuator_[3] = {-1, -1, -1};
  Vec3 site_minus_joints_{};  // tool site minus gantry joint positions (constant)
};

}  // namespace ssc

#endif  // SSC_RUNTIME_TOOL_SERVO_H_
