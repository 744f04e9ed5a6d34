#include "studies/edge_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "common/output_file.h"
#include "common/strict_number.h"
#include "controller/contour_law.h"
#include "geometry/dimensions.h"
#include "runtime/rig.h"

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

std::string EdgeProbe3d::CheckPlacement(double x_m, double y_m, double yaw_rad, double surface_z_m,
                                        double compression_m, double settle_s) {
  auto bad = [](const char* name, double v, const char* range) {
    return std::string(name) + " = " + FormatNumber(v) + " is out of range " + range;
  };
  if (!(std::fabs(x_m) <= 10)) return bad("x_m", x_m, "[-10, 10] m");
  if (!(std::fabs(y_m) <= 10)) return bad("y_m", y_m, "[-10, 10] m");
  if (!(std::fabs(yaw_rad) <= 100)) return bad("yaw_rad", yaw_rad, "[-100, 100] rad");
  if (!(std::fabs(surface_z_m) <= 10)) return bad("surface_z_m", surface_z_m, "[-10, 10] m");
  if (!(std::fabs(compression_m) <= kMaxProbeCompressionMm * 1e-3)) {
    return bad("compression_m", compression_m, "[-0.01, 0.01] m");
  }
  if (!(settle_s > 0 && settle_s <= kMaxProbeSettleS)) {
    return bad("settle_s", settle_s, "(0, 10] s (settling time, simulated)");
  }
  return "";
}

