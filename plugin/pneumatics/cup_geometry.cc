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
  } else if (!std::isfinite(open_depth_m) || open_depth_m < 0.05e-3 || open_depth_m > 0.01) {
    os << "open_depth = " << open_depth_m * 1e3 << " mm is out of range [0.05, 10] mm";
  } else if (!std::isfinite(lip_roughness_gap_m) || lip_roughness_gap_m < 0 ||
             lip_roughness_gap_m > 1e-3) {
    os << "lip_roughness_gap = " << lip_roughness_gap_m * 1e6 << " um is out of range [0, 1000] um";
  } else if (rays_per_chamber < 1 || rays_per_chamber > kMaxRaysPerChamber) {
    os << "rays_per_chamber = " << rays_per_chamber << " is out of range [1, " << kMaxRaysPerChamber
       << "]";
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

void StretchSampleRadii(double r0_m, double r1_m, double radius_out_m[kSamplesPerStretch]) {
  const double a0 = r0_m * r0_m, a1 = r1_m * r1_m;
  for (int k = 0; k < kSamplesPerStretch; ++k) {
    radius_out_m[k] = std::sqrt(a0 + (a1 - a0) * (k + 0.5) / kSamplesPerStretch);
  }
}

void AddStretch(double r0_m, double r1_m, const double gap_m[kSamplesPerStretch],
                OpeningWedge* wedge) {
  const double area = 0.5 * wedge->dtheta_rad * (r1_m * r1_m - r0_m * r0_m) / kSamplesPerStretch;
  if (area <= 0) return;
  for (int k = 0; k < kSamplesPerStretch && wedge->n_samples < kMaxWedgeSamples; ++k) {
    wedge->samples[wedge->n_samples++] = {area, gap_m[k]};
  }
}

WedgeLeak WedgeLeakArea(const CupGeometry& geometry, const OpeningWedge& wedge) {
  const double depth = geometry.open_depth_m;
  const double rim_gap = std::max(0.0, wedge.rim_gap_m);
  const double rim_radius_m = wedge.rim_radius_m > 0.0
                                  ? std::min(wedge.rim_radius_m, geometry.opening_radius_m)
                                  : geometry.opening_radius_m;
  const double curtain_per_m = rim_radius_m * wedge.dtheta_rad;
  const double roughness = geometry.lip_roughness_gap_m;
  auto openness = [depth](double layer_m) { return std::clamp(layer_m / depth, 0.0, 1.0); };
  auto cut = [&](double z) {
    double a = curtain_per_m * (z + roughness);
    for (int k = 0; k < wedge.n_samples; ++k) {
      a += wedge.samples[k].area_m2 * openness(wedge.samples[k].gap_m - z);
    }
    return a;
  };
  // The cut is piecewise linear in z: its minimum lies at an end or where a sample's openness
  // starts or stops changing.
  double best = cut(0.0);
  auto consider = [&](double z) {
    if (!(z > 0.0 && z <= rim_gap)) return;
    best = std::min(best, cut(z));
  };
  consider(rim_gap);
  for (int k = 0; k < wedge.n_samples; ++k) {
    consider(wedge.samples[k].gap_m);
    consider(wedge.samples[k].gap_m - depth);
  }
  WedgeLeak leak;
  leak.area_m2 = best;
  for (int k = 0; k < wedge.n_samples; ++k) {
    const GapSample& s = wedge.samples[k];
    const double w = openness(s.gap_m);
    leak.jet_area_m2 += s.area_m2 * w * w;
    leak.sealed_area_m2 += s.area_m2 * (1.0 - w);
  }
  leak.jet_area_m2 = std::min(leak.jet_area_m2, leak.area_m2);
  return leak;
}

ChamberLeaks LeakAreas(const CupGeometry& geometry, const OpeningWedge* wedges, int n_wedges) {
  ChamberLeaks leaks;
  for (int i = 0; i < n_wedges; ++i) {
    const WedgeLeak w = WedgeLeakArea(geometry, wedges[i]);
    const int c = wedges[i].chamber;
    leaks.area_m2[c] += w.area_m2;
    leaks.jet_area_m2[c] += w.jet_area_m2;
    leaks.sealed_area_m2[c] += w.sealed_area_m2;
  }
  return leaks;
}

namespace {

// Fills one wedge per ray from a depth field below the lip plane (negative or zero = at or above
// the tips, i.e. touching) and the radii where the field jumps (sharp edges) along each ray.
template <typename DepthAt, typename JumpsAlong>
EdgeProbe ProbeField(const CupGeometry& geometry, DepthAt depth_at, JumpsAlong jumps_along) {
  EdgeProbe probe;
  const int m = geometry.rays_per_chamber;
  const double radius = geometry.opening_radius_m;
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < m; ++j) {
      const double a = RayAngle(c, j, m);
      const double ux = std::cos(a), uy = std::sin(a);
      OpeningWedge& w = probe.wedges[probe.n_wedges++];
      w.chamber = c;
      w.dtheta_rad = kHalfPi / m;
      w.rim_gap_m = std::max(0.0, depth_at(radius * ux, radius * uy));
      // Stretches between jumps, each finely split so curved fields are resolved.
      double cuts[kMaxCrossings + 2];
      int n_cuts = 0;
      cuts[n_cuts++] = 0.0;
      n_cuts += jumps_along(ux, uy, cuts + n_cuts);
      cuts[n_cuts++] = radius;
      constexpr int kPieces = 3;  // per stretch: 3 x kSamplesPerStretch samples
      for (int s = 0; s + 1 < n_cuts; ++s) {
        for (int p = 0; p < kPieces; ++p) {
          const double r0 = std::sqrt(
              cuts[s] * cuts[s] + (cuts[s + 1] * cuts[s + 1] - cuts[s] * cuts[s]) * p / kPieces);
          const double r1 =
              std::sqrt(cuts[s] * cuts[s] +
                        (cuts[s + 1] * cuts[s + 1] - cuts[s] * cuts[s]) * (p + 1) / kPieces);
          double rs[kSamplesPerStretch], gaps[kSamplesPerStretch];
          StretchSampleRadii(r0, r1, rs);
          for (int k = 0; k < kSamplesPerStretch; ++k) {
            gaps[k] = std::max(0.0, depth_at(rs[k] * ux, rs[k] * uy));
          }
          AddStretch(r0, r1, gaps, &w);
        }
      }
    }
  }
  return probe;
}

}  // namespace

