#include "compare/log_replay.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>

#include "controller/pure/contour_law.h"
#include "geometry/contour_path.h"
#include "runtime/mujoco_model.h"
#include "plugin/chamber_pressure_sensor.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

// tool0 orientation of the project convention (tool z down, x = world -y).
constexpr double kProjectQuat[4] = {0, 0.70710678118654752, -0.70710678118654752, 0};

double Log10Floor(double p) { return std::log10(std::max(1.0, p)); }

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  if (a.size() < 2) return 0;
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return (saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb) : 0;
}

void Tool0FromTcp(const std::array<double, 3>& tcp, const std::array<double, 4>& q,
                  double tcp_offset_m, mjtNum pos[3]) {
  const mjtNum quat[4] = {q[0], q[1], q[2], q[3]};
  const mjtNum along[3] = {0, 0, tcp_offset_m};
  mjtNum d[3];
  mju_rotVecQuat(d, along, quat);
  for (int k = 0; k < 3; ++k) pos[k] = tcp[k] - d[k];
}

}  // namespace

bool LoadAnyLog(const std::string& path, const ProcessOptions& options, ProcessedLog* log,
                LoadError* error) {
  if (fs::is_directory(path)) {
    RobotLog raw;
    return LoadTopicCsvRecording(path, &raw, error) && ProcessRobotLog(raw, options, log, error);
  }
  if (fs::path(path).extension() == ".mat") {
    RobotLog raw;
    return LoadRobotLogMat(path, &raw, error) && ProcessRobotLog(raw, options, log, error);
  }
  return LoadPlainLog(path, log, error);
}

