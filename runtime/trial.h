// One contour-following trial, headless or in the viewer: the same control callback.
//
// Phases (as on the robot): APPROACH, above the landing point (the start point by default), until
// the tared F/T reads the start-up compression, then hold that height; MOVE to the start point
// (none when landed there); FOLLOW the edge with the controller (the published contour law
// by default; controller/controller.h), one control iteration per control_period; then DONE
// with one outcome. Failure checks run only while following.
#ifndef SSC_RUNTIME_TRIAL_H_
#define SSC_RUNTIME_TRIAL_H_

#include <mujoco/mujoco.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "controller/contour_law.h"
#include "controller/controller.h"
#include "controller/controller_registry.h"
#include "geometry/dimensions.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/control_dispatch.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "runtime/tool_force.h"
#include "runtime/tool_servo.h"
#include "trial/robot_effects.h"
#include "trial/trial_effects.h"
#include "trial/trial_goal.h"
#include "trial/trial_metrics.h"
#include "trial/trial_outcome.h"

namespace ssc {

enum class TrialPhase { kApproach, kMoveToStart, kFollow, kDone };
const char* PhaseName(TrialPhase phase);

// What the trial follows: the landing and start points, the goal that completes it, and the
// true contour for the metrics. The default is the disk benchmark (geometry/dimensions.h: the
// disk at W, the start east of its centre, one counter-clockwise loop).
// Where the cup lands on a disk: at the start point, as the lab's script does (it moves the cup
// over the start, turns the pump to full and then lowers it to the preload), or over the centre,
// as the paper's text has it. Landed on the centre the cup seals, and a sealed skirt's vacuum
// pulls harder than the preload (docs/flex_skirt.md), so the transducer never reads it there.
enum class DiskLanding { kAtStart, kAtCentre };
inline constexpr DiskLanding kDefaultDiskLanding = DiskLanding::kAtStart;
// "start" or "centre" (the --land-at choices).
const char* DiskLandingName(DiskLanding landing);

struct TrialTarget {
  Point2 start{kWorkspaceX + kBenchmarkStartOffsetM, kWorkspaceY};  // cup centre at following
  Point2 approach = start;  // the cup descends here (world x/y, m)
  TrialGoal goal = TrialGoal::AroundDisk({kWorkspaceX, kWorkspaceY}, kBenchmarkDiskRadiusM);
  double disk_radius_m = kBenchmarkDiskRadiusM;  // > 0: r_mean / dr / sigma_r about the centre
  double surface_top_z_m = 0.010;  // the approach never takes the lip plane deeper than the
                                   // tool's lip_max_press_mm below this
  // The true contour: the contour distance, the tracked arc position, goal points, the band of
  // following (the default: the benchmark disk's circle).
  std::shared_ptr<const ContourPath> edge = std::make_shared<const ContourPath>(
      ContourPath::Circle({kWorkspaceX, kWorkspaceY}, kBenchmarkDiskRadiusM));

  // The disk benchmark with its start point `start_offset_m` east of the centre.
  static TrialTarget Disk(double centre_x_m, double centre_y_m, double radius_m,
                          double start_offset_m, DiskLanding landing = kDefaultDiskLanding);
};

struct TrialConfig {
  ContourLawParams law;  // P_ref, beta, step, thresholds of the law
  // What decides while following (controller/controller_registry.h): the published law
  // by default; every controller also reads `law`.
  ControllerChoice controller;
  TrialThresholds thresholds;  // success sweep, failure I/II, safety force
  ServoParams servo;           // look-ahead smoothing of the arm
  // One control iteration. 0.15 s with the 0.15 s servo smoothing below gives the published
  // speeds (about 4 step lengths per second) AND keeps dL = 7.5 mm stable; see docs/trials.md.
  double control_period_s = 0.15;
  double approach_force_n = 1.5;  // tared F/T compression that ends the approach, (0, 50]
  double approach_speed_m_s = 0.005;
  double move_speed_m_s = 0.02;  // to the start point
  TrialTarget target;            // where to land, start and finish (default: the disk)
  double timeout_s = 120;        // follow phase limit, simulated seconds
  std::uint64_t seed = 1;        // sensor noise seed for this trial
  double log_period_s = 0.02;    // path sampling for metrics and the log
  // The real loop, lip and sensors (trial/robot_effects.h): the fitted set by
  // default (each step lands off target; each chamber keeps a tare offset); all zero
  // (`--effects off`) = the ideal loop.
  RobotEffectsParams effects = FittedRobotEffects();

