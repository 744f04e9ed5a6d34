#include "studies/trial_io.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/csv_cell.h"
#include "common/output_file.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

std::string Num(double v, int precision = 6) {
  if (!std::isfinite(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
  return buf;
}

}  // namespace

bool WriteTrialLogCsv(const std::string& path, const TrialResult& result, std::string* error) {
  OutputFile file(path);
  std::ostream& f = file.stream();
  f << "t_s,x_m,y_m,z_m,p1_pa,p2_pa,p3_pa,p4_pa,pbar_pa,dpx_pa,dpy_pa,cf,step_x_m,step_y_m,"
       "ft_normal_n,phase,iteration\n";
  for (const TrialLogRow& r : result.log) {
    f << Num(r.t_s, 7) << ',' << Num(r.tool_m[0], 8) << ',' << Num(r.tool_m[1], 8) << ','
      << Num(r.tool_m[2], 8);
    for (double p : r.p_pa) f << ',' << Num(p);
    f << ',' << Num(r.pbar_pa) << ',' << Num(r.dpx_pa) << ',' << Num(r.dpy_pa) << ',' << Num(r.cf)
      << ',' << Num(r.step_x_m) << ',' << Num(r.step_y_m) << ',' << Num(r.ft_normal_n) << ','
      << PhaseName(r.phase) << ',' << (r.iteration ? 1 : 0) << '\n';
  }
  return file.Commit(error);
}

bool WriteTrialSummaryJson(const std::string& path, const std::string& scene, const TrialConfig& c,
                           const TrialResult& r, std::string* error) {
  const DiskTrialMetrics& m = r.metrics;
  // Numbers at 6 significant digits, as in the CSV files; non-finite values become null.
  auto num = [](double v) -> nlohmann::ordered_json {
    if (!std::isfinite(v)) return nullptr;
    return std::stod(Num(v));
  };
  nlohmann::ordered_json j;
  j["scene"] = scene;
  j["mujoco_version"] = mj_versionString();
  j["parameters"] = {{"pref_pa", num(c.law.p_ref_pa)},
                     {"beta", num(c.law.beta)},
                     {"step_mm", num(c.law.step_mm)},
                     {"p_noise_pa", num(c.law.p_noise_pa)},
                     {"p_grasp_pa", num(c.law.p_grasp_pa)},
                     {"dead_band", c.law.dead_band},
                     {"object_on", c.law.side == FollowSide::kObjectOnLeft ? "left" : "right"},
                     {"control_period_s", num(c.control_period_s)},
                     {"servo_smoothing_s", num(c.servo.smoothing_s)},
                     {"servo_damping", num(c.servo.damping)},
                     {"approach_force_n", num(c.approach_force_n)},
                     {"start_x_mm", num(c.target.start[0] * 1e3)},
                     {"start_y_mm", num(c.target.start[1] * 1e3)},
                     {"timeout_s", num(c.timeout_s)},
                     {"effects", FormatRobotEffects(c.effects)}};
  if (!c.controller.IsPublished()) j["parameters"]["controller"] = c.controller.Text();
  j["seed"] = c.seed;
  j["outcome"] = OutcomeName(r.outcome);
  j["detail"] = r.detail;
  j["metrics"] = {{"s_mm", num(m.s_mm)},
                  {"r_mean_mm", num(m.r_mean_mm)},
                  {"dr_mm", num(m.dr_mm)},
                  {"sigma_r_mm", num(m.sigma_r_mm)},
                  {"s_c", num(m.s_c)},
                  {"duration_s", num(m.duration_s)},
                  {"speed_mm_s", num(m.speed_mm_s)},
                  {"speed_body_d_s", num(m.speed_body_d_s)},
                  {"contour_mean_mm", num(m.contour_mean_mm)},
                  {"contour_max_mm", num(m.contour_max_mm)},
                  {"swept_deg", num(r.swept_deg)},
                  {"end_arc_mm", num(r.end_arc_mm)},
                  {"iterations", r.iterations}};
  j["sim_time_s"] = num(r.sim_time_s);
  j["wall_time_s"] = num(r.wall_time_s);
  j["hold_height_mm"] = num(r.hold_height_m * 1e3);
  return WriteWholeFile(path, j.dump(2) + "\n", error);
}

std::string SweepCsvHeader() {
  return "scene,pref_pa,beta,step_mm,repeat,seed,outcome,s_mm,r_mean_mm,dr_mm,sigma_r_mm,s_c,"
         "duration_s,speed_mm_s,speed_body_d_s,contour_mean_mm,contour_max_mm,swept_deg,"
         "iterations,sim_time_s,detail";
}

std::string SweepCsvRow(const std::string& scene, const TrialConfig& c, int repeat,
                        const TrialResult& r) {
  const DiskTrialMetrics& m = r.metrics;
  std::ostringstream os;
  os << scene << ',' << Num(c.law.p_ref_pa) << ',' << Num(c.law.beta) << ',' << Num(c.law.step_mm)
     << ',' << repeat << ',' << c.seed << ',' << OutcomeName(r.outcome) << ',' << Num(m.s_mm) << ','
     << Num(m.r_mean_mm) << ',' << Num(m.dr_mm) << ',' << Num(m.sigma_r_mm) << ',' << Num(m.s_c)
     << ',' << Num(m.duration_s) << ',' << Num(m.speed_mm_s) << ',' << Num(m.speed_body_d_s) << ','
     << Num(m.contour_mean_mm) << ',' << Num(m.contour_max_mm) << ',' << Num(r.swept_deg) << ','
     << r.iterations << ',' << Num(r.sim_time_s) << ',' << CsvCell(r.detail);
  return os.str();
}

}  // namespace ssc
