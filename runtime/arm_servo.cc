#include "runtime/arm_servo.h"

#include <Eigen/Dense>
#include <algorithm>

namespace ssc {

bool ArmServo::Init(const mjModel* m, mjData* d, int tool_site, std::string* error) {
  site_ = tool_site;
  joints_.clear();
  actuators_.clear();
  dofs_.clear();
  for (int a = 0; a < m->nu; ++a) {
    if (m->actuator_trntype[a] != mjTRN_JOINT) continue;
    const int j = m->actuator_trnid[2 * a];
    if (j < 0 || m->jnt_type[j] != mjJNT_HINGE) continue;
    joints_.push_back(j);
    actuators_.push_back(a);
    dofs_.push_back(m->jnt_dofadr[j]);
  }
  if (joints_.size() != 6) {
    *error = "arm scene needs 6 hinge joints driven by position actuators, found " +
             std::to_string(joints_.size());
    return false;
  }
  jacp_.assign(3 * m->nv, 0);
  jacr_.assign(3 * m->nv, 0);
  mju_mat2Quat(held_quat_, d->site_xmat + 9 * tool_site);
  target_ = command_ = Measured(d);
  last_time_ = d->time;
  return true;
}

void ArmServo::Command(const mjModel* m, mjData* d, const Vec3& tool_site_world) {
  // Cartesian error in world: position, and rotation from the current to the held orientation.
  Eigen::Matrix<double, 6, 1> e;
  const mjtNum* p = d->site_xpos + 3 * site_;
  for (int k = 0; k < 3; ++k) e[k] = tool_site_world[k] - p[k];
  mjtNum q_now[4], local[3], world[3];
  mju_mat2Quat(q_now, d->site_xmat + 9 * site_);
  mju_subQuat(local, held_quat_, q_now);  // q_now * quat(local) = held
  mju_mulMatVec3(world, d->site_xmat + 9 * site_, local);
  for (int k = 0; k < 3; ++k) e[3 + k] = world[k];

  mj_jacSite(m, d, jacp_.data(), jacr_.data(), site_);
  Eigen::Matrix<double, 6, 6> J;
  for (int c = 0; c < 6; ++c) {
    for (int r = 0; r < 3; ++r) {
      J(r, c) = jacp_[r * m->nv + dofs_[c]];
      J(3 + r, c) = jacr_[r * m->nv + dofs_[c]];
    }
  }
  const Eigen::Matrix<double, 6, 6> JJt =
      J * J.transpose() + damping_ * damping_ * Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Matrix<double, 6, 1> dq = J.transpose() * JJt.ldlt().solve(e);
  for (int i = 0; i < 6; ++i) {
    const int j = joints_[i];
    double q = d->qpos[m->jnt_qposadr[j]] + dq[i];
    if (m->jnt_limited[j]) q = std::clamp(q, m->jnt_range[2 * j], m->jnt_range[2 * j + 1]);
    d->ctrl[actuators_[i]] = q;
  }
}

}  // namespace ssc