bool ReplayLog(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
               ReplayComparison* out, std::string* error) {
  *out = ReplayComparison();
  const int body = mj_name2id(m, mjOBJ_BODY, "probe");
  if (body < 0 || m->body_mocapid[body] < 0) {
    *error = "the replay scene needs a mocap body named 'probe' holding the tool (e.g. "
             "scenes/disk_replay.xml)";
    return false;
  }
  if (log.t_s.size() < 2) {
    *error = "the log has fewer than two samples";
    return false;
  }
  const int mocap = m->body_mocapid[body];
  mjData* d = mj_makeData(m);
  const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m, d);
  if (sensor == nullptr) {
    mj_deleteData(d);
    *error = "the replay scene has no ssc.chamber_pressure sensor";
    return false;
  }
  const int adr = sensor->sensor_adr();
  auto place = [&](double t) {
    // Linear interpolation of the pose between log samples.
    const auto it = std::upper_bound(log.t_s.begin(), log.t_s.end(), t);
    size_t i = static_cast<size_t>(it - log.t_s.begin());
    i = std::clamp<size_t>(i, 1, log.t_s.size() - 1);
    const double u = std::clamp((t - log.t_s[i - 1]) / (log.t_s[i] - log.t_s[i - 1]), 0.0, 1.0);
    std::array<double, 3> tcp;
    for (int k = 0; k < 3; ++k) tcp[k] = log.tcp_m[i - 1][k] + u * (log.tcp_m[i][k] - log.tcp_m[i - 1][k]);
    const std::array<double, 4>& q = log.quat[u < 0.5 ? i - 1 : i];
    Tool0FromTcp(tcp, q, tcp_offset_m, d->mocap_pos + 3 * mocap);
    for (int k = 0; k < 4; ++k) d->mocap_quat[4 * mocap + k] = q[k];
  };
  d->time = log.t_s.front();
  place(d->time);
  mj_forward(m, d);
  for (size_t k = 0; k < log.t_s.size(); ++k) {
    while (d->time + 0.5 * m->opt.timestep < log.t_s[k]) {
      place(d->time);
      mj_step(m, d);
    }
    std::array<double, 4> sim;
    for (int c = 0; c < 4; ++c) sim[c] = d->sensordata[adr + c];
    out->t_s.push_back(log.t_s[k]);
    out->sim_pa.push_back(sim);
    out->log_pa.push_back(log.p_pa[k]);
    out->tcp_m.push_back(log.tcp_m[k]);
  }
  mj_deleteData(d);

  const size_t n = out->t_s.size();
  for (int c = 0; c < 4; ++c) {
    std::vector<double> a(n), b(n);
    double se = 0, sl = 0;
    for (size_t i = 0; i < n; ++i) {
      a[i] = out->sim_pa[i][c];
      b[i] = out->log_pa[i][c];
      se += (a[i] - b[i]) * (a[i] - b[i]);
      sl += std::pow(Log10Floor(a[i]) - Log10Floor(b[i]), 2);
    }
    out->rms_pa[c] = std::sqrt(se / static_cast<double>(n));
    out->rms_log10[c] = std::sqrt(sl / static_cast<double>(n));
    out->correlation[c] = Correlation(a, b);
    const double mb = std::accumulate(b.begin(), b.end(), 0.0);
    out->mean_ratio[c] = std::fabs(mb) > 1e-9 ? std::accumulate(a.begin(), a.end(), 0.0) / mb : 0;
  }
  double se = 0, bias = 0;
  std::vector<double> angles;
  ContourLawParams law;
  for (size_t i = 0; i < n; ++i) {
    const ContourStep s = ComputeContourStep(out->sim_pa[i], law);
    const ContourStep l = ComputeContourStep(out->log_pa[i], law);
    se += std::pow(s.p_mean_pa - l.p_mean_pa, 2);
    bias += s.p_mean_pa - l.p_mean_pa;
    if (std::hypot(s.g[0], s.g[1]) > law.p_noise_pa && std::hypot(l.g[0], l.g[1]) > law.p_noise_pa) {
      const double da = std::remainder(std::atan2(s.g[1], s.g[0]) - std::atan2(l.g[1], l.g[0]),
                                       2 * M_PI);
      angles.push_back(std::fabs(da) * 180 / M_PI);
    }
  }
  out->pbar_rms_pa = std::sqrt(se / static_cast<double>(n));
  out->pbar_bias_pa = bias / static_cast<double>(n);
  out->direction_samples = static_cast<int>(angles.size());
  if (!angles.empty()) {
    double s2 = 0;
    for (double a : angles) s2 += a * a;
    out->direction_rms_deg = std::sqrt(s2 / static_cast<double>(angles.size()));
    std::nth_element(angles.begin(), angles.begin() + static_cast<long>(angles.size() / 2), angles.end());
    out->direction_median_deg = angles[angles.size() / 2];
  }
  return true;
}

RobotLog RobotLogFromTrial(const TrialResult& trial, double tcp_offset_m, double scale,
                           double offset_pa, double ambient_pa, double noise_pa, unsigned seed) {
  RobotLog log;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  log.t0_ns = 1700000000000000000LL;  // an arbitrary ROS epoch stamp
  for (const TrialLogRow& r : trial.log) {
    if (!log.pressure_abs.t_s.empty() && r.t_s <= log.pressure_abs.t_s.back()) continue;
    std::vector<double> p = {1.0};
    for (int c = 0; c < 4; ++c) {
      p.push_back(ambient_pa - (scale * r.p_pa[c] + offset_pa) - noise_pa * gauss(rng));
    }
    log.pressure_abs.t_s.push_back(r.t_s);
    log.pressure_abs.rows.push_back(p);
    // tool0 from the tool centre point, the project orientation (tool z = world -z).
    const std::array<double, 4> q = {kProjectQuat[0], kProjectQuat[1], kProjectQuat[2], kProjectQuat[3]};
    mjtNum pos[3];
    Tool0FromTcp({r.tool_m[0], r.tool_m[1], r.tool_m[2]}, q, tcp_offset_m, pos);
    log.tool_pose.t_s.push_back(r.t_s);
    log.tool_pose.rows.push_back({q[0], q[1], q[2], q[3], pos[0], pos[1], pos[2]});
    log.ft.t_s.push_back(r.t_s);
    log.ft.rows.push_back({0, 0, r.ft_normal_n, 0, 0, 0});
    log.pwm.t_s.push_back(r.t_s);
    log.pwm.rows.push_back({100});
  }
  return log;
}

