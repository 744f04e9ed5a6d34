#include "studies/edge_probe.h"

#include <cmath>

#include "controller/pure/contour_law.h"

namespace ssc {

std::unique_ptr<EdgeProbe3d> EdgeProbe3d::Create(const std::string& scene_path,
                                                 std::string* error) {
  std::unique_ptr<EdgeProbe3d> probe(new EdgeProbe3d());
  probe->model_ = LoadModel(scene_path, error);
  if (!probe->model_) return nullptr;
  const mjModel* m = probe->model_.get();
  probe->data_ = MakeData(m, error);
  if (!probe->data_) return nullptr;
  const int body = mj_name2id(m, mjOBJ_BODY, "probe");
  if (body < 0 || m->body_mocapid[body] < 0) {
    *error = scene_path + ": needs a mocap body named 'probe' holding the tool";
    return nullptr;
  }
  probe->mocap_id_ = m->body_mocapid[body];
  probe->sensor_ = FindChamberPressureDiagnostics(m, probe->data_.get());
  if (probe->sensor_ == nullptr) {
    *error = scene_path + ": no ssc.chamber_pressure sensor in the scene";
    return nullptr;
  }
  probe->instance_ = probe->sensor_->instance();
  probe->sensor_adr_ = probe->sensor_->sensor_adr();
  // Tool length: distance from the mocap frame (tool0) to the tool site, at the reference pose.
  mj_forward(m, probe->data_.get());
  const mjtNum* a = probe->data_->xpos + 3 * body;
  const mjtNum* b = probe->data_->site_xpos + 3 * probe->sensor_->site_id();
  probe->tool_length_m_ = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                    (a[2] - b[2]) * (a[2] - b[2]));
  return probe;
}

ProbeReading EdgeProbe3d::Read(double x_m, double y_m, double yaw_rad, double surface_z_m,
                               double compression_m, double settle_s) {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  // Project convention: tool x = world -y, tool y = world -x, tool z = world -z (a half turn
  // about (1, -1, 0)/sqrt 2), then the yaw about world z.
  const mjtNum base[4] = {0, M_SQRT1_2, -M_SQRT1_2, 0};
  const mjtNum yaw[4] = {std::cos(0.5 * yaw_rad), 0, 0, std::sin(0.5 * yaw_rad)};
  mjtNum quat[4];
  mju_mulQuat(quat, yaw, base);
  mjtNum* mpos = d->mocap_pos + 3 * mocap_id_;
  mpos[0] = x_m;
  mpos[1] = y_m;
  mpos[2] = surface_z_m - compression_m + tool_length_m_;
  mju_copy4(d->mocap_quat + 4 * mocap_id_, quat);
  const double t_end = d->time + settle_s;
  while (d->time < t_end) mj_step(m, d);
  mj_forward(m, d);

  ProbeReading r;
  r.x_m = x_m;
  r.y_m = y_m;
  r.yaw_rad = yaw_rad;
  const ChamberPressureSample& s = sensor_->last_sample();
  for (int c = 0; c < 4; ++c) {
    r.filtered_pa[c] = d->sensordata[sensor_adr_ + c];
    r.static_pa[c] = s.flow.tap_pa[c];
    r.sealed_area_mm2[c] = s.sealed_area_m2[c] * 1e6;
    r.leak_area_mm2[c] = s.leak_area_m2[c] * 1e6;
  }
  for (const LipSegmentState& l : s.lip) r.lip_contacts += l.in_contact ? 1 : 0;
  // The reference formulas are the controller's own (controller/pure/contour_law.h).
  const ContourStep law = ComputeContourStep(r.filtered_pa, ContourLawParams{});
  r.pbar_pa = law.p_mean_pa;
  r.dpx_pa = law.dpx_pa;
  r.dpy_pa = law.dpy_pa;
  r.static_pbar_pa = ComputeContourStep(r.static_pa, ContourLawParams{}).p_mean_pa;
  // g is in the tool frame; to world with the site rotation.
  const mjtNum g_tool[3] = {law.g[0], law.g[1], 0};
  mjtNum g_world[3];
  mju_mulMatVec3(g_world, d->site_xmat + 9 * sensor_->site_id(), g_tool);
  r.g_world_rad = std::atan2(g_world[1], g_world[0]);
  // Object on the left seen from above (world z up): travel = g turned 90 deg clockwise.
  r.travel_world_rad = std::atan2(-g_world[0], g_world[1]);
  return r;
}

}  // namespace ssc
