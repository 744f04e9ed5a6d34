// What the viewer draws on top of the scene: the cup-centre trace, the controller's direction,
// correction and step vectors at the cup, per-chamber text, and the live pressure figures.
#ifndef SSC_VIEWER_OVERLAY_H_
#define SSC_VIEWER_OVERLAY_H_

#include <mujoco/mujoco.h>

#include <array>
#include <string>

#include "plugin/chamber_pressure_sensor.h"
#include "runtime/trial.h"

namespace ssc {

// Adds decoration geoms (trace and vectors) to the scene; stops politely when it is full.
void AddTrialDecorations(const mjModel* m, const mjData* d, const ContourTrial& trial,
                         int tool_site, mjvScene* scn);

// What the overlay shows now, in every phase: the sensor's current filtered pressures (not only
// the values of the last control iteration), their mean and differentials, and the c_f of the
// last iteration. One function for the text, the figures and the printed check line.
struct OverlayValues {
  double t_s = 0;
  TrialPhase phase = TrialPhase::kApproach;
  std::array<double, 4> p_pa{};
  double mean_pa = 0, dpx_pa = 0, dpy_pa = 0;
  double cf = 0;  // last control iteration (0 before following starts)
  int iterations = 0;
};
OverlayValues CurrentOverlayValues(const ContourTrial& trial, const mjData* d);
// One line for tests and logs: "overlay t=.. phase=.. p_pa=a,b,c,d mean_pa=.. cf=.."
std::string OverlayValuesLine(const OverlayValues& v);

// Live figures: the four chamber pressures and their mean on a log axis with the reference
// lines P_n, P_ref and P_g; the correction factor c_f.
class PressureFigures {
 public:
  PressureFigures();
  void Reset();
  void Add(const OverlayValues& v, const ContourLawParams& law);
  mjvFigure& pressures() { return pressures_; }
  mjvFigure& correction() { return correction_; }

 private:
  mjvFigure pressures_, correction_;
  double last_t_ = -1;
};

// The text panel: parameters, phase, outcome and live metrics. realtime_factor < 0 (off-screen
// shots, where it means nothing) leaves it out.
std::string TrialStatusText(const ContourTrial& trial, const OverlayValues& values,
                            double realtime_factor, bool paused, double speed,
                            const ChamberPressureDiagnostics* sensor);
std::string ViewerHelpText();

}  // namespace ssc

#endif  // SSC_VIEWER_OVERLAY_H_
