// How a trial ends, as pure logic: the outcomes and their names (the one home of both), the
// swept angle about a centre, and the classification of one filtered sample into running /
// success / failure I / failure II / unstable / timeout (the implementation tested each on a
// single filtered sample). What counts as success is the trial's goal (trial_goal.h).
#ifndef SSC_CONTROLLER_PURE_TRIAL_OUTCOME_H_
#define SSC_CONTROLLER_PURE_TRIAL_OUTCOME_H_

#include <array>
#include <string>

namespace ssc {

struct TrialThresholds {
  double off_edge_pa = 5.0;            // failure I below this mean vacuum (disk script: 5 Pa)
  double grasp_pa = 10000.0;           // failure II when ALL four chambers exceed this
  double max_contact_force_n = 100.0;  // safety: unstable beyond this |F/T| force
  // A controller's hop (ControllerCommand::lifted) pauses failures I and II for at most this
  // long at a time; longer in the air is failure I.
  double max_lifted_s = 5.0;
};

// kLostEdge: the trial's goal can no longer count as followed: the cup centre left the band
// about the edge, or it circled a feature its opening covers whole (trial_goal.h).
// kControllerFault: the controller returned a non-finite or out-of-range command
// (controller/pure/controller.h).
enum class Outcome {
  kRunning,
  kSuccess,
  kFailureOffEdge,
  kFailureGrasp,
  kTimeout,
  kUnstable,
  kLostEdge,
  kControllerFault
};

// The text form, as written in tables and summaries: "running", "success", "failure_I",
// "failure_II", "timeout", "unstable", "lost_edge", "controller_fault".
const char* OutcomeName(Outcome outcome);

// Signed swept angle of a point about a centre, unwrapped (counter-clockwise positive seen from
// above with world z up).
class SweepTracker {
 public:
  void Reset(double centre_x, double centre_y, double x, double y);
  void Add(double x, double y);
  double swept_deg() const { return swept_rad_ * 57.29577951308232; }

 private:
  double cx_ = 0, cy_ = 0, last_angle_ = 0, swept_rad_ = 0;
  bool started_ = false;
};

struct SampleCheck {
  Outcome outcome = Outcome::kRunning;
  std::string detail;  // the value that decided, with units
};

// Where the trial stands against its goal (GoalTracker::status()).
enum class GoalStatus { kPending, kReached, kLost };

// Classifies one sample. Order: unstable (non-finite input, force beyond the safety limit), lost
// edge, success (the goal is reached), failure II, failure I, timeout. For the two goal outcomes
// the caller words the detail (GoalTracker::Detail()).
SampleCheck ClassifySample(const TrialThresholds& t, const std::array<double, 4>& p_pa,
                           double contact_force_n, GoalStatus goal, double elapsed_s,
                           double timeout_s);

}  // namespace ssc

#endif  // SSC_CONTROLLER_PURE_TRIAL_OUTCOME_H_
