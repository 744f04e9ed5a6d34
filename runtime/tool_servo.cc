#include "runtime/tool_servo.h"

#include <algorithm>
#include <cmath>

#include "runtime/arm_servo.h"

namespace ssc {

Vec3 ToolServo::Measured(const mjData* d) const {
  const mjtNum* p = d->site_xpos + 3 * site_;
  return {p[0], p[1], p[2]};
}

void ToolServo::Track(const mjModel* m, mjData* d) {
  const double dt = last_time_ < 0 ? 0.0 : std::max(0.0, d->time - last_time_);
  last_time_ = d->time;
  if (dt > 0 && params_.damping > 0 && params_.smoothing_s > 0) {
    // Second order, semi-implicit Euler (stable: w dt = 2 ms / >= 30 ms), speed limited.
    const double w = 1.0 / params_.smoothing_s;
    double speed = 0;
    for (int k = 0; k < 3; ++k) {
      velocity_[k] +=
          dt * (w * w * (target_[k] - command_[k]) - 2 * params_.damping * w * velocity_[k]);
      speed += velocity_[k] * velocity_[k];
    }
    speed = std::sqrt(speed);
    const double scale = speed > params_.max_speed_m_s ? params_.max_speed_m_s / speed : 1.0;
    for (int k = 0; k < 3; ++k) {
      velocity_[k] *= scale;
      command_[k] += dt * velocity_[k];
    }
  } else if (dt > 0) {
    const double alpha = params_.smoothing_s > 0 ? 1.0 - std::exp(-dt / params_.smoothing_s) : 1.0;
    Vec3 delta;
    double norm = 0;
    for (int k = 0; k < 3; ++k) {
      delta[k] = alpha * (target_[k] - command_[k]);
      norm += delta[k] * delta[k];
    }
    norm = std::sqrt(norm);
    const double max_step = params_.max_speed_m_s * dt;
    const double scale = norm > max_step ? max_step / norm : 1.0;
    for (int k = 0; k < 3; ++k) command_[k] += scale * delta[k];
  }
  Command(m, d, command_);
}

bool GantryServo::Init(const mjModel* m, mjData* d, int tool_site, std::string* error) {
  site_ = tool_site;
  const char* names[3] = {"gantry_x", "gantry_y", "gantry_z"};
  for (int k = 0; k < 3; ++k) {
    actuator_[k] = mj_name2id(m, mjOBJ_ACTUATOR, names[k]);
    const int joint = mj_name2id(m, mjOBJ_JOINT, names[k]);
    if (actuator_[k] < 0 || joint < 0) {
      *error = std::string("gantry scene needs joint and actuator '") + names[k] + "'";
      return false;
    }
    site_minus_joints_[k] = d->site_xpos[3 * tool_site + k] - d->qpos[m->jnt_qposadr[joint]];
  }
  target_ = command_ = Measured(d);
  last_time_ = d->time;
  return true;
}

void GantryServo::Command(const mjModel* m, mjData* d, const Vec3& tool_site_world) {
  (void)m;
  for (int k = 0; k < 3; ++k) d->ctrl[actuator_[k]] = tool_site_world[k] - site_minus_joints_[k];
}

std::unique_ptr<ToolServo> MakeToolServo(const mjModel* m) {
  if (mj_name2id(m, mjOBJ_JOINT, "gantry_x") >= 0) return std::make_unique<GantryServo>();
  return std::make_unique<ArmServo>();
}

}  // namespace ssc