bool CompareClosedLoop(const mjModel* disk_scene, const ProcessedLog& log,
                       const TrialConfig& config, ClosedLoopComparison* out, std::string* error) {
  *out = ClosedLoopComparison();
  const ContourLawParams& law = config.law;
  size_t first = log.t_s.size();
  for (size_t i = 0; i < log.t_s.size(); ++i) {
    const ContourStep s = ComputeContourStep(log.p_pa[i], law);
    if (s.p_mean_pa > law.p_noise_pa && s.p_mean_pa < law.p_grasp_pa &&
        std::hypot(s.dpx_pa, s.dpy_pa) > law.p_noise_pa) {
      first = i;
      break;
    }
  }
  if (first + 2 >= log.t_s.size()) {
    *error = "no edge in the log: the pressures never show a differential above P_n";
    return false;
  }
  out->start_t_s = log.t_s[first];
  out->start = {log.tcp_m[first][0], log.tcp_m[first][1]};
  TrialConfig c = config;
  c.target.start = out->start;
  std::vector<Point2> path;
  std::vector<double> t;
  for (size_t i = first; i < log.t_s.size(); ++i) {
    path.push_back({log.tcp_m[i][0], log.tcp_m[i][1]});
    t.push_back(log.t_s[i]);
  }
  out->log = ComputeDiskMetrics(path, t, c.target.goal.centre, c.target.disk_radius_m);
  DataPtr d = MakeData(disk_scene, error);
  if (!d) return false;
  auto trial = ContourTrial::Create(disk_scene, d.get(), c, false, error);
  if (!trial) return false;
  const TrialResult r = trial->Run();
  out->twin = r.metrics;
  out->twin_outcome = OutcomeName(r.outcome);
  const ContourPath logged = ContourPath::Polygon(path, false);
  const auto e = ContourError(trial->path(),
                              [&](double x, double y) { return logged.Project(x, y).distance_m; });
  out->path_distance_mean_mm = e[0] * 1e3;
  out->path_distance_max_mm = e[1] * 1e3;
  out->ran = true;
  return true;
}

