// Calibrating the pneumatic model to the published disk results (pure C++, the analytic
// straight-edge probe): the offsets where the mean vacuum is 40, 100 and 200 Pa (0.7, 2.5,
// 3.2 mm inside the edge, from the published dr at those P_ref), the differential at 100 Pa
// (about 200 Pa), the cup in air (< 5 Pa) and on a plate (every chamber > 10 kPa).
#ifndef SSC_CALIBRATION_PNEUMATIC_FIT_H_
#define SSC_CALIBRATION_PNEUMATIC_FIT_H_

#include <array>
#include <string>
#include <vector>

#include "calibration/published_targets.h"
#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/flow_network.h"

namespace ssc {

struct PneumaticModel {
  PneumaticParams pneumatics;
  CupGeometry geometry;
};

struct FitTarget {
  std::string name, unit;
  double target, scale;  // residual = (model - target) / scale
  double model = 0;
  double residual() const { return (model - target) / scale; }
};

// The fitted parameters, in the order of their log-scale coordinates.
struct FitParameter {
  std::string key;         // plugin config key
  double value = 0;        // in the key's unit
  double sensitivity = 0;  // d(cost) / d(log value) at the optimum
};

struct PneumaticFit {
  PneumaticModel model;
  std::vector<FitTarget> targets;
  std::vector<FitParameter> parameters;
  double cost = 0;
  int evaluations = 0;
};

// The published P_ref of the three depth targets, and where the cup rode at each (mm inside the
// disk edge, the published -dr at beta 1.5): calibration/published_targets.h.
inline constexpr std::array<double, 3> kDepthTargetPrefPa = kPublishedDepthPrefPa;
inline constexpr std::array<double, 3> kDepthTargetOffsetMm = kPublishedDepthMm;

// The static mean vacuum the depth targets ask for at those offsets. The published depths are
// closed-loop results: P_ref is where the loop aims, not necessarily what the static probe reads
// where the cup rode. By default the two are taken equal (the open-loop reading); a closed-loop
// calibration (studies/loop_calibration.h) moves them to what the twin's loop actually settles on.
using StaticDepthPressures = std::array<double, 3>;
inline constexpr StaticDepthPressures kOpenLoopDepthPressures = kDepthTargetPrefPa;

// The fit's starting model: the defaults with the four fitted parameters multiplied by `scale`
// (ssc calibrate --start-scale: a fit that finds its way back tests the fit).
PneumaticModel ScaledFitStart(double scale);

// Evaluates the targets for a model (fills FitTarget::model): the offsets where the static mean
// vacuum is `depth_pa`, the differential at the middle one.
std::vector<FitTarget> EvaluatePublishedTargets(
    const PneumaticModel& model, const StaticDepthPressures& depth_pa = kOpenLoopDepthPressures);

// Fits pump free flow, port area, jet area and lip roughness (log scale) from `start`.
PneumaticFit FitPublishedTargets(const PneumaticModel& start,
                                 const StaticDepthPressures& depth_pa = kOpenLoopDepthPressures);

// Static mean vacuum with the cup centre `offset_m` inside a straight sharp edge, Pa.
double StaticMeanVacuum(const PneumaticModel& model, double offset_m);

// The next static pressures of a closed-loop calibration (studies/loop_calibration.h): each q
// scaled by Pstatic(loop depth) / Pstatic(published depth) on the iteration's fitted model, the
// factor clamped to [0.5, 2] so one noisy iteration cannot throw the fit far.
StaticDepthPressures NextDepthPressures(const PneumaticModel& model,
                                        const StaticDepthPressures& current,
                                        const std::array<double, 3>& loop_dr_mm);

}  // namespace ssc

#endif  // SSC_CALIBRATION_PNEUMATIC_FIT_H_
