#include "controller/pure/trial_outcome.h"

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
  }
  return "?";
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
