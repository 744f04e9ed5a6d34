// Edge tracking: an estimator of the edge from where the tool has been, and absolute targets on
// it, so that the arm's landing misses do not add up.
//
// The pressures are good at one thing and poor at another. The mean vacuum P-bar says how far
// the cup sits inside the edge (the static curve: monotonic over the band); the differential's
// direction snaps toward the chamber diagonals where the cup is partly off the object (+-15-20
// deg per iteration), a poor heading. The tool's measured positions, on the other hand, are
// exact. So, per iteration:
//   inset      how far the cup centre sits inside the edge, from P-bar (InsetFromMeanVacuumMm);
//   edge       the last fit_points tool positions, each moved out across the edge by its own
//              inset, fitted by a circle (a line when straight): the edge's place, heading and
//              curvature near the tool (FitEdgeArc);
//   target     inset_mm inside the fitted edge, at the previous target's place along it advanced
//              by speed_mm_s x the nominal period (at most max_lead_mm ahead of the tool's own
//              place); the step is that target minus the measured tool.
// The first start_iterations, before enough positions exist, run `fast` at start_step_mm on the
// same readings; so do those after a restart (restart_mm > 0: the reading's inset this far from
// the fit's where the tool is, as at a corner the fit could not see coming). With tare_in_air, the
// chambers' residual tare offsets are measured in air on the way down (AirTare) and subtracted from
// every reading.
#ifndef SSC_CONTROLLER_EDGE_TRACK_H_
#define SSC_CONTROLLER_EDGE_TRACK_H_

#include <array>
#include <cstddef>
#include <cstdint>

#include "controller/air_tare.h"
#include "controller/contour_law.h"
#include "controller/controller_registry.h"
#include "controller/fast_following.h"
#include "geometry/edge_arc.h"

namespace ssc {

struct EdgeTrackParams {
  double speed_mm_s = 75;           // the target's advance along the edge, per second
  double inset_mm = 1.25;           // the target's inset of the cup centre inside the edge
  double fit_points = 8;            // positions in the edge fit
  double start_iterations = 6;      // iterations run by `fast` before the fit takes over
  double start_step_mm = 3;         // `fast`'s step over those iterations
  double start_lateral_gain = 0.6;  // ... and its lateral_gain
  double max_lead_mm = 25;          // the target's lead along the edge ahead of the tool, at most
  double arm_reach = 0.5;           // the share of the way to its goal the arm covers in a period
  double restart_mm = 0;            // a reading this far from the fit's inset restarts (0: never)
  double circle_points = 5;         // positions needed before the fit may curve
  double max_across_mm = 5;         // the step across the fitted edge, at most
  double min_radius_mm = 5;         // the fitted edge turns no tighter than this
  double tare_in_air = 1;           // 1: re-tare the chambers in air on the way down (AirTare)
  double tare_clearance_mm = 4;     // ... from the readings this far above the hold height
};

// How far the cup centre sits inside a straight edge, mm, read from the mean vacuum: the
// static curve (the twin's at the control iterations of disk trials with the default effects,
// within 0.3 mm of the published points 40 Pa at 0.7 mm, 100 Pa at 2.5 mm, 200 Pa at 3.2 mm;
// docs/pneumatics.md), linear in log10(P-bar) between its points and held beyond its ends
// (below 10 Pa the curve is lost in the noise; above 7 kPa it is nearly flat). Not finite: the
// curve's value at 100 Pa.
double InsetFromMeanVacuumMm(double p_mean_pa);

class EdgeTrackController : public Controller {
 public:
  static constexpr std::size_t kMaxFitPoints = kEdgeArcMaxPoints;
  EdgeTrackController(const ControllerContext& context, const EdgeTrackParams& p);
  ControllerCommand Step(const ControllerInput& in) override;
  bool ObservesBeforeFollowing() const override { return p_.tare_in_air > 0; }
  void ObserveBeforeFollowing(const ControllerInput& in) override;
  // True once the edge fit steers (after start_iterations with enough positions).
  bool tracking() const { return tracking_; }
  const EdgeArc& edge() const { return edge_; }

 private:
  bool TrackStep(const std::array<double, 2>& tool_mm, const std::array<double, 9>& R,
                 ControllerCommand* c);
  ControllerContext context_;
  ContourLawParams law_;
  double period_s_;
  EdgeTrackParams p_;
  FastFollowingController start_;
  AirTare air_tare_;
  bool tared_ = false;
  std::array<double, 4> tare_pa_{};
  // The last positions (mm, world) and their insets (mm), oldest first.
  std::array<std::array<double, 2>, kMaxFitPoints> tool_mm_{};
  std::array<double, kMaxFitPoints> inset_mm_{};
  std::size_t count_ = 0;
  bool have_goal_ = false, tracking_ = false;
  std::uint64_t start_from_ = 0;     // the iteration `fast` last started at
  std::array<double, 2> goal_mm_{};  // where the last command sent the tool, world
  EdgeArc edge_;
};

ControllerType EdgeTrackControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_EDGE_TRACK_H_
