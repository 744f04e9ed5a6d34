#include "plugin/pneumatics/lip_rim.h"

#include <algorithm>
#include <cmath>

#include "plugin/pneumatics/cup_geometry.h"

namespace ssc {

std::vector<WedgeRim> AssignWedgeRims(const std::vector<double>& rim_angles_rad,
                                      int rays_per_chamber) {
  const int n_rays = rays_per_chamber * kNumChambers;
  std::vector<WedgeRim> rims(n_rays);
  constexpr double kNone = 1e9;
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < rays_per_chamber; ++j) {
      const double a = RayAngle(c, j, rays_per_chamber);
      double before = kNone, after = kNone;
      WedgeRim& rim = rims[c * rays_per_chamber + j];
      for (int i = 0; i < static_cast<int>(rim_angles_rad.size()); ++i) {
        const double delta = std::remainder(a - rim_angles_rad[i], 2.0 * M_PI);
        if (delta >= 0 && delta < before) {
          before = delta;
          rim.point[0] = i;
        }
        if (delta < 0 && -delta < after) {
          after = -delta;
          rim.point[1] = i;
        }
      }
      if (after >= kNone) rim.point[1] = rim.point[0];
      if (before >= kNone) rim.point[0] = rim.point[1];
      rim.weight1 = (before < kNone && after < kNone) ? before / (before + after) : 0.0;
    }
  }
  return rims;
}

std::vector<int> RimVertices(const std::vector<double>& depth_m, double tolerance_m) {
  std::vector<int> rim;
  if (depth_m.empty()) return rim;
  const double deepest = *std::max_element(depth_m.begin(), depth_m.end());
  for (int i = 0; i < static_cast<int>(depth_m.size()); ++i) {
    if (depth_m[i] >= deepest - tolerance_m) rim.push_back(i);
  }
  return rim;
}

std::vector<std::vector<int>> SkirtColumns(const std::vector<double>& vertex_angles_rad,
                                           const std::vector<double>& rim_angles_rad) {
  std::vector<std::vector<int>> columns(rim_angles_rad.size());
  if (rim_angles_rad.empty()) return columns;
  constexpr double kTieRad = 1e-3;  // model files round coordinates: angles tie only roughly
  const int n_rim = static_cast<int>(rim_angles_rad.size());
  for (int v = 0; v < static_cast<int>(vertex_angles_rad.size()); ++v) {
    double nearest = 1e9;
    for (int i = 0; i < n_rim; ++i) {
      nearest = std::min(
          nearest, std::abs(std::remainder(vertex_angles_rad[v] - rim_angles_rad[i], 2.0 * M_PI)));
    }
    for (int i = 0; i < n_rim; ++i) {
      const double delta =
          std::abs(std::remainder(vertex_angles_rad[v] - rim_angles_rad[i], 2.0 * M_PI));
      if (delta <= nearest + kTieRad) columns[i].push_back(v);
    }
  }
  return columns;
}

int ColumnSealPoint(const double* depth_m, const double* radius_m, int n, double tolerance_m) {
  if (n <= 0) return -1;
  double deepest = depth_m[0];
  for (int k = 1; k < n; ++k) deepest = std::max(deepest, depth_m[k]);
  int seal = -1;
  for (int k = 0; k < n; ++k) {
    if (depth_m[k] < deepest - tolerance_m) continue;
    if (seal < 0 || radius_m[k] < radius_m[seal]) seal = k;
  }
  return seal;
}

std::array<double, 3> TriangleAreaVector(const double p0[3], const double p1[3],
                                         const double p2[3]) {
  double e1[3], e2[3];
  for (int k = 0; k < 3; ++k) {
    e1[k] = p1[k] - p0[k];
    e2[k] = p2[k] - p0[k];
  }
  return {0.5 * (e1[1] * e2[2] - e1[2] * e2[1]), 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
          0.5 * (e1[0] * e2[1] - e1[1] * e2[0])};
}

std::array<double, 3> TrianglePressureForce(const double p0[3], const double p1[3],
                                            const double p2[3], double vacuum_pa,
                                            const double cavity_point[3]) {
  const std::array<double, 3> n = TriangleAreaVector(p0, p1, p2);
  double toward = 0.0;
  for (int k = 0; k < 3; ++k) toward += n[k] * (cavity_point[k] - (p0[k] + p1[k] + p2[k]) / 3.0);
  const double sign = toward < 0 ? -1.0 : 1.0;
  return {sign * vacuum_pa * n[0], sign * vacuum_pa * n[1], sign * vacuum_pa * n[2]};
}

}  // namespace ssc