  // Empty when valid, else names the field and its range.
  std::string Validate() const;
};

// One logged row (every control iteration and every log_period while following).
struct TrialLogRow {
  double t_s = 0;
  Vec3 tool_m{};
  std::array<double, 4> p_pa{};
  double pbar_pa = 0, dpx_pa = 0, dpy_pa = 0, cf = 0;  // NaN on rows without an iteration
  double step_x_m = 0, step_y_m = 0;                   // world frame
  double ft_normal_n = 0;
  TrialPhase phase = TrialPhase::kApproach;
  bool iteration = false;  // a control iteration happened at this row
};

struct TrialResult {
  Outcome outcome = Outcome::kRunning;  // OutcomeName() gives its text form
  std::string detail;                   // why (e.g. the warning or the failing value)
  // The controller was interrupted (Controller::Interrupted): no finished trial, no row.
  bool interrupted = false;
  DiskTrialMetrics metrics;
  double follow_time_s = 0;  // duration of the follow phase, s
  double sim_time_s = 0;     // total simulated time, s
  double wall_time_s = 0;
  double hold_height_m = 0;  // tool site height held after the approach
  double swept_deg = 0;      // swept-angle goals: signed swept angle at the end, deg
  double end_arc_mm = 0;     // with an edge: arc position reached (where it was lost), mm
  int iterations = 0;
  std::vector<TrialLogRow> log;  // filled when requested
};

// What the approach and the move to the start point leave in the controller at the start of
// following, beside the mjData (runtime/approach_cache.h shares both between trials whose
// approaches are the same).
struct FollowStart {
  ToolServo::State servo;
  bool transfer_done = false;
  double ft_tare_n = 0;
  int tare_samples = 0;
  double hold_z_m = 0;
  double follow_start_s = 0, next_iteration_s = 0, next_log_s = 0, next_log_time_s = 0;
  Vec3 last_tool_m{};
  Point2 goal_start_m{};  // the cup where the goal tracker started
  LipShearState lip_shear;
};

// The controller behind mjcb_control for one mjData.
class ContourTrial : public ControlCallback {
 public:
  // Binds to a model/data pair (finds the pressure sensor, the F/T sensor and the servo).
  static std::unique_ptr<ContourTrial> Create(const mjModel* m, mjData* d,
                                              const TrialConfig& config, bool keep_log,
                                              std::string* error);
  // Resets d to the scene's first keyframe (or qpos0), sets the noise seed, restarts phases.
  void Reset();
  void Control(const mjModel* m, mjData* d) override;

  // Steps until the trial ends (or max_sim_s of simulated time). Returns the result.
  TrialResult Run(double max_sim_s = 1e9);
  // For callers that read no sensor from the mjData themselves, only results (studies running
  // many trials through RunTrial and RunTrialShared, the bench): Step and Run then evaluate the
  // F/T (the acceleration-stage sensors, runtime/deferred_sensor_step.h) only on the steps whose
  // reading the controller uses, and on the last step of a Run. Results and trajectories are the
  // same to the bit; between iterations the F/T in sensordata is an older reading. Off when the
  // model does not allow it (CanDeferAccSensors, checked here).
  void SetResultOnly(bool on);
  // One physics step with instability checks; false when the trial has ended.
  bool Step();

