// What the viewer draws on top of the scene: the cup-centre trace, the controller's direction,
// correction and step vectors at the cup, per-chamber text, and the live pressure figures.
#ifndef SSC_VIEWER_OVERLAY_H_
#define SSC_VIEWER_OVERLAY_H_

#include <string>

#include <mujoco/mujoco.h>

#include "runtime/trial.h"
#include "plugin/chamber_pressure_sensor.h"

namespace ssc {

// Adds decoration geoms (trace and vectors) to the scene; stops politely when it is full.
void AddTrialDecorations(const mjModel* m, const mjData* d, const ContourTrial& trial,
                         int tool_site, mjvScene* scn);

// Live figures: chamber pressures and mean P on a log10 axis with lines at P_n, P_ref and P_g;
// the correction factor c_f.
class PressureFigures {
 public:
  PressureFigures();
  void Reset();
  void Add(double t_s, const double p_pa[4], const ContourStep& step, const ContourLawParams& law);
  mjvFigure& pressures() { return pressures_; }
  mjvFigure& correction() { return correction_; }

 private:
  mjvFigure pressures_, correction_;
  double last_t_ = -1;
};

// The text panel: parameters, phase, outcome and live metrics.
std::string TrialStatusText(const ContourTrial& trial, double realtime_factor, bool paused,
                            double speed, const ChamberPressureDiagnostics* sensor);
std::string ViewerHelpText();

}  // namespace ssc

#endif  // SSC_VIEWER_OVERLAY_H_
