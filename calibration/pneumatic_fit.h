// Calibrating the pneumatic model to the published disk results (pure C++, the analytic
// straight-edge probe): the offsets where the mean vacuum is 40, 100 and 200 Pa (0.7, 2.5,
// 3.2 mm inside the edge, from the published dr at those P_ref), the differential at 100 Pa
// (about 200 Pa), the cup in air (< 5 Pa) and on a plate (every chamber > 10 kPa).
#ifndef SSC_CALIBRATION_PNEUMATIC_FIT_H_
#define SSC_CALIBRATION_PNEUMATIC_FIT_H_

#include <string>
#include <vector>

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

// Evaluates the targets for a model (fills FitTarget::model).
std::vector<FitTarget> EvaluatePublishedTargets(const PneumaticModel& model);

// Fits pump free flow, port area, jet area and lip roughness (log scale) from `start`.
PneumaticFit FitPublishedTargets(const PneumaticModel& start);

}  // namespace ssc

#endif  // SSC_CALIBRATION_PNEUMATIC_FIT_H_
