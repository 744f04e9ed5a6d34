// The published contour-following law of the Smart Suction Cup, as plain C++ (no MuJoCo).
//
// Conventions: pressures are vacuum relative to ambient, Pa, positive = vacuum, chambers 1..4 =
// indices 0..3 = south-east, north-east, north-west, south-west seen from above in the tool
// frame. Tool frame (the authors' implementation): +x toward the south chambers, +y toward the
// west chambers, +z down into the object. So north = -x_tool, west = +y_tool, and because +z
// points down, a turn that looks counter-clockwise from above is a clockwise turn about +z_tool.
//
// Per control iteration:
//   P_S = (P1+P4)/2, P_N = (P2+P3)/2, P_W = (P3+P4)/2, P_E = (P1+P2)/2
//   dPx = P_N - P_S, dPy = P_W - P_E
//   g = dPx * north + dPy * west        (points toward the covered side: the object)
//   v_hat = g_hat turned 90 deg so that the object lies on the left of the motion seen from
//           above (default), or on the right
//   P_mean = (P_N + P_S + P_W + P_E) / 4
//   c_f: piecewise linear in log10(P_mean): +beta at P_n, 0 at P_ref, -beta at P_g,
//        extrapolated (not clipped) outside [P_n, P_g]
//   v_f = v_hat + c_f * g_hat, normalised; step = step_mm * v_f_hat
//   dead band: no step unless |dPx| > P_n or |dPy| > P_n.
#ifndef SSC_CONTROLLER_CONTOUR_LAW_H_
#define SSC_CONTROLLER_CONTOUR_LAW_H_

#include <array>
#include <string>

namespace ssc {

enum class FollowSide { kObjectOnLeft, kObjectOnRight };

// The step dL's valid range, mm (every reader of a step uses it: options, maps, configs). Below
// 0.1 mm the cup barely moves within the servo's 0.2 mm tolerance; such a value is most likely
// metres given where millimetres belong.
inline constexpr double kMinStepMm = 0.1, kMaxStepMm = 100;

struct ContourLawParams {
  double p_ref_pa = 100.0;    // P_ref, set point of the mean vacuum, (P_n, P_g) Pa
  double beta = 2.0;          // correction gain, [0, 100], dimensionless
  double step_mm = 7.5;       // step length per iteration, [kMinStepMm, kMaxStepMm] mm
  double p_noise_pa = 10.0;   // P_n: c_f = +beta here; also the dead band, (0, P_ref) Pa
  double p_grasp_pa = 15000;  // P_g in the c_f line (the implementation's 15 kPa), (P_ref, 1e6)
  bool dead_band = true;      // hold still unless a differential exceeds P_n
  FollowSide side = FollowSide::kObjectOnLeft;

  // Empty when valid; otherwise names the field, its value and the valid range.
  std::string Validate() const;
};

// Everything the law computes in one iteration (for logging and overlays).
struct ContourStep {
  double p_south_pa = 0, p_north_pa = 0, p_west_pa = 0, p_east_pa = 0;
  double dpx_pa = 0, dpy_pa = 0;  // P_N - P_S, P_W - P_E
  double p_mean_pa = 0;
  std::array<double, 2> g{};           // toward the object, tool frame (Pa)
  std::array<double, 2> along_edge{};  // v_hat, unit, tool frame
  std::array<double, 2> correction{};  // g_hat, unit, tool frame
  double cf = 0;                       // signed correction factor
  std::array<double, 2> direction{};   // v_f_hat, unit (zero when no step)
  bool moving = false;                 // false inside the dead band or with g = 0
  std::array<double, 2> step_m{};      // tool frame, metres
};

ContourStep ComputeContourStep(const std::array<double, 4>& p_pa, const ContourLawParams& params);

// c_f as a function of the mean vacuum (exposed for plots and tests).
double CorrectionFactor(double p_mean_pa, const ContourLawParams& params);

}  // namespace ssc

#endif  // SSC_CONTROLLER_CONTOUR_LAW_H_
