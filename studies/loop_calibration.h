// Closed-loop calibration of the static pneumatic curve (`ssc calibrate --closed-loop`).
//
// The published depths (dr -0.7 / -2.5 / -3.2 mm at beta 1.5, P_ref 40 / 100 / 200 Pa, dL 5 mm)
// are where the robot's closed loop rode, not static equilibria. The open-loop calibration takes
// the static probe's mean vacuum at those depths to be P_ref; the twin's own loop then rides
// elsewhere (deeper at 40 Pa, where the law's gain on the open side of P_ref is four times the
// gain on the covered side, so noise pushes the cup in; shallower at 100-200 Pa, where the disk
// curving away asks for a standing correction toward the object). This fit moves the static
// pressures the depth targets ask for until the twin's loop rides at the published depths:
//   repeat: fit the pneumatic model to pressures q (calibration/pneumatic_fit.h); run the loop
//   (beta 1.5, dL 5 mm, the given effects, `seeds` common seeds per P_ref); for each P_ref,
//   q <- q * Pstatic(the loop's mean depth) / Pstatic(published depth).
// The differential, air and plate targets stay as they are.
#ifndef SSC_STUDIES_LOOP_CALIBRATION_H_
#define SSC_STUDIES_LOOP_CALIBRATION_H_

#include <functional>
#include <string>
#include <vector>

#include "calibration/pneumatic_fit.h"
#include "runtime/trial.h"
#include "studies/tool_variants.h"

namespace ssc {

// The plugin config keys of a static fit (its parameters, as MJCF text), for a tool variant or
// a calibrated tool model.
PluginConfig FittedPluginConfig(const PneumaticFit& fit);

struct LoopCalibrationSpec {
  PneumaticModel start;    // where the first static fit starts
  std::string scene_path;  // a disk scene with the tool (read once; variants compiled in memory)
  TrialConfig base;        // everything but P_ref, beta, step and seed
  int seeds = 10;          // trials per P_ref per iteration (the sweep's seeds, base seed 1)
  int iterations = 4;      // outer iterations, >= 1
  int threads = 2;
};

struct LoopCalibrationIteration {
  StaticDepthPressures depth_pa{};      // static pressures the fit was asked for
  PneumaticFit fit;                     // the static fit at those pressures
  std::array<double, 3> loop_dr_mm{};   // the loop's mean dr at each P_ref (successes; all if none)
  std::array<int, 3> loop_successes{};  // of `seeds`
};

struct LoopCalibrationResult {
  std::vector<LoopCalibrationIteration> iterations;
  int best = 0;  // the iteration whose loop depths are closest to the published (RMS)
  double RmsDepthErrorMm(int i) const;
};

// Runs the iterations; `progress` gets one line per iteration. False + *error when the scene
// cannot be read or a variant cannot be compiled.
bool CalibrateClosedLoop(const LoopCalibrationSpec& spec,
                         const std::function<void(const std::string&)>& progress,
                         LoopCalibrationResult* result, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_LOOP_CALIBRATION_H_
