#include "controller/pure/trial_goal.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace ssc {

TrialGoal TrialGoal::SweptAngle(const Point2& centre, double sweep_deg) {
  TrialGoal g;
  g.kind = Kind::kSweptAngle;
  g.centre = centre;
  g.sweep_deg = sweep_deg;
  return g;
}

TrialGoal TrialGoal::GoalPoint(double goal_arc_m) {
  TrialGoal g;
  g.kind = Kind::kGoalPoint;
  g.goal_arc_m = goal_arc_m;
  return g;
}

std::string TrialGoal::Validate() const {
  std::ostringstream os;
  if (kind == Kind::kSweptAngle) {
    if (!std::isfinite(centre[0]) || !std::isfinite(centre[1])) return "goal centre must be finite";
    if (!std::isfinite(sweep_deg) || std::fabs(sweep_deg) < 1 || std::fabs(sweep_deg) > 3600) {
      os << "goal sweep_deg = " << sweep_deg << " is out of range +-[1, 3600] deg";
    }
  } else if (!std::isfinite(goal_arc_m) || goal_arc_m < 0) {
    os << "goal goal_arc_m = " << goal_arc_m << " is out of range [0, inf) m";
  }
  return os.str();
}

void GoalTracker::Start(const TrialGoal& goal, std::shared_ptr<const ContourPath> edge,
                        const Point2& p) {
  goal_ = goal;
  edge_ = std::move(edge);
  sweep_ = SweepTracker();
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) {
    sweep_.Reset(goal_.centre[0], goal_.centre[1], p[0], p[1]);
  }
  arc_m_ = edge_ ? edge_->ArcPosition(p[0], p[1]) : 0.0;
}

void GoalTracker::Add(const Point2& p) {
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) sweep_.Add(p[0], p[1]);
  if (edge_) {
    arc_m_ = edge_->ProjectWithin(p[0], p[1], arc_m_ - kArcTrackWindowM, arc_m_ + kArcTrackWindowM)
                 .arc_m;
  }
}

double GoalTracker::Progress() const {
  return goal_.sweep_deg < 0 ? -sweep_.swept_deg() : sweep_.swept_deg();
}

bool GoalTracker::reached() const {
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) return Progress() >= std::fabs(goal_.sweep_deg);
  return edge_ != nullptr && arc_m_ >= goal_.goal_arc_m;
}

std::string GoalTracker::ReachedDetail() const {
  std::ostringstream os;
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) {
    os << "swept " << Progress() << " deg";
  } else {
    os << "reached the goal point, " << arc_m_ * 1e3 << " mm along the edge";
  }
  return os.str();
}

}  // namespace ssc
