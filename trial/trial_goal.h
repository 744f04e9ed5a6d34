// What completes a contour-following trial, and how far along it the cup is. Pure C++.
//
//   swept angle (closed contours: disks, holes): the cup centre's swept angle about a centre
//     passes a signed target (> 0 counter-clockwise seen from above);
//   goal point (open contours: corners, strips, the fillet): the cup's tracked position along
//     the edge passes the goal point's arc position.
//
// Following (issue 12): with a band, the cup centre must stay within band_m of the edge it is
// tracking at every sample from the start to the goal; leaving the band loses the goal. A goal
// marked never_followed (a disk the cup's opening covers whole: the cup sits over it and turns
// about its centre without ever following the edge) is lost when it would have been reached.
//
// The tracked arc position follows the cup along the edge: each sample may move it at most
// kArcTrackWindowM from the previous one, so it cannot jump to another part of the contour that
// passes close by; with a band it may also move forward over any stretch of edge that lies
// under the cup body (within band_m of the cup centre): the apex of a sharp corner that passes
// under the body is followed round, one the cup turns back from short of it is not.
#ifndef SSC_TRIAL_TRIAL_GOAL_H_
#define SSC_TRIAL_TRIAL_GOAL_H_

#include <limits>
#include <memory>
#include <string>

#include "geometry/contour_path.h"
#include "geometry/dimensions.h"
#include "geometry/point2.h"
#include "trial/trial_outcome.h"

namespace ssc {

inline constexpr double kLoopSweepDeg = 355;       // the implementation's "one loop"
inline constexpr double kArcTrackWindowM = 0.010;  // largest move of the tracked arc position
inline constexpr double kReachStepM = 0.25e-3;     // resolution of the stretch under the body
// The band of following: the edge stays under the cup body (its radius), m.
inline constexpr double kFollowBandM = 0.5e-3 * kCupBodyDiameterMm;

struct TrialGoal {
  enum class Kind { kSweptAngle, kGoalPoint };
  Kind kind = Kind::kSweptAngle;
  Point2 centre{kWorkspaceX, kWorkspaceY};  // kSweptAngle: the swept angle is measured about it
  double sweep_deg = kLoopSweepDeg;         // kSweptAngle: signed, > 0 counter-clockwise
  double goal_arc_m = 0;                    // kGoalPoint: arc position of the goal on the edge
  // kGoalPoint: arc position of the start on the edge (NaN: unknown, the nearest point of the
  // whole edge). A thin wedge passes close to the start on its far side: the tracked position
  // starts here, not there.
  double start_arc_m = std::numeric_limits<double>::quiet_NaN();
  double band_m = 0;           // > 0: the cup centre must stay this close to the tracked edge
  std::string never_followed;  // non-empty: why this goal never counts as followed

  static TrialGoal SweptAngle(const Point2& centre, double sweep_deg);
  static TrialGoal GoalPoint(double goal_arc_m);
  // Counter-clockwise round a disk of radius_m about centre, within kFollowBandM; never
  // followed when the disk is smaller than the cup's opening.
  static TrialGoal AroundDisk(const Point2& centre, double radius_m);
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

  GoalStatus status() const;
  bool reached() const { return status() == GoalStatus::kReached; }
  // Why the goal is reached or lost, with the deciding value ("swept 356.1 deg").
  std::string Detail() const;
  double swept_deg() const { return sweep_.swept_deg(); }    // signed, 0 for kGoalPoint goals
  double arc_m() const { return arc_m_; }                    // tracked arc position (edge given)
  double path_m() const { return path_m_; }                  // the cup centre's path so far
  double max_distance_m() const { return max_distance_m_; }  // from the tracked edge so far
  // How far along the goal the cup is, m (the stall rule's measure): the tracked arc position
  // (goal points), or the swept angle in the goal's sense as a share of the edge's length
  // (swept-angle goals; without an edge, of the circle through the start point).
  double progress_m() const;

 private:
  double Progress() const;  // kSweptAngle: swept angle in the goal's sense, deg
  bool ProgressReached() const;
  // A goal point counts only after the cup centre covered the edge between start and goal less
  // what lies under its body at each end (2 band_m): a success needs a path.
  double PathNeededM() const;
  void Track(const Point2& p, double s_min, double s_max);
  // The largest arc position the tracked one may reach from p this sample.
  double ForwardReach(const Point2& p) const;

  TrialGoal goal_;
  std::shared_ptr<const ContourPath> edge_;
  SweepTracker sweep_;
  double arc_m_ = 0;
  double start_radius_m_ = 0;  // swept-angle goals: the start point's distance from the centre
  double max_distance_m_ = 0;
  double path_m_ = 0;
  Point2 last_{};
  bool left_band_ = false;
  Point2 left_at_{};
};

}  // namespace ssc

#endif  // SSC_TRIAL_TRIAL_GOAL_H_