EdgeProbe ProbeStraightEdge(const CupGeometry& geometry, double edge_offset_m,
                            double normal_angle_rad) {
  return ProbeRoundedEdge(geometry, edge_offset_m, normal_angle_rad, 0.0);
}

EdgeProbe ProbeRoundedEdge(const CupGeometry& geometry, double edge_offset_m,
                           double normal_angle_rad, double fillet_radius_m) {
  const double nx = std::cos(normal_angle_rad), ny = std::sin(normal_angle_rad);
  const double rho = std::max(0.0, fillet_radius_m);
  // Distance beyond where the rounding starts: flat top before, quarter circle, then nothing.
  auto depth_at = [=](double x, double y) {
    const double beyond = nx * x + ny * y - edge_offset_m;
    if (beyond <= 0.0) return 0.0;
    if (beyond >= rho) return kNoSurfaceGapM;
    return rho - std::sqrt(rho * rho - beyond * beyond);
  };
  auto jumps_along = [=](double ux, double uy, double* out) {
    const double nu = nx * ux + ny * uy;
    const double r = std::fabs(nu) > 1e-12 ? (edge_offset_m + rho) / nu : -1.0;
    if (std::fabs(nu) > 1e-12 && r > 0.0 && r < geometry.opening_radius_m) {
      out[0] = r;
      return 1;
    }
    return 0;
  };
  return ProbeField(geometry, depth_at, jumps_along);
}

EdgeProbe ProbeSlopedPlate(const CupGeometry& geometry, double slope, double normal_angle_rad) {
  const double nx = std::cos(normal_angle_rad), ny = std::sin(normal_angle_rad);
  const double radius = geometry.opening_radius_m;
  auto depth_at = [=](double x, double y) { return slope * (nx * x + ny * y + radius); };
  auto no_jumps = [](double, double, double*) { return 0; };
  return ProbeField(geometry, depth_at, no_jumps);
}

}  // namespace ssc

namespace ssc {

EdgeProbe ProbeFlatPlate(const CupGeometry& geometry, double gap_m) {
  auto depth_at = [=](double, double) { return gap_m; };
  auto no_jumps = [](double, double, double*) { return 0; };
  return ProbeField(geometry, depth_at, no_jumps);
}

FlowSolution SolveProbe(const CupGeometry& geometry, const PneumaticParams& params,
                        const EdgeProbe& probe) {
  const ChamberLeaks leaks = LeakAreas(geometry, probe.wedges.data(), probe.n_wedges);
  return SolveFlowNetwork(params, leaks.area_m2, nullptr, &leaks.jet_area_m2);
}

}  // namespace ssc