  TrialPhase phase() const { return phase_; }
  // The controller reads the sensors before following (Controller::ObservesBeforeFollowing):
  // such a trial cannot resume from a shared approach.
  bool ControllerObservesApproach() const;
  const TrialResult& result() const { return result_; }
  const TrialConfig& config() const { return config_; }
  TrialConfig& mutable_config() { return config_; }
  const ContourStep& last_step() const { return last_step_; }
  const std::vector<Point2>& path() const { return path_xy_; }
  int tool_site() const { return rig_.tool_site; }
  const RigBinding& rig() const { return rig_; }
  // The F/T transducer's wrench on the cup, its site's frame (runtime/tool_force.h): the sensors
  // on a rigid lip, the contact balance on a flex skirt.
  std::array<double, 6> ToolWrench() const { return ft_reader_.Wrench(d_); }
  // The four filtered chamber pressures now (the plugin's output), Pa.
  std::array<double, 4> Pressures() const;
  // What the controller read at the last iteration: the plugin's output through the lip tilt
  // and the chamber spread (equal to it with the effects off), Pa.
  const std::array<double, 4>& HostPressures() const { return host_p_pa_; }
  // Progress while following: the signed swept angle (swept-angle goals, deg) and the tracked
  // arc position along the edge (m; with an edge).
  double swept_deg() const { return goal_.swept_deg(); }
  double tracked_arc_m() const { return goal_.arc_m(); }
  const GoalTracker& goal() const { return goal_; }
  // Another policy than the contour law (the Gymnasium environment). When on, each following
  // control iteration reads the sensor and waits: RunToNextIteration returns, the caller
  // decides from HostPressures() and calls ApplyStep, and the servo takes that step
  // (from the next physics step on) instead of the law's.
  // With `controller_in_loop`, the trial's controller still decides at each iteration and the
  // caller's step is added to its command (a residual policy; a zero step runs the controller).
  void SetExternalPolicy(bool on, bool controller_in_loop = false) {
    external_policy_ = on;
    controller_in_loop_ = on && controller_in_loop;
  }
  // The controller's command at the waiting iteration (controller in the loop).
  const ControllerCommand& controller_command() const { return controller_command_; }
  // Steps until the next control iteration has read the sensor (external policy) or run (the
  // law), or the trial ends, or max_sim_s; false when the trial ended.
  bool RunToNextIteration(double max_sim_s = 1e9);
  // The planar step for the iteration that is waiting (tool frame, m); the height is held (or,
  // with the controller in the loop, the controller's height and lift, its step plus this one).
  void ApplyStep(const std::array<double, 2>& step_m);

  // The shared approach (runtime/approach_cache.h). Steps through the approach and the move;
  // true when following has just started (false when the trial ended before).
  bool RunToFollowStart(double max_sim_s = 1e9);
  // At the start of following (right after RunToFollowStart returned true): the state to share.
  FollowStart SaveFollowStart() const;
  // On a freshly created trial: continues from another trial's follow start with the same
  // approach (ApproachKeyOf equal, same model): copies `follow_start_data` into this trial's
  // mjData, re-derives the pressure sensor's noise for this trial's seed and starts following
  // with this trial's goal. The rows are then those of a run from scratch, to the bit.
  void ResumeAtFollowStart(const mjData* follow_start_data, const FollowStart& s);

 private:
  ContourTrial(const mjModel* m, mjData* d, const TrialConfig& config, bool keep_log);
  // The control callback's phases, each with the time and the measured tool position.
  void TareAndApproach(double t, const Vec3& tool);
  void MoveToStart(double t, const Vec3& tool);
  void Follow(double t, const Vec3& tool);
  // One control iteration: read the host's pressures, ask the controller, take the step, check.
  void RunIteration(double t, const Vec3& tool);
  void StartFollowing(double t, const Vec3& tool);
  // The stall rule from the follow start (TrialThresholds::stall_mm, stall_window_s).
  void StartStallWatch();
  // The lip's footprint drags on the object while the body slides over it.
  void TrackLipShear(const Vec3& tool);
  // Moves the servo's set point toward `point` at the move speed, at height z; true once the
  // set point is there.
  bool MoveSetPointToward(const Point2& point, double z);
  // The controller's command at this iteration: the step landed and sent (or held for the pose
  // read after the plot), the height. False when it is out of range (the trial then ends).
  bool TakeCommand(const ControllerCommand& command, double t, const Vec3& tool);
  ControllerInput InputAt(double t, const Vec3& tool, const std::array<double, 4>& p_pa) const;
  void Finish(Outcome outcome, const std::string& detail);
  // While the tool has not yet reached `point` (target already there): ends the trial as a
  // timeout naming the point once it has waited kReachWaitS; true when it did.
  bool ReachTimedOut(double t, const char* what, const Vec3& point);
  double FtNormalForce() const;
  // Whether the next step's control callback (or a caller once Run returns) may read the F/T
  // that the current step's forward pass leaves in sensordata.
  bool FtReadAfterThisStep() const;
  void Log(bool iteration);

