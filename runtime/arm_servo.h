// Tool tracking through an arm's joint position servos (the UR-10 scenes): resolved-rate
// inverse kinematics on the measured state. Each physics step the tool-site position error (and
// the orientation error against the pose held at Init) maps through the damped least-squares
// inverse of the site Jacobian (Eigen) to a joint correction, and the joint servos get
// measured joints + correction. At rest this converges to zero Cartesian error; under the 1.5 N
// lip load the residual is the servo stiffness seen through the Jacobian (docs/ur10_model.md).
// Joint limits: targets are clamped to each joint's range.
#ifndef SSC_RUNTIME_ARM_SERVO_H_
#define SSC_RUNTIME_ARM_SERVO_H_

#include <vector>

#include "runtime/tool_servo.h"

namespace ssc {

class ArmServo : public ToolServo {
 public:
  // The arm: every hinge joint driven by a joint-transmission actuator (6 for the UR-10).
  bool Init(const mjModel* m, mjData* d, int tool_site, std::string* error) override;
  double damping() const { return damping_; }

 protected:
  void Command(const mjModel* m, mjData* d, const Vec3& tool_site_world) override;

 private:
  std::vector<int> joints_, actuators_, dofs_;
  mjtNum held_quat_[4] = {1, 0, 0, 0};
  double damping_ = 1e-3;  // DLS damping (m, rad scale)
  std::vector<mjtNum> jacp_, jacr_;
};

}  // namespace ssc

#endif  // SSC_RUNTIME_ARM_SERVO_H_
