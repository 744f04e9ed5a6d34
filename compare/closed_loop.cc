#include "compare/closed_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "controller/contour_law.h"
#include "geometry/contour_path.h"
#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// History x, y that match the logged TCP within this (RMS) are the same path.
constexpr double kHistoryMatchM = 5e-3;

// Linear interpolation of the log's TCP at t (held at the ends).
std::array<double, 2> TcpAt(const ProcessedLog& log, double t) {
  const auto it = std::upper_bound(log.t_s.begin(), log.t_s.end(), t);
  if (it == log.t_s.begin()) return {log.tcp_m.front()[0], log.tcp_m.front()[1]};
  if (it == log.t_s.end()) return {log.tcp_m.back()[0], log.tcp_m.back()[1]};
  const size_t i = static_cast<size_t>(it - log.t_s.begin());
  const double u = (t - log.t_s[i - 1]) / (log.t_s[i] - log.t_s[i - 1]);
  return {log.tcp_m[i - 1][0] + u * (log.tcp_m[i][0] - log.tcp_m[i - 1][0]),
          log.tcp_m[i - 1][1] + u * (log.tcp_m[i][1] - log.tcp_m[i - 1][1])};
}

double MatchRms(const std::vector<HistoryRow>& h, const ProcessedLog& log, double offset,
                double sign) {
  double s = 0;
  for (const HistoryRow& r : h) {
    const std::array<double, 2> p = TcpAt(log, r.t_s + offset);
    s += std::pow(sign * r.x_m - p[0], 2) + std::pow(sign * r.y_m - p[1], 2);
  }
  return std::sqrt(s / static_cast<double>(h.size()));
}

// The offset (log time - history time) that lays the history's x, y on the logged path: a
// 10 ms grid over every placement inside the log, then 1 ms around the best.
double BestOffset(const std::vector<HistoryRow>& h, const ProcessedLog& log, double sign,
                  double* rms) {
  const double lo = log.t_s.front() - h.front().t_s, hi = log.t_s.back() - h.back().t_s;
  double best = lo, best_rms = std::numeric_limits<double>::infinity();
  for (double step : {0.01, 0.001}) {
    const double from = step == 0.01 ? lo : best - 0.01, to = step == 0.01 ? hi : best + 0.01;
    for (double o = from; o <= to + 1e-12; o += step) {
      const double r = MatchRms(h, log, o, sign);
      if (r < best_rms) {
        best_rms = r;
        best = o;
      }
    }
  }
  *rms = best_rms;
  return best;
}

double AngleDeg(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  if (std::hypot(a[0], a[1]) < 1e-9 || std::hypot(b[0], b[1]) < 1e-9) return kNaN;
  return std::remainder(std::atan2(a[0], a[1]) - std::atan2(b[0], b[1]), 2 * M_PI) * 180 / M_PI;
}

double MedianAbs(std::vector<double> v) {
  if (v.empty()) return kNaN;
  for (double& x : v) x = std::fabs(x);
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

size_t NearestIndex(const std::vector<double>& t, double x) {
  const auto it = std::lower_bound(t.begin(), t.end(), x);
  if (it == t.begin()) return 0;
  if (it == t.end()) return t.size() - 1;
  const size_t i = static_cast<size_t>(it - t.begin());
  return (x - t[i - 1] < t[i] - x) ? i - 1 : i;
}

}  // namespace

bool TwinContactDepth(const mjModel* disk_scene, double force_n, double* depth_m,
                      std::string* error) {
  TrialConfig c;
  c.approach_force_n = force_n;
  DataPtr d = MakeData(disk_scene, error);
  if (!d) return false;
  auto trial = ContourTrial::Create(disk_scene, d.get(), c, false, error);
  if (!trial) return false;
  while (trial->phase() == TrialPhase::kApproach && trial->Step()) {
  }
  if (trial->phase() == TrialPhase::kApproach || trial->phase() == TrialPhase::kDone) {
    *error = "the twin's approach never reached " + std::to_string(force_n) + " N";
    return false;
  }
  *depth_m = c.target.surface_top_z_m - trial->result().hold_height_m;
  return true;
}