  const mjModel* m_;
  mjData* d_;
  TrialConfig config_;
  bool keep_log_;
  RigBinding rig_;  // tool site, sensors, servo, seeded reset
  TrialPhase phase_ = TrialPhase::kApproach;
  bool active_ = false;         // the servo is bound; the callback may act
  bool transfer_done_ = false;  // over the landing point
  double ft_tare_n_ = 0;
  ToolForceReader ft_reader_;  // the transducer's reading (runtime/tool_force.h)
  int tare_samples_ = 0;
  double hold_z_ = 0;
  double command_z_ = 0;        // the tool height the controller asks for (hold_z_ first)
  double lifted_since_s_ = -1;  // when the controller's current hop began (-1: on surface)
  std::unique_ptr<Controller> controller_;
  double next_iteration_s_ = 0, next_log_s_ = 0, follow_start_s_ = 0;
  double next_observe_s_ = 0;   // the controller's next reading before following
  double next_log_time_s_ = 0;  // next row of the trial log (all phases)
  Vec3 start_point_{};
  double reach_wait_since_s_ = -1;  // when the tool began waiting to reach a set point
  GoalTracker goal_;
  StallWatch stall_;
  ContourStep last_step_{};
  std::array<double, 2> last_step_world_{};
  // The step as the arm lands it (robot effects: step error), tool frame -> world.
  std::array<double, 2> LandedStepWorld(std::array<double, 2> step_m) const;
  std::vector<Point2> path_xy_;
  std::vector<double> path_t_;
  // Robot effects: lip shear, chamber spread, the step waiting for the pose read after the plot.
  TrialEffects effects_;
  Vec3 last_tool_{};  // where the lip's drag was last advanced from
  std::array<double, 4> host_p_pa_{};
  TrialResult result_;
  std::unique_ptr<ScopedControl> registration_;
  bool external_policy_ = false, awaiting_step_ = false, controller_in_loop_ = false;
  ControllerCommand controller_command_;  // the controller's, at the waiting iteration
  double iteration_t_s_ = 0;              // host clock of the waiting iteration
  bool defer_acc_sensors_ = false;        // SetResultOnly(true) and the model allows it
  double run_until_s_ = 1e300;            // while Run runs: its max_sim_s
  Vec3 iteration_tool_{};                 // measured tool position at the waiting iteration
  Point2 goal_start_{};                   // the cup where the goal tracker started following
};

// Loads nothing: runs one trial on an existing model with its own mjData.
// Checks that `m` can host a trial with `config` (sensors, sites, servo, time step) without
// running it: studies call it once before any row is written, so a scene that cannot run a
// trial is an error naming what is missing, never a table of "unstable" rows.
bool CheckTrialSetup(const mjModel* m, const TrialConfig& config, std::string* error);

// Makes the trial's mjData (*data, which must outlive the trial) and the trial. On failure returns
// null and *failed is the row a study records: outcome unstable, the reason in its detail.
std::unique_ptr<ContourTrial> CreateTrialWithData(const mjModel* m, const TrialConfig& config,
                                                  bool keep_log, DataPtr* data, TrialResult* failed,
                                                  std::string* error);

TrialResult RunTrial(const mjModel* m, const TrialConfig& config, bool keep_log,
                     std::string* error);

}  // namespace ssc

#endif  // SSC_RUNTIME_TRIAL_H_