bool WriteComparisonReport(const std::string& dir, const std::string& log_name,
                           const ReplayComparison& c, const ClosedLoopComparison* closed,
                           std::string* error) {
  fs::create_directories(dir);
  std::ofstream md(fs::path(dir) / "report.md");
  md << "# Twin against robot log: " << log_name << "\n\n"
     << "Replay of the logged tool path; " << c.t_s.size() << " pressure samples over "
     << (c.t_s.empty() ? 0 : c.t_s.back() - c.t_s.front()) << " s.\n\n"
     << "| chamber | RMS error (Pa) | RMS error (log10) | correlation | mean sim / mean log |\n"
     << "| --- | --- | --- | --- | --- |\n";
  char buf[1024];
  for (int k = 0; k < 4; ++k) {
    std::snprintf(buf, sizeof(buf), "| %d | %.1f | %.3f | %.3f | %.3f |\n", k + 1, c.rms_pa[k],
                  c.rms_log10[k], c.correlation[k], c.mean_ratio[k]);
    md << buf;
  }
  std::snprintf(buf, sizeof(buf),
                "\nMean pressure: RMS error %.1f Pa, bias (sim - log) %.1f Pa.\n"
                "Direction the controller would compute (g): RMS angle error %.1f deg, median "
                "%.1f deg over %d samples with both differentials above P_n.\n",
                c.pbar_rms_pa, c.pbar_bias_pa, c.direction_rms_deg, c.direction_median_deg,
                c.direction_samples);
  md << buf;
  if (closed && closed->ran) {
    const DiskTrialMetrics& a = closed->log;
    const DiskTrialMetrics& b = closed->twin;
    md << "\n## Closed loop\n\nThe twin's controller from the log's start pose (t = "
       << closed->start_t_s << " s), outcome " << closed->twin_outcome << ".\n\n"
       << "| metric | robot log | twin |\n| --- | --- | --- |\n";
    std::snprintf(buf, sizeof(buf),
                  "| dr (mm) | %.2f | %.2f |\n| sigma_r (mm) | %.2f | %.2f |\n"
                  "| s_c | %.3f | %.3f |\n| duration (s) | %.1f | %.1f |\n"
                  "| speed (mm/s) | %.1f | %.1f |\n",
                  a.dr_mm, b.dr_mm, a.sigma_r_mm, b.sigma_r_mm, a.s_c, b.s_c, a.duration_s,
                  b.duration_s, a.speed_mm_s, b.speed_mm_s);
    md << buf;
    std::snprintf(buf, sizeof(buf), "\nTwin path to logged path: mean %.2f mm, max %.2f mm.\n",
                  closed->path_distance_mean_mm, closed->path_distance_max_mm);
    md << buf;
  }
  std::ofstream js(fs::path(dir) / "report.json");
  js << "{\"log\": \"" << log_name << "\", \"samples\": " << c.t_s.size() << ", \"chambers\": [";
  for (int k = 0; k < 4; ++k) {
    std::snprintf(buf, sizeof(buf),
                  "%s{\"rms_pa\": %.4g, \"rms_log10\": %.4g, \"correlation\": %.4g, "
                  "\"mean_ratio\": %.4g}",
                  k ? ", " : "", c.rms_pa[k], c.rms_log10[k], c.correlation[k], c.mean_ratio[k]);
    js << buf;
  }
  std::snprintf(buf, sizeof(buf),
                "], \"pbar_rms_pa\": %.4g, \"pbar_bias_pa\": %.4g, \"direction_rms_deg\": %.4g, "
                "\"direction_median_deg\": %.4g, \"direction_samples\": %d",
                c.pbar_rms_pa, c.pbar_bias_pa, c.direction_rms_deg, c.direction_median_deg,
                c.direction_samples);
  js << buf;
  if (closed && closed->ran) {
    std::snprintf(buf, sizeof(buf),
                  ", \"closed_loop\": {\"twin_outcome\": \"%s\", \"log_dr_mm\": %.4g, "
                  "\"twin_dr_mm\": %.4g, \"log_sigma_r_mm\": %.4g, \"twin_sigma_r_mm\": %.4g, "
                  "\"log_s_c\": %.4g, \"twin_s_c\": %.4g, \"log_duration_s\": %.4g, "
                  "\"twin_duration_s\": %.4g, \"path_distance_mean_mm\": %.4g, "
                  "\"path_distance_max_mm\": %.4g}",
                  closed->twin_outcome.c_str(), closed->log.dr_mm, closed->twin.dr_mm,
                  closed->log.sigma_r_mm, closed->twin.sigma_r_mm, closed->log.s_c, closed->twin.s_c,
                  closed->log.duration_s, closed->twin.duration_s, closed->path_distance_mean_mm,
                  closed->path_distance_max_mm);
    js << buf;
  }
  js << "}\n";
  std::ofstream series(fs::path(dir) / "series.csv");
  series << "t_s,x_m,y_m,z_m,sim_p1_pa,sim_p2_pa,sim_p3_pa,sim_p4_pa,log_p1_pa,log_p2_pa,"
            "log_p3_pa,log_p4_pa\n";
  for (size_t i = 0; i < c.t_s.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%.4f,%.6f,%.6f,%.6f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n",
                  c.t_s[i], c.tcp_m[i][0], c.tcp_m[i][1], c.tcp_m[i][2], c.sim_pa[i][0],
                  c.sim_pa[i][1], c.sim_pa[i][2], c.sim_pa[i][3], c.log_pa[i][0], c.log_pa[i][1],
                  c.log_pa[i][2], c.log_pa[i][3]);
    series << buf;
  }
  if (!md || !js || !series) {
    *error = dir + ": cannot write the report";
    return false;
  }
  return true;
}

}  // namespace ssc
