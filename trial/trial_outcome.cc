#include "trial/trial_outcome.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ssc {

const char* OutcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::kRunning:
      return "running";
    case Outcome::kSuccess:
      return "success";
    case Outcome::kFailureOffEdge:
      return "failure_I";
    case Outcome::kFailureGrasp:
      return "failure_II";
    case Outcome::kTimeout:
      return "timeout";
    case Outcome::kUnstable:
      return "unstable";
    case Outcome::kLostEdge:
      return "lost_edge";
    case Outcome::kControllerFault:
      return "controller_fault";
    case Outcome::kStalled:
      return "stalled";
  }
  return "?";
}

std::string ValidateStallRule(double stall_mm, double stall_window_s) {
  std::ostringstream os;
  if (!std::isfinite(stall_mm) || stall_mm <= 0 || stall_mm > 1000) {
    os << "stall_mm = " << stall_mm << " is out of range (0, 1000] mm";
  } else if (!std::isfinite(stall_window_s) || stall_window_s < 0 || stall_window_s > 3600) {
    os << "stall_window_s = " << stall_window_s << " is out of range [0, 3600] s (0: off)";
  }
  return os.str();
}

void StallWatch::Start(double stall_m, double window_s, double t_s, double progress_m) {
  stall_m_ = stall_m;
  window_s_ = window_s;
  mark_t_s_ = last_t_s_ = t_s;
  mark_m_ = furthest_m_ = progress_m;
}

bool StallWatch::Add(double t_s, double progress_m) {
  last_t_s_ = t_s;
  furthest_m_ = std::max(furthest_m_, progress_m);
  if (furthest_m_ > mark_m_ + stall_m_) {
    mark_t_s_ = t_s;
    mark_m_ = furthest_m_;
    return false;
  }
  return window_s_ > 0 && t_s - mark_t_s_ >= window_s_;
}

std::string StallWatch::Detail() const {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(2);
  os << 1e3 * (furthest_m_ - mark_m_) << " mm of progress over the last ";
  os.precision(1);
  os << last_t_s_ - mark_t_s_ << " s, " << 1e3 * stall_m_ << " mm or less in " << window_s_
     << " s is stalled (furthest " << 1e3 * furthest_m_ << " mm along the edge)";
  return os.str();
}

void SweepTracker::Reset(double centre_x, double centre_y, double x, double y) {
  cx_ = centre_x;
  cy_ = centre_y;
  last_angle_ = std::atan2(y - cy_, x - cx_);
  swept_rad_ = 0;
  started_ = true;
}

void SweepTracker::Add(double x, double y) {
  const double a = std::atan2(y - cy_, x - cx_);
  if (!started_) {
    last_angle_ = a;
    started_ = true;
    return;
  }
  // Increments are small between samples; unwrap across +-pi.
  swept_rad_ += std::remainder(a - last_angle_, 2 * M_PI);
  last_angle_ = a;
}

SampleCheck ClassifySample(const TrialThresholds& t, const std::array<double, 4>& p,
                           double contact_force_n, GoalStatus goal, double elapsed_s,
                           double timeout_s) {
  SampleCheck c;
  std::ostringstream os;
  for (double v : p) {
    if (!std::isfinite(v)) {
      c.outcome = Outcome::kUnstable;
      c.detail = "non-finite chamber pressure";
      return c;
    }
  }
  if (!std::isfinite(contact_force_n) || std::fabs(contact_force_n) > t.max_contact_force_n) {
    os << "contact force " << contact_force_n << " N beyond the safety limit "
       << t.max_contact_force_n << " N";
    c.outcome = Outcome::kUnstable;
    c.detail = os.str();
    return c;
  }
  if (goal == GoalStatus::kLost) {
    c.outcome = Outcome::kLostEdge;
    return c;
  }
  if (goal == GoalStatus::kReached) {
    c.outcome = Outcome::kSuccess;
    return c;
  }
  bool all_grasped = true;
  for (double v : p) all_grasped = all_grasped && v > t.grasp_pa;
  const double mean = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  if (all_grasped) {
    os << "all chambers above " << t.grasp_pa << " Pa (mean " << mean << " Pa)";
    c.outcome = Outcome::kFailureGrasp;
  } else if (mean < t.off_edge_pa) {
    os << "mean vacuum " << mean << " Pa below " << t.off_edge_pa << " Pa";
    c.outcome = Outcome::kFailureOffEdge;
  } else if (elapsed_s > timeout_s) {
    os << "no outcome after " << elapsed_s << " s";
    c.outcome = Outcome::kTimeout;
  }
  c.detail = os.str();
  return c;
}

}  // namespace ssc
