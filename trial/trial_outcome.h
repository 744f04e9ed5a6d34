// How a trial ends, as pure logic: the outcomes and their names (the one home of both), the
// swept angle about a centre, and the classification of one filtered sample into running /
// success / failure I / failure II / unstable / timeout (the implementation tested each on a
// single filtered sample). What counts as success is the trial's goal (trial_goal.h).
#ifndef SSC_TRIAL_TRIAL_OUTCOME_H_
#define SSC_TRIAL_TRIAL_OUTCOME_H_

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
  // Stalled (StallWatch): the furthest point reached along the edge has not moved on by more
  // than stall_mm over stall_window_s of simulated time. 0 s: off (the disk trials); object
  // trials use kObjectStallMm / kObjectStallWindowS (studies/object_trials.cc).
  double stall_mm = 2.0;        // (0, 1000] mm
  double stall_window_s = 0.0;  // [0, 3600] s
};

// The object trials' stall rule (docs/objects.md, "Outcomes"). At dL 0.5 mm the law moves the
// cup at 0.5 mm x (1 - exp(-1)) / 0.15 s = 2.1 mm/s, so 20 s of free following covers about
// 42 mm: 2 mm over that window is under 5 % of the law's speed, and more than the arm's largest
// landing error (step_error_max_mm 1.43), so a cup held in place cannot count its jitter as
// progress.
inline constexpr double kObjectStallMm = 2.0;
inline constexpr double kObjectStallWindowS = 20.0;

// Empty when valid, else names the field and its range.
std::string ValidateStallRule(double stall_mm, double stall_window_s);

// kLostEdge: the trial's goal can no longer count as followed: the cup centre left the band
// about the edge, or it circled a feature its opening covers whole (trial_goal.h).
// kControllerFault: the controller returned a non-finite or out-of-range command
// (controller/controller.h).
// kStalled: the cup stopped making progress along the edge (TrialThresholds::stall_mm over
// stall_window_s): its outcome is decided long before the time limit. kTimeout: the time limit
// was reached while the cup still moved on.
enum class Outcome {
  kRunning,
  kSuccess,
  kFailureOffEdge,
  kFailureGrasp,
  kTimeout,
  kUnstable,
  kLostEdge,
  kControllerFault,
  kStalled
};

// The text form, as written in tables and summaries: "running", "success", "failure_I",
// "failure_II", "timeout", "unstable", "lost_edge", "controller_fault", "stalled".
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

// Progress along the edge at the control iterations, for the stall rule: true once the furthest
// progress seen has not passed the last mark by more than stall_m for window_s (a mark is set at
// the start and each time the furthest passes it by more than stall_m). Backing up never counts:
// only the furthest point reached does.
class StallWatch {
 public:
  // window_s 0: never stalls.
  void Start(double stall_m, double window_s, double t_s, double progress_m);
  // One control iteration's progress along the edge (m). True once stalled.
  bool Add(double t_s, double progress_m);
  // "2.00 mm of progress or less over the last 20.0 s (furthest 12.5 mm along the edge)"
  std::string Detail() const;

 private:
  double stall_m_ = 0, window_s_ = 0;
  double mark_t_s_ = 0, mark_m_ = 0, furthest_m_ = 0, last_t_s_ = 0;
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

#endif  // SSC_TRIAL_TRIAL_OUTCOME_H_
