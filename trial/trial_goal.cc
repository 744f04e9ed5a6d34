#include "trial/trial_goal.h"

#include <algorithm>
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

TrialGoal TrialGoal::AroundDisk(const Point2& centre, double radius_m) {
  TrialGoal g = SweptAngle(centre, kLoopSweepDeg);
  g.band_m = kFollowBandM;
  if (2 * radius_m < kCupOpeningDiameterMm * 1e-3) {
    std::ostringstream os;
    os << "a disk of " << 2e3 * radius_m << " mm is smaller than the cup's "
       << kCupOpeningDiameterMm << " mm opening: the cup covers it, it does not follow its edge";
    g.never_followed = os.str();
  }
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
  } else if (!std::isnan(start_arc_m) && !(start_arc_m >= 0 && start_arc_m <= goal_arc_m)) {
    os << "goal start_arc_m = " << start_arc_m << " is out of range [0, goal_arc_m = " << goal_arc_m
       << "] m";
  }
  if (!std::isfinite(band_m) || band_m < 0 || band_m > 1) {
    os << "goal band_m = " << band_m << " is out of range [0, 1] m";
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
  start_radius_m_ = std::hypot(p[0] - goal_.centre[0], p[1] - goal_.centre[1]);
  arc_m_ = 0;
  max_distance_m_ = 0;
  path_m_ = 0;
  last_ = p;
  left_band_ = false;
  if (!edge_) return;
  if (goal_.kind == TrialGoal::Kind::kGoalPoint && std::isfinite(goal_.start_arc_m)) {
    Track(p, goal_.start_arc_m - kArcTrackWindowM, goal_.start_arc_m + kArcTrackWindowM);
  } else {
    Track(p, 0, edge_->Length());
  }
}

void GoalTracker::Add(const Point2& p) {
  path_m_ += std::hypot(p[0] - last_[0], p[1] - last_[1]);
  last_ = p;
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) sweep_.Add(p[0], p[1]);
  if (edge_) Track(p, arc_m_ - kArcTrackWindowM, ForwardReach(p));
}

double GoalTracker::ForwardReach(const Point2& p) const {
  double reach = arc_m_ + kArcTrackWindowM;
  if (goal_.band_m <= 0) return reach;
  // With a band, the edge ahead that lies under the cup body (within the band of the cup centre)
  // is covered: a corner whose apex passes under the body is followed round it however sharp,
  // while a part of the edge reached only across open ground stays out of reach.
  const double end = edge_->closed() ? arc_m_ + edge_->Length() : edge_->Length();
  for (double s = arc_m_ + kReachStepM; s <= end; s += kReachStepM) {
    const Point2 q = edge_->PointAt(s);
    if (std::hypot(q[0] - p[0], q[1] - p[1]) > goal_.band_m) break;
    reach = std::max(reach, s);
  }
  return reach;
}

void GoalTracker::Track(const Point2& p, double s_min, double s_max) {
  const ContourProjection pr = edge_->ProjectWithin(p[0], p[1], s_min, s_max);
  arc_m_ = pr.arc_m;
  max_distance_m_ = std::max(max_distance_m_, pr.distance_m);
  // Once lost, the goal stays lost (a trial that reached it first has already ended).
  if (!left_band_ && goal_.band_m > 0 && pr.distance_m > goal_.band_m && !ProgressReached()) {
    left_band_ = true;
    left_at_ = p;
  }
}

double GoalTracker::Progress() const {
  return goal_.sweep_deg < 0 ? -sweep_.swept_deg() : sweep_.swept_deg();
}

double GoalTracker::progress_m() const {
  if (goal_.kind == TrialGoal::Kind::kGoalPoint) return arc_m_;
  const double loop_m = edge_ ? edge_->Length() : 2 * M_PI * start_radius_m_;
  return Progress() / 360.0 * loop_m;
}

double GoalTracker::PathNeededM() const {
  if (goal_.kind != TrialGoal::Kind::kGoalPoint || !std::isfinite(goal_.start_arc_m)) return 0;
  return std::max(0.0, goal_.goal_arc_m - goal_.start_arc_m - 2 * goal_.band_m);
}

bool GoalTracker::ProgressReached() const {
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) return Progress() >= std::fabs(goal_.sweep_deg);
  return edge_ != nullptr && arc_m_ >= goal_.goal_arc_m && path_m_ >= PathNeededM();
}

GoalStatus GoalTracker::status() const {
  // A band needs the edge to measure against: without one the goal can never be followed.
  if (left_band_ || (goal_.band_m > 0 && !edge_)) return GoalStatus::kLost;
  if (!ProgressReached()) return GoalStatus::kPending;
  return goal_.never_followed.empty() ? GoalStatus::kReached : GoalStatus::kLost;
}

std::string GoalTracker::Detail() const {
  std::ostringstream os;
  if (left_band_) {
    os << "left the " << goal_.band_m * 1e3 << " mm band about the edge at (" << left_at_[0] * 1e3
       << ", " << left_at_[1] * 1e3 << ") mm, " << arc_m_ * 1e3 << " mm along it";
    return os.str();
  }
  if (goal_.band_m > 0 && !edge_) return "a band of following needs the edge";
  if (goal_.kind == TrialGoal::Kind::kSweptAngle) {
    os << "swept " << Progress() << " deg";
  } else {
    os << "reached the goal point, " << arc_m_ * 1e3 << " mm along the edge";
    if (arc_m_ >= goal_.goal_arc_m && path_m_ < PathNeededM()) {
      os << " under the body, but the cup moved " << path_m_ * 1e3 << " mm of the "
         << PathNeededM() * 1e3 << " mm needed";
    }
  }
  if (!goal_.never_followed.empty() && ProgressReached()) os << ", but " << goal_.never_followed;
  return os.str();
}

}  // namespace ssc
