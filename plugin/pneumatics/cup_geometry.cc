#include "plugin/pneumatics/cup_geometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ssc {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = 0.5 * kPi;

// Start angle of each chamber's quadrant (see the header's layout table).
constexpr double kChamberStart[kNumChambers] = {-kHalfPi, -kPi, kHalfPi, 0.0};
}  // namespace

std::string CupGeometry::Validate() const {
  std::ostringstream os;
  if (!std::isfinite(opening_radius_m) || opening_radius_m < 0.5e-3 || opening_radius_m > 0.05) {
    os << "opening_radius = " << opening_radius_m * 1e3 << " mm is out of range [0.5, 50] mm";
  } else if (!std::isfinite(seal_distance_m) || seal_distance_m < 0 || seal_distance_m > 0.01) {
    os << "seal_distance = " << seal_distance_m * 1e3 << " mm is out of range [0, 10] mm";
  } else if (!std::isfinite(lip_roughness_gap_m) || lip_roughness_gap_m < 0 ||
             lip_roughness_gap_m > 1e-3) {
    os << "lip_roughness_gap = " << lip_roughness_gap_m * 1e6
       << " um is out of range [0, 1000] um";
  } else if (rays_per_chamber < 1 || rays_per_chamber > kMaxRaysPerChamber) {
    os << "rays_per_chamber = " << rays_per_chamber << " is out of range [1, "
       << kMaxRaysPerChamber << "]";
  }
  return os.str();
}

double CupGeometry::ChamberOpeningArea() const {
  return 0.25 * kPi * opening_radius_m * opening_radius_m;
}

int ChamberOfAngle(double angle_rad) {
  double a = std::remainder(angle_rad, 2.0 * kPi);  // (-pi, pi]
  if (a >= 0.0) return a < kHalfPi ? 3 : 2;
  return a >= -kHalfPi ? 0 : 1;
}

double RayAngle(int chamber, int j, int rays_per_chamber) {
  const double width = kHalfPi / rays_per_chamber;
  return kChamberStart[chamber] + (j + 0.5) * width;
}

double SubSectorCoveredArea(bool centre_covered, const double* crossings_m, int n_crossings,
                            double radius_m, double dtheta_rad) {
  double covered_r2 = 0.0;  // integral of 2 r dr over covered stretches
  double r0 = 0.0;
  bool covered = centre_covered;
  for (int i = 0; i < n_crossings && r0 < radius_m; ++i) {
    const double r1 = std::clamp(crossings_m[i], r0, radius_m);
    if (covered) covered_r2 += r1 * r1 - r0 * r0;
    covered = !covered;
    r0 = r1;
  }
  if (covered && r0 < radius_m) covered_r2 += radius_m * radius_m - r0 * r0;
  return 0.5 * dtheta_rad * covered_r2;
}

std::array<double, kNumChambers> LeakAreas(const CupGeometry& geometry,
                                           const std::array<double, kNumChambers>& sealed_area_m2,
                                           const LipSegmentState* segments, int n_segments) {
  std::array<double, kNumChambers> leak{};
  const double opening = geometry.ChamberOpeningArea();
  for (int c = 0; c < kNumChambers; ++c) {
    leak[c] = std::max(0.0, opening - std::clamp(sealed_area_m2[c], 0.0, opening));
  }
  for (int i = 0; i < n_segments; ++i) {
    const LipSegmentState& s = segments[i];
    if (s.in_contact) {
      leak[s.chamber] += s.arc_m * geometry.lip_roughness_gap_m;
    } else if (s.gap_m <= geometry.seal_distance_m) {
      leak[s.chamber] += s.arc_m * (std::max(0.0, s.gap_m) + geometry.lip_roughness_gap_m);
    }
  }
  return leak;
}

EdgeProbe ProbeStraightEdge(const CupGeometry& geometry, double edge_offset_m,
                            double normal_angle_rad, double lip_radius_m, int n_lip_segments,
                            double lip_phase_rad) {
  EdgeProbe probe;
  const double nx = std::cos(normal_angle_rad);
  const double ny = std::sin(normal_angle_rad);
  const int m = geometry.rays_per_chamber;
  const double dtheta = kHalfPi / m;
  const bool centre_covered = edge_offset_m >= 0.0;
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < m; ++j) {
      const double a = RayAngle(c, j, m);
      const double nu = nx * std::cos(a) + ny * std::sin(a);
      // Along this ray the surface covers {r : r * nu <= edge_offset}.
      double crossing[1];
      int n = 0;
      bool start_covered = centre_covered;
      if (nu > 1e-12) {
        start_covered = edge_offset_m > 0.0;
        if (start_covered) crossing[n++] = edge_offset_m / nu;
      } else if (nu < -1e-12 && !centre_covered) {
        crossing[n++] = edge_offset_m / nu;
      }
      probe.sealed_area_m2[c] +=
          SubSectorCoveredArea(start_covered, crossing, n, geometry.opening_radius_m, dtheta);
    }
  }
  probe.n_segments = std::clamp(n_lip_segments, 0, kMaxLipSegments);
  const double arc = 2.0 * kPi * lip_radius_m / std::max(1, probe.n_segments);
  for (int i = 0; i < probe.n_segments; ++i) {
    const double a = lip_phase_rad + 2.0 * kPi * i / probe.n_segments;
    LipSegmentState& s = probe.segments[i];
    s.chamber = ChamberOfAngle(a);
    s.arc_m = arc;
    const double along_normal = lip_radius_m * (nx * std::cos(a) + ny * std::sin(a));
    s.in_contact = along_normal <= edge_offset_m;
    s.gap_m = s.in_contact ? 0.0 : 1.0;  // over the edge: no surface within reach
  }
  return probe;
}

}  // namespace ssc