TrialConfig ConfigFromArgs(const LabRunArgs& a, const TrialConfig& defaults, std::string* what) {
  TrialConfig c = defaults;
  std::string from_file;
  auto note = [&](const std::string& s) { from_file += (from_file.empty() ? "" : ", ") + s; };
  if (!std::isnan(a.p_ref_pa)) {
    c.law.p_ref_pa = a.p_ref_pa;
    note("P_ref");
  }
  if (!std::isnan(a.beta)) {
    c.law.beta = a.beta;
    note("beta");
  }
  if (!std::isnan(a.d_lat_m)) {
    c.law.step_mm = a.d_lat_m * 1e3;  // the script's d_lat is in metres
    note("dL (d_lat)");
  }
  if (!a.fz_set_n.empty()) {
    c.approach_force_n = std::fabs(std::accumulate(a.fz_set_n.begin(), a.fz_set_n.end(), 0.0) /
                                   static_cast<double>(a.fz_set_n.size()));
    note("approach force (Fz_set)");
  }
  if (!std::isnan(a.disk_radius_mm)) {
    c.target.disk_radius_m = a.disk_radius_mm * 1e-3;
    note("disk radius");
  }
  *what = from_file.empty() ? "the command line (the file holds no script arguments)"
                            : from_file + " from the file";
  return c;
}

bool CompareHistory(const LabRunArgs& args, const ProcessedLog& base_log,
                    const ReplayComparison& replay, const ContourLawParams& law,
                    HistoryComparison* out, std::string* error) {
  *out = HistoryComparison();
  const std::vector<HistoryRow>& h = args.history;
  if (h.size() < 2 || base_log.t_s.size() < 2 || replay.t_s.empty()) {
    *error = "no edgeFollowing_history to compare";
    return false;
  }
  double rms = 0, rms_turned = 0;
  double offset = BestOffset(h, base_log, 1.0, &rms);
  if (rms > kHistoryMatchM) {
    // The script records RTDE's TCP, in the UR Base frame: the same path turned 180 deg.
    const double turned = BestOffset(h, base_log, -1.0, &rms_turned);
    if (rms_turned < rms) {
      offset = turned;
      rms = rms_turned;
      out->history_in_ur_base = true;
    }
  }
  if (rms > kHistoryMatchM) {
    char buf[200];
    std::snprintf(buf, sizeof(buf),
                  "edgeFollowing_history x, y lie nowhere on the logged tool path (best RMS "
                  "%.1f mm at any time offset, in base_link or turned 180 deg)",
                  rms * 1e3);
    *error = buf;
    return false;
  }
  out->time_offset_s = offset;
  out->match_rms_mm = rms * 1e3;
  std::vector<double> r_p, corr_p, r_p_final, f_err;
  std::array<std::vector<double>, 4> twin_p, lab_p;
  for (const HistoryRow& row : h) {
    HistoryPair pair;
    pair.t_log_s = row.t_s + offset;
    pair.lab = row;
    const size_t k = NearestIndex(replay.t_s, pair.t_log_s);
    pair.twin_vacuum_pa = replay.sim_pa[k];
    pair.twin = LabVectorsFromPressures(replay.sim_pa[k], law);
    pair.twin_f_normal_n = k < replay.sim_ft_normal_n.size() ? -replay.sim_ft_normal_n[k] : kNaN;
    pair.r_p_deg = AngleDeg(pair.twin.r_p, row.r_p);
    pair.corr_p_deg = AngleDeg(pair.twin.corr_p, row.corr_p);
    pair.r_p_final_deg = AngleDeg(pair.twin.r_p_final, row.r_p_final);
    if (!std::isnan(pair.r_p_deg)) r_p.push_back(pair.r_p_deg);
    if (!std::isnan(pair.corr_p_deg)) corr_p.push_back(pair.corr_p_deg);
    if (!std::isnan(pair.r_p_final_deg)) r_p_final.push_back(pair.r_p_final_deg);
    if (!std::isnan(pair.twin_f_normal_n)) f_err.push_back(pair.twin_f_normal_n - row.f_normal_n);
    for (int c = 0; c < 4; ++c) {
      twin_p[c].push_back(pair.twin_vacuum_pa[c]);
      lab_p[c].push_back(-row.p_pa[c]);  // the host's absolute - offset: vacuum negative
    }
    out->rows.push_back(pair);
  }
  out->iterations = static_cast<int>(out->rows.size());
  out->r_p_median_deg = MedianAbs(r_p);
  double s2 = 0;
  for (double a : r_p) s2 += a * a;
  out->r_p_rms_deg = r_p.empty() ? kNaN : std::sqrt(s2 / static_cast<double>(r_p.size()));
  out->corr_p_median_deg = MedianAbs(corr_p);
  out->corr_p_samples = static_cast<int>(corr_p.size());
  out->r_p_final_median_deg = MedianAbs(r_p_final);
  for (int c = 0; c < 4; ++c) {
    double se = 0;
    for (size_t i = 0; i < twin_p[c].size(); ++i) se += std::pow(twin_p[c][i] - lab_p[c][i], 2);
    out->p_rms_pa[c] = std::sqrt(se / static_cast<double>(twin_p[c].size()));
    out->p_correlation[c] = Correlation(twin_p[c], lab_p[c]);
    const double lab_sum = std::accumulate(lab_p[c].begin(), lab_p[c].end(), 0.0);
    out->p_mean_ratio[c] = std::fabs(lab_sum) > 1e-9
                               ? std::accumulate(twin_p[c].begin(), twin_p[c].end(), 0.0) / lab_sum
                               : kNaN;
  }
  double fe2 = 0, fb = 0;
  for (double e : f_err) {
    fe2 += e * e;
    fb += e;
  }
  out->f_normal_rms_n = f_err.empty() ? kNaN : std::sqrt(fe2 / static_cast<double>(f_err.size()));
  out->f_normal_bias_n = f_err.empty() ? kNaN : fb / static_cast<double>(f_err.size());
  out->ran = true;
  return true;
}

