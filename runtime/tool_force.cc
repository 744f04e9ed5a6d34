#include "runtime/tool_force.h"

#include "plugin/body_tree.h"
#include "plugin/chamber_pressure_sensor.h"

namespace ssc {

void ToolForceReader::Bind(const mjModel* m, int force_sensor, int torque_sensor) {
  sensor_adr_ = m->sensor_adr[force_sensor];
  torque_adr_ = torque_sensor >= 0 ? m->sensor_adr[torque_sensor] : -1;
  site_ = m->sensor_objid[force_sensor];
  // The site sits on the body the transducer carries (the cup).
  root_body_ = m->site_bodyid[site_];
  flex_ = -1;
  for (int f = 0; f < m->nflex && flex_ < 0; ++f) {
    if (IsInSubtree(m, m->flex_vertbodyid[m->flex_vertadr[f]], root_body_)) flex_ = f;
  }
}

double ToolForceReader::Axial(const mjModel* m, const mjData* d) const {
  (void)m;
  return flex_ < 0 ? d->sensordata[sensor_adr_ + 2] : balance_n_;
}

std::array<double, 6> ToolForceReader::Wrench(const mjData* d) const {
  if (flex_ >= 0) return balance_wrench_;
  std::array<double, 6> w{};
  for (int k = 0; k < 3; ++k) {
    w[k] = d->sensordata[sensor_adr_ + k];
    if (torque_adr_ >= 0) w[3 + k] = d->sensordata[torque_adr_ + k];
  }
  return w;
}

void ToolForceReader::Update(const mjModel* m, const mjData* d) {
  if (flex_ < 0) return;
  const mjtNum* site_mat = d->site_xmat + 9 * site_;
  const mjtNum axis_z[3] = {site_mat[2], site_mat[5], site_mat[8]};
  const mjtNum* site_pos = d->site_xpos + 3 * site_;
  double axial = 0.0;
  // The loads on the tool (world frame; torque about the site), the transducer's is minus them.
  mjtNum load[3] = {0, 0, 0};
  mjtNum load_torque[3] = {0, 0, 0};
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.efc_address < 0) continue;
    // Which side of the contact is the tool: +1 when side 1 (the normal points toward it).
    int tool_side = -1;
    for (int side = 0; side < 2; ++side) {
      const bool on_tool =
          con.flex[side] == flex_ ||
          (con.geom[side] >= 0 && IsInSubtree(m, m->geom_bodyid[con.geom[side]], root_body_));
      if (on_tool) tool_side = tool_side < 0 ? side : 2;  // 2: tool against itself
    }
    if (tool_side < 0 || tool_side == 2) continue;
    mjtNum f_contact[6];
    mj_contactForce(m, d, i, f_contact);
    // World force on side 1 from side 0: the contact frame's rows times its components.
    mjtNum f_world[3] = {0, 0, 0};
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) f_world[k] += con.frame[3 * r + k] * f_contact[r];
    }
    const double on_tool_along_z = (tool_side == 1 ? 1.0 : -1.0) * mju_dot3(f_world, axis_z);
    axial -= on_tool_along_z;
    mjtNum on_tool[3], arm[3], moment[3];
    mju_scl3(on_tool, f_world, tool_side == 1 ? 1.0 : -1.0);
    mju_sub3(arm, con.pos, site_pos);
    mju_cross(moment, arm, on_tool);
    mju_addTo3(load, on_tool);
    mju_addTo3(load_torque, moment);
  }
  // The chamber vacuums pull the cup and skirt toward the object: the transducer carries that too.
  if (const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m, d)) {
    const std::array<double, 3> f = sensor->lip_vacuum_force_n(m, d);
    axial -= f[0] * axis_z[0] + f[1] * axis_z[1] + f[2] * axis_z[2];
    const std::array<double, 3> t = sensor->lip_vacuum_torque_nm(m, d);
    for (int k = 0; k < 3; ++k) {
      load[k] += f[k];
      load_torque[k] += t[k];
    }
  }
  balance_n_ = axial;
  mjtNum in_site[3];
  mju_mulMatTVec3(in_site, site_mat, load);
  for (int k = 0; k < 3; ++k) balance_wrench_[k] = -in_site[k];
  mju_mulMatTVec3(in_site, site_mat, load_torque);
  for (int k = 0; k < 3; ++k) balance_wrench_[3 + k] = -in_site[k];
}

}  // namespace ssc
