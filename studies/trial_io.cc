#include "studies/trial_io.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace ssc {
namespace {

std::string Num(double v, int precision = 6) {
  if (!std::isfinite(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
  return buf;
}

std::string JsonEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

// CSV cells never contain commas or quotes from us except the free-text detail.
std::string CsvText(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"') ? '\'' : c;
  return out + "\"";
}

}  // namespace

bool WriteTrialLogCsv(const std::string& path, const TrialResult& result, std::string* error) {
  std::ofstream f(path);
  if (!f) {
    *error = path + ": cannot write";
    return false;
  }
  f << "t_s,x_m,y_m,z_m,p1_pa,p2_pa,p3_pa,p4_pa,pbar_pa,dpx_pa,dpy_pa,cf,step_x_m,step_y_m,"
       "ft_normal_n,phase,iteration\n";
  for (const TrialLogRow& r : result.log) {
    f << Num(r.t_s, 7) << ',' << Num(r.tool_m[0], 8) << ',' << Num(r.tool_m[1], 8) << ','
      << Num(r.tool_m[2], 8);
    for (double p : r.p_pa) f << ',' << Num(p);
    f << ',' << Num(r.pbar_pa) << ',' << Num(r.dpx_pa) << ',' << Num(r.dpy_pa) << ','
      << Num(r.cf) << ',' << Num(r.step_x_m) << ',' << Num(r.step_y_m) << ','
      << Num(r.ft_normal_n) << ',' << PhaseName(r.phase) << ',' << (r.iteration ? 1 : 0) << '\n';
  }
  if (!f) {
    *error = path + ": write failed";
    return false;
  }
  return true;
}

bool WriteTrialSummaryJson(const std::string& path, const std::string& scene,
                           const TrialConfig& c, const TrialResult& r, std::string* error) {
  std::ofstream f(path);
  if (!f) {
    *error = path + ": cannot write";
    return false;
  }
  const DiskTrialMetrics& m = r.metrics;
  f << "{\n"
    << "  \"scene\": \"" << JsonEscape(scene) << "\",\n"
    << "  \"mujoco_version\": \"" << mj_versionString() << "\",\n"
    << "  \"parameters\": {\"pref_pa\": " << Num(c.law.p_ref_pa) << ", \"beta\": "
    << Num(c.law.beta) << ", \"step_mm\": " << Num(c.law.step_mm) << ", \"p_noise_pa\": "
    << Num(c.law.p_noise_pa) << ", \"p_grasp_pa\": " << Num(c.law.p_grasp_pa)
    << ", \"dead_band\": " << (c.law.dead_band ? "true" : "false")
    << ", \"object_on\": \"" << (c.law.side == FollowSide::kObjectOnLeft ? "left" : "right")
    << "\", \"control_period_s\": " << Num(c.control_period_s)
    << ", \"servo_smoothing_s\": " << Num(c.servo.smoothing_s)
    << ", \"approach_force_n\": " << Num(c.approach_force_n)
    << ", \"start_x_mm\": " << Num(c.target.start[0] * 1e3)
    << ", \"start_y_mm\": " << Num(c.target.start[1] * 1e3)
    << ", \"timeout_s\": " << Num(c.timeout_s) << "},\n"
    << "  \"seed\": " << c.seed << ",\n"
    << "  \"outcome\": \"" << OutcomeName(r.outcome) << "\",\n"
    << "  \"detail\": \"" << JsonEscape(r.detail) << "\",\n"
    << "  \"metrics\": {\"s_mm\": " << Num(m.s_mm) << ", \"r_mean_mm\": " << Num(m.r_mean_mm)
    << ", \"dr_mm\": " << Num(m.dr_mm) << ", \"sigma_r_mm\": " << Num(m.sigma_r_mm)
    << ", \"s_c\": " << Num(m.s_c) << ", \"duration_s\": " << Num(m.duration_s)
    << ", \"speed_mm_s\": " << Num(m.speed_mm_s) << ", \"speed_body_d_s\": "
    << Num(m.speed_body_d_s) << ", \"contour_mean_mm\": " << Num(m.contour_mean_mm)
    << ", \"contour_max_mm\": " << Num(m.contour_max_mm) << ", \"swept_deg\": "
    << Num(r.swept_deg) << ", \"end_arc_mm\": " << Num(r.end_arc_mm)
    << ", \"iterations\": " << r.iterations << "},\n"
    << "  \"sim_time_s\": " << Num(r.sim_time_s) << ",\n"
    << "  \"wall_time_s\": " << Num(r.wall_time_s) << ",\n"
    << "  \"hold_height_mm\": " << Num(r.hold_height_m * 1e3) << "\n"
    << "}\n";
  if (!f) {
    *error = path + ": write failed";
    return false;
  }
  return true;
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
  os << scene << ',' << Num(c.law.p_ref_pa) << ',' << Num(c.law.beta) << ','
     << Num(c.law.step_mm) << ',' << repeat << ',' << c.seed << ',' << OutcomeName(r.outcome) << ','
     << Num(m.s_mm) << ',' << Num(m.r_mean_mm) << ',' << Num(m.dr_mm) << ','
     << Num(m.sigma_r_mm) << ',' << Num(m.s_c) << ',' << Num(m.duration_s) << ','
     << Num(m.speed_mm_s) << ',' << Num(m.speed_body_d_s) << ',' << Num(m.contour_mean_mm)
     << ',' << Num(m.contour_max_mm) << ',' << Num(r.swept_deg) << ',' << r.iterations << ','
     << Num(r.sim_time_s) << ',' << CsvText(r.detail);
  return os.str();
}

}  // namespace ssc
