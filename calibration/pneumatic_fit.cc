#include "calibration/pneumatic_fit.h"

#include <algorithm>
#include <cmath>

#include "calibration/nelder_mead.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<double, 4> Taps(const PneumaticModel& m, double offset_m) {
  // Edge normal toward north (chambers 2, 3 over the edge).
  return SolveProbe(m.geometry, m.pneumatics, ProbeStraightEdge(m.geometry, offset_m, kPi)).tap_pa;
}

double Mean(const std::array<double, 4>& p) { return 0.25 * (p[0] + p[1] + p[2] + p[3]); }

double OffsetFor(const PneumaticModel& m, double target_pa) {
  double lo = -6e-3, hi = 6e-3;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Mean(Taps(m, mid)) < target_pa ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

PneumaticModel WithLog(const PneumaticModel& base, const std::vector<double>& x) {
  PneumaticModel m = base;
  m.pneumatics.pump_free_flow_m3_s = std::exp(x[0]);
  m.pneumatics.port_area_m2 = std::exp(x[1]);
  m.pneumatics.jet_area_m2 = std::exp(x[2]);
  m.geometry.lip_roughness_gap_m = std::exp(x[3]);
  return m;
}

double Cost(const std::vector<FitTarget>& targets) {
  double c = 0;
  for (const FitTarget& t : targets) {
    if (t.name == "air_mean_pa") {  // one-sided: below the bound
      c += t.model > t.target ? std::pow(t.residual(), 2) : 0;
    } else if (t.name == "plate_min_pa") {  // one-sided: above the bound
      c += t.model < t.target ? std::pow(t.residual(), 2) : 0;
    } else {
      c += std::pow(t.residual(), 2);
    }
  }
  return c;
}

}  // namespace

double StaticMeanVacuum(const PneumaticModel& model, double offset_m) {
  return Mean(Taps(model, offset_m));
}

PneumaticModel ScaledFitStart(double scale) {
  PneumaticModel start;
  start.pneumatics.pump_free_flow_m3_s *= scale;
  start.pneumatics.port_area_m2 *= scale;
  start.pneumatics.jet_area_m2 *= scale;
  start.geometry.lip_roughness_gap_m *= scale;
  return start;
}

std::vector<FitTarget> EvaluatePublishedTargets(const PneumaticModel& m,
                                                const StaticDepthPressures& depth_pa) {
  std::vector<FitTarget> t = {
      {"offset_at_40pa_mm", "mm", kDepthTargetOffsetMm[0], 0.1},
      {"offset_at_100pa_mm", "mm", kDepthTargetOffsetMm[1], 0.1},
      {"offset_at_200pa_mm", "mm", kDepthTargetOffsetMm[2], 0.1},
      {"differential_at_100pa_pa", "Pa", kPublishedDifferentialAt100PaPa, 20},
      {"air_mean_pa", "Pa", 4, 1},
      {"plate_min_pa", "Pa", 20000, 1000}};
  const double d100 = OffsetFor(m, depth_pa[1]);
  t[0].model = OffsetFor(m, depth_pa[0]) * 1e3;
  t[1].model = d100 * 1e3;
  t[2].model = OffsetFor(m, depth_pa[2]) * 1e3;
  const auto p = Taps(m, d100);
  t[3].model = std::hypot(0.5 * (p[1] + p[2]) - 0.5 * (p[0] + p[3]),
                          0.5 * (p[2] + p[3]) - 0.5 * (p[0] + p[1]));
  t[4].model = Mean(Taps(m, -0.02));
  const auto plate = Taps(m, 0.02);
  t[5].model = *std::min_element(plate.begin(), plate.end());
  return t;
}

StaticDepthPressures NextDepthPressures(const PneumaticModel& model,
                                        const StaticDepthPressures& current,
                                        const std::array<double, 3>& loop_dr_mm) {
  StaticDepthPressures next = current;
  for (int k = 0; k < 3; ++k) {
    const double at_target = StaticMeanVacuum(model, kDepthTargetOffsetMm[k] * 1e-3);
    const double at_loop = StaticMeanVacuum(model, -loop_dr_mm[k] * 1e-3);
    // The loop settles where the static curve reads what it reads at the loop's depth; ask the
    // next curve to read that at the published depth.
    double factor = at_target > 0 ? at_loop / at_target : 2.0;
    if (!std::isfinite(factor)) factor = 1.0;
    next[k] = current[k] * std::clamp(factor, 0.5, 2.0);
  }
  return next;
}

PneumaticFit FitPublishedTargets(const PneumaticModel& start,
                                 const StaticDepthPressures& depth_pa) {
  const std::vector<double> x0 = {
      std::log(start.pneumatics.pump_free_flow_m3_s), std::log(start.pneumatics.port_area_m2),
      std::log(start.pneumatics.jet_area_m2), std::log(start.geometry.lip_roughness_gap_m)};
  auto f = [&](const std::vector<double>& x) {
    return Cost(EvaluatePublishedTargets(WithLog(start, x), depth_pa));
  };
  const NelderMeadResult r = NelderMead(f, x0, {0.3, 0.3, 0.3, 0.3}, 1e-10, 1500);
  PneumaticFit fit;
  fit.model = WithLog(start, r.x);
  fit.targets = EvaluatePublishedTargets(fit.model, depth_pa);
  fit.cost = Cost(fit.targets);
  fit.evaluations = r.evaluations;
  const char* keys[4] = {"pump_free_flow_lpm", "port_area_mm2", "jet_area_mm2", "lip_roughness_um"};
  const double to_unit[4] = {60000.0, 1e6, 1e6, 1e6};
  for (int i = 0; i < 4; ++i) {
    FitParameter p;
    p.key = keys[i];
    p.value = std::exp(r.x[i]) * to_unit[i];
    // Curvature of the cost along this coordinate (a 10 % change), for how well it is pinned.
    std::vector<double> up = r.x, down = r.x;
    up[i] += 0.1;
    down[i] -= 0.1;
    p.sensitivity = (f(up) - 2 * fit.cost + f(down)) / (0.1 * 0.1);
    fit.parameters.push_back(p);
  }
  return fit;
}

}  // namespace ssc
