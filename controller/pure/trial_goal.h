// What completes a contour-following trial, and how far along it the cup is. Pure C++.
//
//   swept angle (closed contours: disks, holes): the cup centre's swept angle about a centre
//     passes a signed target (> 0 counter-clockwise seen from above);
//   goal point (open contours: corners, strips, the fillet): the cup's tracked position along
//     the edge passes the goal point's arc position.
//
// The tracked arc position follows the cup along the edge: each sample may move it at most
// kArcTrackWindowM from the previous one, so it cannot jump to another part of the contour that
// passes close by.
#ifndef SSC_CONTROLLER_PURE_TRIAL_GOAL_H_
#define SSC_CONTROLLER_PURE_TRIAL_GOAL_H_

#include <memory>
#include <string>

#include "controller/pure/trial_outcome.h"
#include "geometry/contour_path.h"
#include "geometry/dimensions.h"
#include "geometry/point2.h"

namespace ssc {

inline constexpr double kLoopSweepDeg = 355;      // the implementation's "one loop"
inline constexpr double kArcTrackWindowM = 0.010;  // largest move of the tracked arc position

struct TrialGoal {
  enum class Kind { kSweptAngle, kGoalPoint };
  Kind kind = Kind::kSweptAngle;
  Point2 centre{kWorkspaceX, kWorkspaceY};  // kSweptAngle: the swept angle is measured about it
  double sweep_deg = kLoopSweepDeg;         // kSweptAngle: signed, > 0 counter-clockwise
  double goal_arc_m = 0;                    // kGoalPoint: arc position of the goal on the edge

  static TrialGoal SweptAngle(const Point2& centre, double sweep_deg);
  static TrialGoal GoalPoint(double goal_arc_m);
  // Empty when valid, else names the field and its range.
  std::string Validate() const;
};

// Progress toward a goal along a trial's follow phase.
class GoalTracker {
 public:
  // Starts at the cup position p. `edge` (may be null) is the true contour: the tracked arc
  // position needs it, and a kGoalPoint goal is never reached without it.
  void Start(const TrialGoal& goal, std::shared_ptr<const ContourPath> edge, const Point2& p);
  // One path sample.
  void Add(const Point2& p);

  bool reached() const;
  // Why the goal counts as reached, with the deciding value ("swept 356.1 deg").
  std::string ReachedDetail() const;
  double swept_deg() const { return sweep_.swept_deg(); }  // signed, 0 for kGoalPoint goals
  double arc_m() const { return arc_m_; }                  // tracked arc position (edge given)

 private:
  double Progress() const;  // kSweptAngle: swept angle in the goal's sense, deg

  TrialGoal goal_;
  std::shared_ptr<const ContourPath> edge_;
  SweepTracker sweep_;
  double arc_m_ = 0;
};

}  // namespace ssc

#endif  // SSC_CONTROLLER_PURE_TRIAL_GOAL_H_
