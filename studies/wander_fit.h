// Calibrating the sensor chain to the published wander of the cup: sigma_r and s_c against beta
// (P_ref 100 Pa). Each evaluation runs disk trials with fixed seeds (a deterministic objective)
// in a scene whose tool carries the candidate noise and lag; Nelder-Mead on log scales.
#ifndef SSC_STUDIES_WANDER_FIT_H_
#define SSC_STUDIES_WANDER_FIT_H_

#include <string>
#include <vector>

#include "calibration/pneumatic_fit.h"
#include "studies/tool_variants.h"
#include "trial/robot_effects.h"

namespace ssc {

struct WanderTarget {
  double beta;
  double sigma_r_mm;  // < 0: not a target
  double s_c;         // < -1: not a target
};

// The published means at P_ref 100 Pa (calibration/published_targets.h).
std::vector<WanderTarget> PublishedWanderTargets();

struct WanderFit {
  double noise_pa = 0, lag_ms = 0;
  double cost = 0;
  int evaluations = 0;
  std::vector<WanderTarget> model;  // the twin's sigma_r and s_c at each target beta
};

// Fits noise_pa and lag_ms from (noise0, lag0). `scene` is a disk scene with the tool; it is
// read once, and each evaluation compiles its tool variant in memory (studies/tool_variants.h).
// False + *error on read or load failure.
// `effects`: the robot effects its trials run with (the twin's defaults in ssc calibrate).
bool FitWander(const std::string& scene, const std::vector<WanderTarget>& targets, double step_mm,
               const RobotEffectsParams& effects, int seeds, int max_evaluations, double noise0,
               double lag0, WanderFit* fit, std::string* error);

// params.json of ssc calibrate: the static fit (cost, parameters, targets published vs model)
// and, when given, the wander fit (noise_pa, lag_ms, cost). One JSON object.
std::string CalibrationParamsJson(const PneumaticFit& fit, const WanderFit* wander);

// ssc_tool_calibrated.xml of ssc calibrate: `tool` with the static fit's config keys and, when
// given, the wander fit's noise_pa and lag_ms. Empty + *error when the tool cannot take them.
std::string CalibratedToolXml(const ToolModelVariants& tool, const PneumaticFit& fit,
                              const WanderFit* wander, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_WANDER_FIT_H_
