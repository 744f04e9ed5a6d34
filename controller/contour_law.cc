#include "controller/contour_law.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ssc {

std::string ContourLawParams::Validate() const {
  std::ostringstream os;
  auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(p_noise_pa) || p_noise_pa <= 0) {
    os << "p_noise_pa (P_n) = " << p_noise_pa << " must be > 0 Pa and below P_ref";
  } else if (!finite(p_ref_pa) || p_ref_pa <= p_noise_pa || p_ref_pa >= p_grasp_pa) {
    os << "pref_pa (P_ref) = " << p_ref_pa << " is out of range (" << p_noise_pa << ", "
       << p_grasp_pa << ") Pa (between P_n and P_g)";
  } else if (!finite(p_grasp_pa) || p_grasp_pa >= 1e6) {
    os << "p_grasp_pa (P_g) = " << p_grasp_pa << " is out of range (P_ref, 1e6) Pa";
  } else if (!finite(beta) || beta < 0 || beta > 100) {
    os << "beta = " << beta << " is out of range [0, 100]";
  } else if (!finite(step_mm) || step_mm < kMinStepMm || step_mm > kMaxStepMm) {
    os << "step_mm (dL) = " << step_mm << " is out of range [" << kMinStepMm << ", " << kMaxStepMm
       << "] mm" << (step_mm > 0 && step_mm < kMinStepMm ? " (metres given as mm?)" : "");
  }
  return os.str();
}

double CorrectionFactor(double p_mean_pa, const ContourLawParams& params) {
  // log10 of a non-positive mean (pure noise) is taken at a floor 3 decades below P_n: far off
  // the object, steer toward it hard but finitely.
  const double floor_pa = params.p_noise_pa * 1e-3;
  const double x = std::log10(std::max(p_mean_pa, floor_pa));
  const double xn = std::log10(params.p_noise_pa);
  const double xr = std::log10(params.p_ref_pa);
  const double xg = std::log10(params.p_grasp_pa);
  if (x <= xr) return params.beta * (xr - x) / (xr - xn);
  return -params.beta * (x - xr) / (xg - xr);
}

ContourStep ComputeContourStep(const std::array<double, 4>& p, const ContourLawParams& params) {
  ContourStep s;
  s.p_south_pa = 0.5 * (p[0] + p[3]);
  s.p_north_pa = 0.5 * (p[1] + p[2]);
  s.p_west_pa = 0.5 * (p[2] + p[3]);
  s.p_east_pa = 0.5 * (p[0] + p[1]);
  s.dpx_pa = s.p_north_pa - s.p_south_pa;
  s.dpy_pa = s.p_west_pa - s.p_east_pa;
  s.p_mean_pa = 0.25 * (s.p_north_pa + s.p_south_pa + s.p_west_pa + s.p_east_pa);
  // north = -x_tool, west = +y_tool.
  s.g = {-s.dpx_pa, s.dpy_pa};
  s.cf = CorrectionFactor(s.p_mean_pa, params);
  const double g_norm = std::hypot(s.g[0], s.g[1]);
  const bool outside_dead_band = !params.dead_band || std::fabs(s.dpx_pa) > params.p_noise_pa ||
                                 std::fabs(s.dpy_pa) > params.p_noise_pa;
  if (!(g_norm > 0) || !std::isfinite(g_norm) || !outside_dead_band) return s;
  s.correction = {s.g[0] / g_norm, s.g[1] / g_norm};
  // Seen from above, +z_tool points away from the viewer, so "turn clockwise as seen from above"
  // (object ends up on the left) is +90 deg about +z_tool: (x, y) -> (-y, x).
  if (params.side == FollowSide::kObjectOnLeft) {
    s.along_edge = {-s.correction[1], s.correction[0]};
  } else {
    s.along_edge = {s.correction[1], -s.correction[0]};
  }
  const double fx = s.along_edge[0] + s.cf * s.correction[0];
  const double fy = s.along_edge[1] + s.cf * s.correction[1];
  const double f_norm = std::hypot(fx, fy);  // >= 1: along_edge is orthogonal to correction
  s.direction = {fx / f_norm, fy / f_norm};
  s.moving = true;
  s.step_m = {params.step_mm * 1e-3 * s.direction[0], params.step_mm * 1e-3 * s.direction[1]};
  return s;
}

}  // namespace ssc