std::string EdgeProbe3d::CheckStudyLayout() {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  // The tool out of the rays' way for the check, then back (kinematics only: no step taken).
  mjtNum* mpos = d->mocap_pos + 3 * mocap_id_;
  const mjtNum saved[3] = {mpos[0], mpos[1], mpos[2]};
  mpos[2] += 10;
  mj_kinematics(m, d);
  constexpr double kRayStartZ = 0.2, kTolM = 5e-4;
  // The highest geom welded to the world below (x, y); -inf where there is none. A tool held to
  // the mocap body by a constraint (the flex scene's chamber body) stays where it is, so the rays
  // pass through whatever moves.
  auto top_z = [&](double x, double y) {
    mjtNum from[3] = {x, y, kRayStartZ};
    const mjtNum down[3] = {0, 0, -1};
    for (int hop = 0; hop < 64; ++hop) {
      int geom = -1;
      const mjtNum dist = mj_ray(m, d, from, down, nullptr, 1, -1, &geom, nullptr);
      if (dist < 0 || geom < 0) break;
      if (m->body_weldid[m->geom_bodyid[geom]] == 0) return from[2] - dist;
      from[2] -= dist + 1e-6;
    }
    return -std::numeric_limits<double>::infinity();
  };
  const double r = kBenchmarkDiskRadiusM, cx = kProbeDiskCentreXM, in = 0.005;
  struct Point {
    double x, y;
    bool surface;
    const char* what;
  };
  const Point points[] = {{-in, 0, true, "the plate just inside its edge at x = 0"},
                          {in, 0, false, "just outside the plate's edge at x = 0"},
                          {cx, 0, true, "the disk's centre"},
                          {cx + r - in, 0, true, "the disk just inside its rim"},
                          {cx + r + in, 0, false, "just outside the disk's rim"}};
  std::string error;
  for (const Point& p : points) {
    const double z = top_z(p.x, p.y);
    const bool at_top = std::fabs(z - kProbeSurfaceTopM) <= kTolM;
    if (at_top == p.surface) continue;
    char buf[320];
    std::snprintf(buf, sizeof(buf),
                  "the probe's layout is not in this scene: at (%.3f, %.3f) m (%s) the top "
                  "surface is %s, expected %s z = %.3f m (%s: a plate with its "
                  "straight edge along y at x = 0, a %.0f mm-radius disk centred at (%.2f, 0) m)",
                  p.x, p.y, p.what, std::isfinite(z) ? (FormatNumber(z) + " m").c_str() : "absent",
                  p.surface ? "at" : "below", kProbeSurfaceTopM, RigTierFor(RigUse::kProbe).scene,
                  r * 1e3, cx);
    error = buf;
    break;
  }
  mpos[0] = saved[0];
  mpos[1] = saved[1];
  mpos[2] = saved[2];
  mj_kinematics(m, d);
  return error;
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
  // The reference formulas are the controller's own (controller/contour_law.h).
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

namespace {

void WriteHeader(std::ostream& f) {
  f << "offset_mm,angle_deg,x_mm,y_mm,p1_pa,p2_pa,p3_pa,p4_pa,pbar_pa,dpx_pa,dpy_pa,diff_pa,"
       "g_world_deg,travel_world_deg,static_p1_pa,static_p2_pa,static_p3_pa,static_p4_pa,"
       "static_pbar_pa,sealed1_mm2,sealed2_mm2,sealed3_mm2,sealed4_mm2,leak1_mm2,leak2_mm2,"
       "leak3_mm2,leak4_mm2,lip_contacts\n";
}

void WriteRow(std::ostream& f, double offset_mm, double angle_deg, const ProbeReading& r) {
  char line[1024];
  const double deg = 180.0 / M_PI;
  std::snprintf(line, sizeof(line),
                "%.4f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,"
                "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n",
                offset_mm, angle_deg, r.x_m * 1e3, r.y_m * 1e3, r.filtered_pa[0], r.filtered_pa[1],
                r.filtered_pa[2], r.filtered_pa[3], r.pbar_pa, r.dpx_pa, r.dpy_pa,
                std::hypot(r.dpx_pa, r.dpy_pa), r.g_world_rad * deg, r.travel_world_rad * deg,
                r.static_pa[0], r.static_pa[1], r.static_pa[2], r.static_pa[3], r.static_pbar_pa,
                r.sealed_area_mm2[0], r.sealed_area_mm2[1], r.sealed_area_mm2[2],
                r.sealed_area_mm2[3], r.leak_area_mm2[0], r.leak_area_mm2[1], r.leak_area_mm2[2],
                r.leak_area_mm2[3], r.lip_contacts);
  f << line;
}

}  // namespace

bool RunProbeStudy(EdgeProbe3d* probe, const ProbeStudySpec& spec,
                   const std::function<void(double offset_mm, const ProbeReading&)>& edge_row,
                   ProbeStudyResult* result, std::string* error) {
  const std::filesystem::path out = spec.out_dir;
  result->edge_csv = (out / "edge.csv").string();
  result->disk_csv = (out / "disk.csv").string();
  if (std::string e = probe->CheckStudyLayout(); !e.empty()) {
    *error = e;
    return false;
  }
  // Straight edge along world y at x = 0, plate at x < 0 with its top at z = 10 mm.
  const double surface_z = kProbeSurfaceTopM, compression = spec.compression_mm * 1e-3;
  OutputFile edge_file(result->edge_csv);
  std::ostream& edge = edge_file.stream();
  WriteHeader(edge);
  for (double off = spec.from_mm; off <= spec.to_mm + 1e-9; off += spec.step_mm) {
    const ProbeReading r =
        probe->Read(-off * 1e-3, 0.0, 0.0, surface_z, compression, spec.settle_s);
    WriteRow(edge, off, 0.0, r);
    if (edge_row) edge_row(off, r);
  }
  // Around the benchmark disk (the probe tier puts it at (0.15, 0)) at a fixed inset.
  OutputFile disk_file(result->disk_csv);
  std::ostream& disk = disk_file.stream();
  WriteHeader(disk);
  const double cx = kProbeDiskCentreXM, radius = kBenchmarkDiskRadiusM;
  for (double a = 0; a < 360 - 1e-9; a += spec.disk_step_deg) {
    const double th = a * M_PI / 180;
    const double r_m = radius - spec.disk_inset_mm * 1e-3;
    const ProbeReading r = probe->Read(cx + r_m * std::cos(th), r_m * std::sin(th), 0.0, surface_z,
                                       compression, spec.settle_s);
    WriteRow(disk, spec.disk_inset_mm, a, r);
    // Counter-clockwise tangent at angle th is th + 90 deg.
    const double err = std::remainder(r.travel_world_rad - (th + M_PI / 2), 2 * M_PI) * 180 / M_PI;
    result->worst_direction_deg = std::max(result->worst_direction_deg, std::fabs(err));
  }
  return edge_file.Commit(error) && disk_file.Commit(error);
}

}  // namespace ssc
