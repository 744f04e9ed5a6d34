#include "compare/replay.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "common/tool_names.h"
#include "controller/contour_law.h"
#include "plugin/chamber_pressure_sensor.h"
#include "robotlog/align.h"
#include "runtime/rig.h"
#include "runtime/tool_servo.h"

namespace ssc {
namespace {

double Log10Floor(double p) { return std::log10(std::max(1.0, p)); }

}  // namespace

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  if (a.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  // A constant series (a dead sensor, a pump that never ran) has no correlation: NaN, shown as
  // "n/a" and null in report.json, never a made-up 0.
  return (saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb)
                              : std::numeric_limits<double>::quiet_NaN();
}

std::string CorrelationText(double r) {
  if (!std::isfinite(r)) return "n/a (constant)";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3f", r);
  return buf;
}

namespace {

// Steps the replay scene along the log: the twin's chamber pressures (as the host reads them,
// with the lip's drag) and tared F/T force at the log's time stamps into `out`, beside the log's
// own series; with `take` the log's series move into `out` at the end instead of being copied
// sample by sample.
bool ReplayPath(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
                const LipShearParams& lip, ReplayComparison* out, std::string* error,
                const std::function<void(double)>& progress, ProcessedLog* take) {
  const int body = mj_name2id(m, mjOBJ_BODY, "probe");
  if (body < 0 || m->body_mocapid[body] < 0) {
    *error =
        std::string("the replay scene needs a mocap body named 'probe' holding the tool (e.g. ") +
        RigTierFor(RigUse::kReplay).scene + ")";
    return false;
  }
  if (log.t_s.size() < 2) {
    *error = "the log has fewer than two samples";
    return false;
  }
  const int mocap = m->body_mocapid[body];
  mjData* d = mj_makeData(m);
  RigBinding rig;
  if (std::string e = rig.BindSensors(m, d); !e.empty()) {
    mj_deleteData(d);
    *error = "the replay " + e;
    return false;
  }
  const int adr = rig.pressure_adr;
  auto place = [&](double t) {
    // Linear interpolation of the pose between log samples.
    const auto it = std::upper_bound(log.t_s.begin(), log.t_s.end(), t);
    size_t i = static_cast<size_t>(it - log.t_s.begin());
    i = std::clamp<size_t>(i, 1, log.t_s.size() - 1);
    const double u = std::clamp((t - log.t_s[i - 1]) / (log.t_s[i] - log.t_s[i - 1]), 0.0, 1.0);
    std::array<double, 3> tcp;
    for (int k = 0; k < 3; ++k)
      tcp[k] = log.tcp_m[i - 1][k] + u * (log.tcp_m[i][k] - log.tcp_m[i - 1][k]);
    const std::array<double, 4>& q = log.quat[u < 0.5 ? i - 1 : i];
    const Eigen::Vector3d tool0 =
        Tool0FromTcp(Eigen::Vector3d(tcp[0], tcp[1], tcp[2]),
                     Eigen::Quaterniond(q[0], q[1], q[2], q[3]), tcp_offset_m);
    for (int k = 0; k < 3; ++k) d->mocap_pos[3 * mocap + k] = tool0[k];
    for (int k = 0; k < 4; ++k) d->mocap_quat[4 * mocap + k] = q[k];
  };
  // The F/T force sensor of the tool (z along the cup axis), tared on the first sample as the
  // host tares it in air.
  const int ft_adr = rig.force_adr + 2;
  // The simulation clock starts at 0 whatever the log's clock reads (a log starting at -5 s or
  // at 1.7e9 s replays the same): sim time = log time - t0.
  const double t0 = log.t_s.front();
  d->time = 0;
  place(t0);
  mj_forward(m, d);
  const double ft_tare = ft_adr >= 0 ? d->sensordata[ft_adr] : 0.0;
  // The lip drags along the path step by step, as in the closed-loop trial.
  const int site = rig.tool_site;
  LipShearState shear;
  std::array<double, 2> last_xy = {d->site_xpos[3 * site], d->site_xpos[3 * site + 1]};
  const size_t samples = log.t_s.size();
  out->sim_pa.reserve(samples);
  out->sim_ft_normal_n.reserve(samples);
  if (take == nullptr) {
    out->t_s.reserve(samples);
    out->log_pa.reserve(samples);
    out->tcp_m.reserve(samples);
  }
  size_t next_report = samples / 100;
  for (size_t k = 0; k < samples; ++k) {
    if (progress && k >= next_report && samples >= 100) {
      progress(static_cast<double>(k) / static_cast<double>(samples));
      next_report += samples / 100;
    }
    // To the microsecond: a clock that starts elsewhere (an epoch clock holds 1.7e9 s to 0.24 us)
    // gives the same differences.
    const double target_s = std::round((log.t_s[k] - t0) * 1e6) * 1e-6;
    while (d->time + 0.5 * m->opt.timestep < target_s) {
      place(t0 + d->time);
      mj_step(m, d);
      const mjtNum* xy = d->site_xpos + 3 * site;
      // As in the trial: the lip drags only while the cup is pressed on something.
      DragLip(lip, WorldToTool(d->site_xmat + 9 * site, xy[0] - last_xy[0], xy[1] - last_xy[1]),
              ft_adr >= 0 ? d->sensordata[ft_adr] - ft_tare : kLipPressedN, &shear);
      last_xy = {xy[0], xy[1]};
    }
    std::array<double, 4> sim;
    for (int c = 0; c < 4; ++c) sim[c] = d->sensordata[adr + c];
    ApplyLipTilt(lip, shear, &sim);
    out->sim_pa.push_back(sim);
    out->sim_ft_normal_n.push_back(ft_adr >= 0 ? d->sensordata[ft_adr] - ft_tare : 0.0);
    if (take == nullptr) {
      out->t_s.push_back(log.t_s[k]);
      out->log_pa.push_back(log.p_pa[k]);
      out->tcp_m.push_back(log.tcp_m[k]);
    }
  }
  mj_deleteData(d);
  if (take != nullptr) {
    out->t_s = std::move(take->t_s);
    out->log_pa = std::move(take->p_pa);
    out->tcp_m = std::move(take->tcp_m);
    *take = ProcessedLog();
  }
  if (progress) progress(1.0);
  return true;
}

// Per chamber, twin against log: RMS in Pa and in log10, correlation, ratio of means.
void ScoreChambers(ReplayComparison* out) {
  const size_t n = out->t_s.size();
  for (int c = 0; c < 4; ++c) {
    // One pass of sums per chamber (no copies of the series): RMS, log10 RMS, correlation.
    double se = 0, sl = 0, sa = 0, sb = 0;
    for (size_t i = 0; i < n; ++i) {
      const double a = out->sim_pa[i][c], b = out->log_pa[i][c];
      se += (a - b) * (a - b);
      sl += std::pow(Log10Floor(a) - Log10Floor(b), 2);
      sa += a;
      sb += b;
    }
    const double ma = sa / static_cast<double>(n), mb = sb / static_cast<double>(n);
    double sab = 0, saa = 0, sbb = 0;
    for (size_t i = 0; i < n; ++i) {
      const double a = out->sim_pa[i][c] - ma, b = out->log_pa[i][c] - mb;
      sab += a * b;
      saa += a * a;
      sbb += b * b;
    }
    out->rms_pa[c] = std::sqrt(se / static_cast<double>(n));
    out->rms_log10[c] = std::sqrt(sl / static_cast<double>(n));
    // As Correlation(): NaN when either side is constant.
    out->correlation[c] = (n >= 2 && saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb)
                                                         : std::numeric_limits<double>::quiet_NaN();
    out->mean_ratio[c] = std::fabs(sb) > 1e-9 ? sa / sb : 0;
  }
}

// What the law reads from either side: the mean pressure's RMS and bias, and the direction of g
// where both exceed the law's noise level.
void ScoreLaw(ReplayComparison* out) {
  const size_t n = out->t_s.size();
  double se = 0, bias = 0;
  std::vector<double> angles;
  ContourLawParams law;
  for (size_t i = 0; i < n; ++i) {
    const ContourStep s = ComputeContourStep(out->sim_pa[i], law);
    const ContourStep l = ComputeContourStep(out->log_pa[i], law);
    se += std::pow(s.p_mean_pa - l.p_mean_pa, 2);
    bias += s.p_mean_pa - l.p_mean_pa;
    if (std::hypot(s.g[0], s.g[1]) > law.p_noise_pa &&
        std::hypot(l.g[0], l.g[1]) > law.p_noise_pa) {
      const double da =
          std::remainder(std::atan2(s.g[1], s.g[0]) - std::atan2(l.g[1], l.g[0]), 2 * M_PI);
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
    std::nth_element(angles.begin(), angles.begin() + static_cast<long>(angles.size() / 2),
                     angles.end());
    out->direction_median_deg = angles[angles.size() / 2];
  }
}

bool Replay(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
            const LipShearParams& lip, ReplayComparison* out, std::string* error,
            const std::function<void(double)>& progress, ProcessedLog* take) {
  *out = ReplayComparison();
  if (!ReplayPath(m, log, tcp_offset_m, lip, out, error, progress, take)) return false;
  ScoreChambers(out);
  ScoreLaw(out);
  return true;
}

}  // namespace

bool ReplayLog(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
               const LipShearParams& lip, ReplayComparison* out, std::string* error,
               const std::function<void(double)>& progress) {
  return Replay(m, log, tcp_offset_m, lip, out, error, progress, nullptr);
}

bool ReplayLogConsuming(const mjModel* m, ProcessedLog* log, double tcp_offset_m,
                        const LipShearParams& lip, ReplayComparison* out, std::string* error,
                        const std::function<void(double)>& progress) {
  return Replay(m, *log, tcp_offset_m, lip, out, error, progress, log);
}

}  // namespace ssc
