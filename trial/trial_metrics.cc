#include "trial/trial_metrics.h"

#include <algorithm>
#include <cmath>

namespace ssc {

double PathLength(const std::vector<Point2>& path) {
  double s = 0;
  for (size_t i = 1; i < path.size(); ++i) {
    s += std::hypot(path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]);
  }
  return s;
}

std::array<double, 2> ContourError(const std::vector<Point2>& path, const ContourDistance& dist) {
  if (path.empty()) return {0, 0};
  double sum = 0, worst = 0;
  for (const Point2& p : path) {
    const double e = dist(p[0], p[1]);
    sum += e;
    worst = std::max(worst, e);
  }
  return {sum / static_cast<double>(path.size()), worst};
}

DiskTrialMetrics ComputeDiskMetrics(const std::vector<Point2>& path, const std::vector<double>& t,
                                    const Point2& c, double radius) {
  DiskTrialMetrics m;
  if (path.empty()) return m;
  const double s = PathLength(path);
  double sum = 0, sum2 = 0;
  for (const Point2& p : path) {
    const double r = std::hypot(p[0] - c[0], p[1] - c[1]);
    sum += r;
    sum2 += r * r;
  }
  const double n = static_cast<double>(path.size());
  const double r_mean = sum / n;
  const double var = std::max(0.0, sum2 / n - r_mean * r_mean);
  m.s_mm = s * 1e3;
  m.r_mean_mm = r_mean * 1e3;
  m.dr_mm = (r_mean - radius) * 1e3;
  m.sigma_r_mm = std::sqrt(var) * 1e3;
  m.s_c = s / (2 * M_PI * radius) - 1;
  if (t.size() == path.size() && t.size() >= 2) m.duration_s = t.back() - t.front();
  m.speed_mm_s = m.duration_s > 0 ? m.s_mm / m.duration_s : 0;
  m.speed_body_d_s = m.speed_mm_s / kCupBodyDiameterMm;
  const auto err = ContourError(
      path, [&](double x, double y) { return std::fabs(std::hypot(x - c[0], y - c[1]) - radius); });
  m.contour_mean_mm = err[0] * 1e3;
  m.contour_max_mm = err[1] * 1e3;
  return m;
}

}  // namespace ssc