bool CompareClosedLoop(const mjModel* disk_scene, const ProcessedLog& log, const SceneObject& disk,
                       double start_t_s, const TrialConfig& config, ClosedLoopComparison* out,
                       std::string* error) {
  *out = ClosedLoopComparison();
  const ContourLawParams& law = config.law;
  size_t first = log.t_s.size();
  if (start_t_s >= 0) {
    first = NearestIndex(log.t_s, start_t_s);
  } else {
    for (size_t i = 0; i < log.t_s.size(); ++i) {
      const ContourStep s = ComputeContourStep(log.p_pa[i], law);
      if (s.p_mean_pa > law.p_noise_pa && s.p_mean_pa < law.p_grasp_pa &&
          std::hypot(s.dpx_pa, s.dpy_pa) > law.p_noise_pa) {
        first = i;
        break;
      }
    }
  }
  if (first + 2 >= log.t_s.size()) {
    *error = "no edge in the log: the pressures never show a differential above P_n";
    return false;
  }
  out->start_t_s = log.t_s[first];
  out->start = {log.tcp_m[first][0], log.tcp_m[first][1]};
  TrialConfig c = config;
  const double radius = c.target.disk_radius_m;
  c.target = TrialTarget::Disk(disk.x_m, disk.y_m, radius, 0.0);
  c.target.surface_top_z_m = config.target.surface_top_z_m;
  c.target.start = out->start;
  std::vector<Point2> path;
  std::vector<double> t;
  for (size_t i = first; i < log.t_s.size(); ++i) {
    path.push_back({log.tcp_m[i][0], log.tcp_m[i][1]});
    t.push_back(log.t_s[i]);
  }
  out->log = ComputeDiskMetrics(path, t, c.target.goal.centre, radius);
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

}  // namespace ssc
