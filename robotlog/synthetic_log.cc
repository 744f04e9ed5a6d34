#include "robotlog/synthetic_log.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace ssc {
namespace {

double MedianStep(const std::vector<TwinSample>& run) {
  if (run.size() < 2) return 0.01;
  std::vector<double> dt;
  for (size_t i = 1; i < run.size(); ++i) dt.push_back(run[i].t_s - run[i - 1].t_s);
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

// Gauge vacuum of the run at time t (linear; held at the ends).
std::array<double, 4> VacuumAt(const std::vector<TwinSample>& run, double t) {
  if (t <= run.front().t_s) return run.front().p_pa;
  if (t >= run.back().t_s) return run.back().p_pa;
  const auto it = std::upper_bound(run.begin(), run.end(), t,
                                   [](double v, const TwinSample& s) { return v < s.t_s; });
  const TwinSample& b = *it;
  const TwinSample& a = *(it - 1);
  const double u = (t - a.t_s) / (b.t_s - a.t_s);
  std::array<double, 4> p{};
  for (int c = 0; c < 4; ++c) p[c] = a.p_pa[c] + u * (b.p_pa[c] - a.p_pa[c]);
  return p;
}

double PwmRaw(double pct, PwmScale scale) {
  switch (scale) {
    case PwmScale::kFraction:
      return pct / 100.0;
    case PwmScale::kByte:
      return std::round(pct * 2.55);
    case PwmScale::kAuto:
    case PwmScale::kPercent:
      break;
  }
  return pct;
}

}  // namespace

RobotLog MakeRobotLog(const std::vector<TwinSample>& run_in, const LogPerturbation& o) {
  RobotLog log;
  if (run_in.empty()) return log;
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  // The run with its in-air lead: the cup held at the first pose, no vacuum.
  std::vector<TwinSample> run;
  const double step_s = o.pressure_rate_hz > 0 ? 1.0 / o.pressure_rate_hz : MedianStep(run_in);
  // Whole samples; the 1e-9 keeps 1 s at 160 Hz from rounding up to 161 samples.
  const int lead = o.in_air_s > 0 ? static_cast<int>(std::ceil(o.in_air_s / step_s - 1e-9)) : 0;
  for (int k = lead; k > 0; --k) {
    TwinSample s = run_in.front();
    s.t_s -= k * step_s;
    s.p_pa = {0, 0, 0, 0};
    s.ft = {0, 0, 0, 0, 0, 0};
    run.push_back(s);
  }
  run.insert(run.end(), run_in.begin(), run_in.end());

  auto jitter = [&](std::vector<double>* t) {
    for (size_t i = 0; i < t->size(); ++i) {
      if (o.jitter_s > 0) (*t)[i] += o.jitter_s * uniform(rng);
      if (i > 0) (*t)[i] = std::max((*t)[i], (*t)[i - 1] + 1e-6);  // keep stamps increasing
    }
  };

  // Pressures: absolute, with the sensors' offsets, scale and noise.
  Stream& p = log.pressure_abs;
  if (o.pressure_rate_hz > 0) {
    const double span_s = run.back().t_s - run.front().t_s;
    for (long k = 0; static_cast<double>(k) * step_s <= span_s + 1e-12; ++k) {
      p.t_s.push_back(run.front().t_s + static_cast<double>(k) * step_s);
    }
  } else {
    for (const TwinSample& s : run) p.t_s.push_back(s.t_s);
  }
  for (double t : p.t_s) {
    const std::array<double, 4> vac = VacuumAt(run, t);
    std::vector<double> row = {4};  // ch: the number of chambers
    for (int c = 0; c < 4; ++c) {
      row.push_back(o.ambient_pa + o.sensor_offset_pa[c] - o.pressure_scale * vac[c] -
                    o.noise_pa * gauss(rng));
    }
    p.rows.push_back(row);
  }
  jitter(&p.t_s);

  // Pose, F/T and PWM at the run's times (pose and F/T late and thinned as asked).
  const Eigen::Quaterniond q_base_scene(o.X_scene_base.rotation().transpose());
  const Eigen::Isometry3d X_base_scene = o.X_scene_base.inverse();
  for (size_t i = 0; i < run.size(); ++i) {
    const TwinSample& s = run[i];
    const bool end = i == 0 || i + 1 == run.size();
    if (!end && o.drop_fraction > 0 && unit(rng) < o.drop_fraction) continue;
    const Eigen::Quaterniond q_scene(s.quat[0], s.quat[1], s.quat[2], s.quat[3]);
    const Eigen::Vector3d tcp(s.tcp_m[0], s.tcp_m[1], s.tcp_m[2]);
    const Eigen::Vector3d tool0_scene = Tool0FromTcp(tcp, q_scene, o.tcp_offset_m);
    const Eigen::Vector3d tool0 = X_base_scene * tool0_scene;
    const Eigen::Quaterniond q = q_base_scene * q_scene;
    log.tool_pose.t_s.push_back(s.t_s + o.pose_delay_s);
    log.tool_pose.rows.push_back({q.w(), q.x(), q.y(), q.z(), tool0.x(), tool0.y(), tool0.z()});
    log.ft.t_s.push_back(s.t_s + o.pose_delay_s);
    log.ft.rows.push_back(std::vector<double>(s.ft.begin(), s.ft.end()));
  }
  for (const TwinSample& s : run) {
    log.pwm.t_s.push_back(s.t_s);
    log.pwm.rows.push_back({PwmRaw(s.pwm_pct, o.pwm_scale)});
  }
  jitter(&log.tool_pose.t_s);
  jitter(&log.ft.t_s);
  jitter(&log.pwm.t_s);

  // Times from the earliest stamp of any stream.
  Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
  double first = p.t_s.front();
  for (Stream* s : streams) first = std::min(first, s->t_s.front());
  for (Stream* s : streams) {
    for (double& t : s->t_s) t -= first;
  }
  log.t0_ns = o.t0_ns;
  return log;
}

}  // namespace ssc
