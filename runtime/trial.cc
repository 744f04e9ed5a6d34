#include "runtime/trial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/tool_names.h"
#include "runtime/deferred_sensor_step.h"
#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

std::string RangeError(const char* field, double v, const char* range) {
  std::ostringstream os;
  os << field << " = " << v << " is out of range " << range;
  return os.str();
}

bool Finite(double v) { return std::isfinite(v); }

// The servo brings the tool within 0.2 mm of a set point in well under a second; a set point it
// has not reached this long after the target got there lies out of the arm's (or the gantry's)
// reach, and the trial would otherwise wait for ever.
constexpr double kReachWaitS = 5.0;

std::string PointText(const Vec3& p) {
  std::ostringstream os;
  os.precision(4);
  os << std::fixed << "(" << p[0] << ", " << p[1] << ") m";
  return os.str();
}

}  // namespace

TrialTarget TrialTarget::Disk(double centre_x_m, double centre_y_m, double radius_m,
                              double start_offset_m, DiskLanding landing) {
  TrialTarget t;
  t.start = {centre_x_m + start_offset_m, centre_y_m};
  t.approach = landing == DiskLanding::kAtStart ? t.start : Point2{centre_x_m, centre_y_m};
  t.goal = TrialGoal::AroundDisk({centre_x_m, centre_y_m}, radius_m);
  t.edge =
      std::make_shared<const ContourPath>(ContourPath::Circle({centre_x_m, centre_y_m}, radius_m));
  t.disk_radius_m = radius_m;
  return t;
}

const char* DiskLandingName(DiskLanding landing) {
  return landing == DiskLanding::kAtCentre ? "centre" : "start";
}

const char* PhaseName(TrialPhase phase) {
  switch (phase) {
    case TrialPhase::kApproach:
      return "approach";
    case TrialPhase::kMoveToStart:
      return "move";
    case TrialPhase::kFollow:
      return "follow";
    case TrialPhase::kDone:
      return "done";
  }
  return "?";
}

std::string TrialConfig::Validate() const {
  if (const std::string e = law.Validate(); !e.empty()) return e;
  if (const std::string e = controller.Validate(); !e.empty()) return e;
  if (!Finite(control_period_s) || control_period_s < 0.002 || control_period_s > 10)
    return RangeError("control_period_s", control_period_s, "[0.002, 10] s");
  // Below 0.05 N the approach would stop on the first touch (F/T noise is of that order).
  if (!Finite(approach_force_n) || approach_force_n < 0.05 || approach_force_n > 50)
    return RangeError("approach_force_n", approach_force_n, "[0.05, 50] N");
  if (!Finite(approach_speed_m_s) || approach_speed_m_s <= 0 || approach_speed_m_s > 0.1)
    return RangeError("approach_speed_m_s", approach_speed_m_s, "(0, 0.1] m/s");
  if (!Finite(move_speed_m_s) || move_speed_m_s <= 0 || move_speed_m_s > 0.5)
    return RangeError("move_speed_m_s", move_speed_m_s, "(0, 0.5] m/s");
  if (!Finite(target.start[0]) || !Finite(target.start[1]) || !Finite(target.approach[0]) ||
      !Finite(target.approach[1]))
    return "target start/approach points must be finite";
  if (const std::string e = target.goal.Validate(); !e.empty()) return e;
  if (!Finite(timeout_s) || timeout_s <= 0 || timeout_s > 3600)
    return RangeError("timeout_s", timeout_s, "(0, 3600] s");
  if (const std::string e = ValidateStallRule(thresholds.stall_mm, thresholds.stall_window_s);
      !e.empty())
    return e;
  if (control_period_s > timeout_s) {
    std::ostringstream os;
    os << "control_period_s = " << control_period_s << " s is longer than timeout_s = " << timeout_s
       << " s: the trial would end before its first control iteration";
    return os.str();
  }
  if (!Finite(servo.smoothing_s) || servo.smoothing_s < 0 || servo.smoothing_s > 5)
    return RangeError("servo smoothing_s", servo.smoothing_s, "[0, 5] s");
  if (!Finite(servo.damping) || servo.damping < 0 || servo.damping > 2)
    return RangeError("servo damping", servo.damping, "[0, 2]");
  if (!Finite(log_period_s) || log_period_s <= 0 || log_period_s > 1)
    return RangeError("log_period_s", log_period_s, "(0, 1] s");
  if (const std::string e = effects.Validate(control_period_s); !e.empty()) return e;
  return "";
}

ContourTrial::ContourTrial(const mjModel* m, mjData* d, const TrialConfig& config, bool keep_log)
    : m_(m), d_(d), config_(config), keep_log_(keep_log) {}

std::unique_ptr<ContourTrial> ContourTrial::Create(const mjModel* m, mjData* d,
                                                   const TrialConfig& config, bool keep_log,
                                                   std::string* error) {
  if (const std::string e = config.Validate(); !e.empty()) {
    *error = "trial config: " + e;
    return nullptr;
  }
  // A zero step would never reach the timeout (models changed after LoadModel come here too).
  if (const std::string e = CheckTimestep(m->opt.timestep, nullptr); !e.empty()) {
    *error = e;
    return nullptr;
  }
  std::unique_ptr<ContourTrial> trial(new ContourTrial(m, d, config, keep_log));
  if (std::string e = trial->rig_.Bind(m, d); !e.empty()) {
    *error = e;
    return nullptr;
  }
  trial->ft_reader_.Bind(m, trial->rig_.force_sensor, trial->rig_.torque_sensor);
  trial->rig_.servo->set_params(config.servo);
  trial->registration_ = std::make_unique<ScopedControl>(d, trial.get());
  if (!trial->registration_->ok()) {
    *error = "mjcb_control is owned by other code; cannot install the trial controller";
    return nullptr;
  }
  trial->Reset();
  if (!trial->controller_) {
    *error = "controller '" + config.controller.name + "' could not be made";
    return nullptr;
  }
  if (!trial->active_) {
    // Bind once more to get the servo's reason.
    trial->rig_.servo->Init(m, d, trial->rig_.tool_site, error);
    return nullptr;
  }
  return trial;
}

void ContourTrial::Reset() {
  active_ = false;  // mj_forward below calls the control callback: not before the servo is bound
  rig_.Reset(m_, d_, config_.seed);
  ft_reader_.Update(m_, d_);
  phase_ = TrialPhase::kApproach;
  ft_tare_n_ = 0;
  tare_samples_ = 0;
  next_iteration_s_ = 0;
  next_log_s_ = 0;
  next_log_time_s_ = 0;
  follow_start_s_ = 0;
  next_observe_s_ = 0;
  goal_ = GoalTracker();
  goal_start_ = {};
  path_xy_.clear();
  path_t_.clear();
  result_ = TrialResult();
  last_step_ = ContourStep{};
  awaiting_step_ = false;
  command_z_ = 0;
  lifted_since_s_ = -1;
  controller_ = config_.controller.Make({config_.law, config_.control_period_s});
  if (rig_.servo) {
    std::string ignored;
    active_ = rig_.servo->Init(m_, d_, rig_.tool_site, &ignored);
  }
  start_point_ = {config_.target.start[0], config_.target.start[1], 0};
  transfer_done_ = false;
  reach_wait_since_s_ = -1;
  effects_.Reset(config_.effects, config_.seed);
  last_tool_ = rig_.servo ? rig_.servo->Measured(d_) : Vec3{};
  host_p_pa_ = {};
}

double ContourTrial::FtNormalForce() const {
  // Force the transducer exerts on the cup, in the F/T site frame (z along the cup axis, down).
  // Pressing on a surface pushes the cup up: the reading along +z grows; tared in air.
  return ft_reader_.Axial(m_, d_) - ft_tare_n_;
}

std::array<double, 4> ContourTrial::Pressures() const {
  return {d_->sensordata[rig_.pressure_adr], d_->sensordata[rig_.pressure_adr + 1],
          d_->sensordata[rig_.pressure_adr + 2], d_->sensordata[rig_.pressure_adr + 3]};
}

void ContourTrial::Log(bool iteration) {
  if (!keep_log_) return;
  TrialLogRow row;
  row.t_s = d_->time;
  row.tool_m = rig_.servo->Measured(d_);
  // Between iterations the chambers as the lip drags them (the peel is in the real chambers,
  // so a lab log has it in every sample); the sensors' spread and slow noise only at iterations,
  // where the host drew them.
  if (iteration) {
    row.p_pa = host_p_pa_;
  } else {
    row.p_pa = effects_.ChamberReading(Pressures());
  }
  // The law's quantities exist only where it ran: NaN elsewhere (the approach, the move, and
  // the rows between iterations), never 0 or the previous iteration's values.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.pbar_pa = iteration ? last_step_.p_mean_pa : nan;
  row.dpx_pa = iteration ? last_step_.dpx_pa : nan;
  row.dpy_pa = iteration ? last_step_.dpy_pa : nan;
  row.cf = iteration ? last_step_.cf : nan;
  row.step_x_m = last_step_world_[0];
  row.step_y_m = last_step_world_[1];
  row.ft_normal_n = FtNormalForce();
  row.phase = phase_;
  row.iteration = iteration;
  result_.log.push_back(row);
}

void ContourTrial::Finish(Outcome outcome, const std::string& detail) {
  if (phase_ == TrialPhase::kDone) return;
  phase_ = TrialPhase::kDone;
  result_.outcome = outcome;
  result_.detail = detail;
  result_.sim_time_s = d_->time;
  result_.follow_time_s = follow_start_s_ > 0 ? d_->time - follow_start_s_ : 0;
  result_.swept_deg = goal_.swept_deg();
  const TrialTarget& tg = config_.target;
  if (tg.edge) result_.end_arc_mm = goal_.arc_m() * 1e3;
  if (path_xy_.size() >= 2) {
    const bool swept = tg.goal.kind == TrialGoal::Kind::kSweptAngle;
    result_.metrics = ComputeDiskMetrics(path_xy_, path_t_, swept ? tg.goal.centre : tg.start,
                                         tg.disk_radius_m > 0 ? tg.disk_radius_m : 1.0);
    if (tg.disk_radius_m <= 0) {  // r_mean etc. mean nothing without a disk
      result_.metrics.r_mean_mm = result_.metrics.dr_mm = result_.metrics.sigma_r_mm = 0;
      result_.metrics.s_c = 0;
    }
    if (tg.edge && tg.disk_radius_m <= 0) {  // (round a disk: |r - R| above)
      const ContourPath& edge = *tg.edge;
      const auto e = ContourError(
          path_xy_, [&edge](double x, double y) { return edge.Project(x, y).distance_m; });
      result_.metrics.contour_mean_mm = e[0] * 1e3;
      result_.metrics.contour_max_mm = e[1] * 1e3;
    }
  }
}

void ContourTrial::Control(const mjModel* m, mjData* d) {
  (void)m;
  (void)d;
  if (!active_) return;
  const double t = d_->time;
  const Vec3 tool = rig_.servo->Measured(d_);
  if (phase_ == TrialPhase::kMoveToStart || phase_ == TrialPhase::kFollow) TrackLipShear(tool);
  last_tool_ = tool;
  if (effects_.TakeDueStep(t)) {
    // The pose read after the plot: measured pose + the step computed from older pressures.
    rig_.servo->SetTarget(
        {tool[0] + last_step_world_[0], tool[1] + last_step_world_[1], command_z_});
  }
  // The log keeps every phase (the approach gives the in-air start a robot log also has),
  // one row per log period; a control iteration logs its own row instead.
  const bool iteration_now = phase_ == TrialPhase::kFollow && t + 1e-9 >= next_iteration_s_;
  if (keep_log_ && t >= next_log_time_s_ && !iteration_now) {
    Log(false);
    next_log_time_s_ = t + config_.log_period_s;
  }
  if ((phase_ == TrialPhase::kApproach || phase_ == TrialPhase::kMoveToStart) &&
      t + 1e-9 >= next_observe_s_ && ControllerObservesApproach()) {
    next_observe_s_ = t + config_.control_period_s;
    ControllerInput in = InputAt(t, tool, effects_.HostReading(t, Pressures()));
    in.iteration = 0;
    in.follow_s = 0;
    controller_->ObserveBeforeFollowing(in);
  }
  switch (phase_) {
    case TrialPhase::kApproach:
      TareAndApproach(t, tool);
      break;
    case TrialPhase::kMoveToStart:
      MoveToStart(t, tool);
      break;
    case TrialPhase::kFollow:
      Follow(t, tool);
      break;
    case TrialPhase::kDone:
      break;
  }
  rig_.servo->Track(m_, d_);
}

bool ContourTrial::ControllerObservesApproach() const {
  return controller_ && controller_->ObservesBeforeFollowing();
}

void ContourTrial::TrackLipShear(const Vec3& tool) {
  const mjtNum* R = d_->site_xmat + 9 * rig_.tool_site;
  effects_.MoveTool(WorldToTool(R, tool[0] - last_tool_[0], tool[1] - last_tool_[1]),
                    FtNormalForce());
}

bool ContourTrial::MoveSetPointToward(const Point2& point, double z) {
  Vec3 target = rig_.servo->target();
  const double dx = point[0] - target[0], dy = point[1] - target[1];
  const double dist = std::hypot(dx, dy), step = config_.move_speed_m_s * m_->opt.timestep;
  const bool there = dist <= step;
  if (there) {
    target[0] = point[0];
    target[1] = point[1];
  } else {
    target[0] += dx / dist * step;
    target[1] += dy / dist * step;
  }
  target[2] = z;
  rig_.servo->SetTarget(target);
  return there;
}

void ContourTrial::TareAndApproach(double t, const Vec3& tool) {
  // Tare the F/T over the first 50 ms in air, then descend until the compression is read.
  if (t < 0.05) {
    ft_tare_n_ = (ft_tare_n_ * tare_samples_ + ft_reader_.Axial(m_, d_)) / (tare_samples_ + 1);
    ++tare_samples_;
    return;
  }
  // First carry the cup, at its starting height, over the landing point.
  if (!transfer_done_) {
    const Point2& landing = config_.target.approach;
    if (!MoveSetPointToward(landing, rig_.servo->target()[2])) return;
    if (std::hypot(tool[0] - landing[0], tool[1] - landing[1]) > 2e-4) {
      ReachTimedOut(t, "landing point", rig_.servo->target());
      return;
    }
    transfer_done_ = true;
    reach_wait_since_s_ = -1;
  }
  const bool deep_enough = tool[2] <= config_.target.surface_top_z_m - rig_.max_press_m;
  if (FtNormalForce() >= config_.approach_force_n || deep_enough) {
    hold_z_ = tool[2];
    command_z_ = hold_z_;
    result_.hold_height_m = hold_z_;
    rig_.servo->SetTarget({tool[0], tool[1], hold_z_});
    phase_ = TrialPhase::kMoveToStart;
    return;
  }
  Vec3 target = rig_.servo->target();
  target[2] -= config_.approach_speed_m_s * m_->opt.timestep;
  rig_.servo->SetTarget(target);
  if (t > 30) Finish(Outcome::kTimeout, "approach never reached the start-up force");
}

void ContourTrial::MoveToStart(double t, const Vec3& tool) {
  const Point2 start = {start_point_[0], start_point_[1]};
  if (!MoveSetPointToward(start, hold_z_)) return;
  if (std::hypot(tool[0] - start[0], tool[1] - start[1]) >= 2e-4) {
    ReachTimedOut(t, "start point", start_point_);
    return;
  }
  StartFollowing(t, tool);
}

void ContourTrial::StartFollowing(double t, const Vec3& tool) {
  phase_ = TrialPhase::kFollow;
  follow_start_s_ = t;
  next_iteration_s_ = t;
  next_log_s_ = t;
  goal_start_ = {tool[0], tool[1]};
  goal_.Start(config_.target.goal, config_.target.edge, goal_start_);
  StartStallWatch();
}

void ContourTrial::StartStallWatch() {
  stall_.Start(1e-3 * config_.thresholds.stall_mm, config_.thresholds.stall_window_s,
               follow_start_s_, goal_.progress_m());
}

void ContourTrial::Follow(double t, const Vec3& tool) {
  if (t >= next_log_s_) {
    path_xy_.push_back({tool[0], tool[1]});
    path_t_.push_back(t);
    goal_.Add({tool[0], tool[1]});
    next_log_s_ += config_.log_period_s;
  }
  if (t + 1e-9 >= next_iteration_s_) RunIteration(t, tool);
}

ControllerInput ContourTrial::InputAt(double t, const Vec3& tool,
                                      const std::array<double, 4>& p_pa) const {
  ControllerInput in;
  in.t_s = t;
  in.follow_s = t - follow_start_s_;
  in.iteration = static_cast<std::uint64_t>(result_.iterations - 1);
  in.p_pa = p_pa;
  in.ft_normal_n = FtNormalForce();
  in.tool_m = tool;
  const mjtNum* R = d_->site_xmat + 9 * rig_.tool_site;
  for (int k = 0; k < 9; ++k) in.tool_rotation[static_cast<std::size_t>(k)] = R[k];
  in.hold_z_m = hold_z_;
  return in;
}

bool ContourTrial::TakeCommand(const ControllerCommand& command, double t, const Vec3& tool) {
  if (const std::string e = CheckControllerCommand(command); !e.empty()) {
    const std::string why = controller_->FaultDetail();
    result_.interrupted = controller_->Interrupted();
    Finish(Outcome::kControllerFault, "controller '" + config_.controller.name + "': " + e +
                                          (why.empty() ? "" : " (" + why + ")"));
    return false;
  }
  last_step_.step_m = command.step_m;
  // Never deeper than the approach's limit (nor than where the approach itself stopped).
  const double floor_z = std::min(hold_z_, config_.target.surface_top_z_m - rig_.max_press_m);
  command_z_ = std::max(hold_z_ + command.height_offset_m, floor_z);
  if (!command.lifted) {
    lifted_since_s_ = -1;
  } else if (lifted_since_s_ < 0) {
    lifted_since_s_ = t;
  }
  last_step_world_ = LandedStepWorld(command.step_m);
  // Measured pose + step; with a pose delay, the pose read after the plot.
  if (!effects_.DeferStep(t)) {
    rig_.servo->SetTarget(
        {tool[0] + last_step_world_[0], tool[1] + last_step_world_[1], command_z_});
  }
  return true;
}

void ContourTrial::RunIteration(double t, const Vec3& tool) {
  next_iteration_s_ += effects_.NextIterationPeriod(config_.control_period_s);
  ++result_.iterations;
  const std::array<double, 4> p = effects_.HostReading(t, Pressures());
  host_p_pa_ = p;
  // The law's reading of the pressures (P_mean, the differentials, c_f) for the log and overlays.
  last_step_ = ComputeContourStep(p, config_.law);
  if (external_policy_) {  // the caller's step arrives through ApplyStep
    if (controller_in_loop_) {
      controller_command_ = controller_->Step(InputAt(t, tool, p));
      if (const std::string e = CheckControllerCommand(controller_command_); !e.empty()) {
        TakeCommand(controller_command_, t, tool);  // ends the trial with controller_fault
        Log(true);
        return;
      }
    }
    awaiting_step_ = true;
    iteration_tool_ = tool;
    iteration_t_s_ = t;
  } else if (!TakeCommand(controller_->Step(InputAt(t, tool, p)), t, tool)) {
    Log(true);
    return;
  }
  Log(true);
  TrialThresholds thresholds = config_.thresholds;
  if (lifted_since_s_ >= 0) {  // a hop: in the air on purpose, for a while
    if (t - lifted_since_s_ > thresholds.max_lifted_s) {
      std::ostringstream os;
      os << "lifted for " << t - lifted_since_s_ << " s, longer than " << thresholds.max_lifted_s
         << " s";
      Finish(Outcome::kFailureOffEdge, os.str());
      return;
    }
    thresholds.off_edge_pa = -std::numeric_limits<double>::infinity();
    thresholds.grasp_pa = std::numeric_limits<double>::infinity();
  }
  const SampleCheck check = ClassifySample(thresholds, p, FtNormalForce(), goal_.status(),
                                           t - follow_start_s_, config_.timeout_s);
  const bool stalled = stall_.Add(t, goal_.progress_m());
  if (check.outcome == Outcome::kSuccess || check.outcome == Outcome::kLostEdge) {
    Finish(check.outcome, goal_.Detail());
  } else if (check.outcome != Outcome::kRunning) {
    Finish(check.outcome, check.detail);
  } else if (stalled) {
    Finish(Outcome::kStalled, stall_.Detail());
  }
}

bool ContourTrial::ReachTimedOut(double t, const char* what, const Vec3& point) {
  if (reach_wait_since_s_ < 0) reach_wait_since_s_ = t;
  if (t - reach_wait_since_s_ <= kReachWaitS) return false;
  const Vec3 tool = rig_.servo->Measured(d_);
  std::ostringstream os;
  os.precision(1);
  os << std::fixed << "the tool did not reach the " << what << " " << PointText(point) << " within "
     << kReachWaitS << " s (it stays " << 1e3 * std::hypot(tool[0] - point[0], tool[1] - point[1])
     << " mm away): out of reach? (--start-offset, the object's place)";
  Finish(Outcome::kTimeout, os.str());
  return true;
}

void ContourTrial::SetResultOnly(bool on) { defer_acc_sensors_ = on && CanDeferAccSensors(m_); }

bool ContourTrial::FtReadAfterThisStep() const {
  // While following, only a control iteration reads the F/T (the failure checks), and the log.
  // The next step's callback runs at d->time + timestep; a whole step more of margin for the
  // round-off of the time sum.
  if (phase_ != TrialPhase::kFollow || keep_log_ || external_policy_) return true;
  const double after_next_s = d_->time + 2 * m_->opt.timestep;
  return after_next_s + 1e-9 >= next_iteration_s_ || after_next_s >= run_until_s_;
}

bool ContourTrial::Step() {
  if (phase_ == TrialPhase::kDone) return false;
  if (defer_acc_sensors_) {
    const mjtNum start = StepToAccSensors(m_, d_);  // runs this step's control callback
    FinishStep(m_, d_, FtReadAfterThisStep(), start);
  } else {
    mj_step(m_, d_);
  }
  ft_reader_.Update(m_, d_);
  // A numerically broken run is never a controller result.
  if (d_->warning[mjWARN_BADQACC].number > 0) {
    Finish(Outcome::kUnstable, "MuJoCo warning: bad qacc (simulation diverged)");
  } else {
    for (int i = 0; i < m_->nq; ++i) {
      if (!std::isfinite(d_->qpos[i])) {
        Finish(Outcome::kUnstable, "non-finite qpos");
        break;
      }
    }
  }
  return phase_ != TrialPhase::kDone;
}

bool ContourTrial::RunToNextIteration(double max_sim_s) {
  const int iterations = result_.iterations;
  while (result_.iterations == iterations && d_->time < max_sim_s && Step()) {
  }
  return phase_ != TrialPhase::kDone;
}

std::array<double, 2> ContourTrial::LandedStepWorld(std::array<double, 2> step) const {
  step = effects_.LandedStep(step, static_cast<std::uint64_t>(result_.iterations));
  // Tool frame -> world with the tool site's rotation (orientation is held).
  return ToolToWorld(d_->site_xmat + 9 * rig_.tool_site, step[0], step[1]);
}

void ContourTrial::ApplyStep(const std::array<double, 2>& step_m) {
  if (!awaiting_step_) return;
  awaiting_step_ = false;
  if (controller_in_loop_) {
    ControllerCommand command = controller_command_;
    command.step_m = {command.step_m[0] + step_m[0], command.step_m[1] + step_m[1]};
    TakeCommand(command, iteration_t_s_, iteration_tool_);
    return;
  }
  last_step_.step_m = step_m;
  last_step_world_ = LandedStepWorld(step_m);
  rig_.servo->SetTarget({iteration_tool_[0] + last_step_world_[0],
                         iteration_tool_[1] + last_step_world_[1], command_z_});
}

bool ContourTrial::RunToFollowStart(double max_sim_s) {
  while ((phase_ == TrialPhase::kApproach || phase_ == TrialPhase::kMoveToStart) &&
         d_->time < max_sim_s && Step()) {
  }
  return phase_ == TrialPhase::kFollow;
}

FollowStart ContourTrial::SaveFollowStart() const {
  FollowStart s;
  s.servo = rig_.servo->state();
  s.transfer_done = transfer_done_;
  s.ft_tare_n = ft_tare_n_;
  s.tare_samples = tare_samples_;
  s.hold_z_m = hold_z_;
  s.follow_start_s = follow_start_s_;
  s.next_iteration_s = next_iteration_s_;
  s.next_log_s = next_log_s_;
  s.next_log_time_s = next_log_time_s_;
  s.last_tool_m = last_tool_;
  s.goal_start_m = goal_start_;
  s.lip_shear = effects_.lip_shear();
  return s;
}

void ContourTrial::ResumeAtFollowStart(const mjData* follow_start_data, const FollowStart& s) {
  mj_copyData(d_, m_, follow_start_data);
  // The only seed the approach used: the sensor's noise (its pressures fed nothing back).
  ReseedChamberPressure(m_, d_, rig_.pressure_instance, config_.seed);
  rig_.servo->set_state(s.servo);
  transfer_done_ = s.transfer_done;
  ft_tare_n_ = s.ft_tare_n;
  tare_samples_ = s.tare_samples;
  hold_z_ = s.hold_z_m;
  command_z_ = s.hold_z_m;
  result_.hold_height_m = s.hold_z_m;
  follow_start_s_ = s.follow_start_s;
  next_iteration_s_ = s.next_iteration_s;
  next_log_s_ = s.next_log_s;
  next_log_time_s_ = s.next_log_time_s;
  last_tool_ = s.last_tool_m;
  effects_.set_lip_shear(s.lip_shear);
  goal_start_ = s.goal_start_m;
  goal_.Start(config_.target.goal, config_.target.edge, goal_start_);
  StartStallWatch();
  phase_ = TrialPhase::kFollow;
}

TrialResult ContourTrial::Run(double max_sim_s) {
  const auto t0 = std::chrono::steady_clock::now();
  run_until_s_ = max_sim_s;
  while (d_->time < max_sim_s && Step()) {
  }
  run_until_s_ = 1e300;
  if (phase_ != TrialPhase::kDone) Finish(Outcome::kTimeout, "simulation time limit");
  result_.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result_;
}

std::unique_ptr<ContourTrial> CreateTrialWithData(const mjModel* m, const TrialConfig& config,
                                                  bool keep_log, DataPtr* data, TrialResult* failed,
                                                  std::string* error) {
  *data = MakeData(m, error);
  std::unique_ptr<ContourTrial> trial;
  if (*data) trial = ContourTrial::Create(m, data->get(), config, keep_log, error);
  if (!trial) {
    *failed = TrialResult();
    failed->outcome = Outcome::kUnstable;
    failed->detail = *data ? *error : "could not make mjData: " + *error;
  }
  return trial;
}

bool CheckTrialSetup(const mjModel* m, const TrialConfig& config, std::string* error) {
  DataPtr data;
  TrialResult failed;
  return CreateTrialWithData(m, config, false, &data, &failed, error) != nullptr;
}

TrialResult RunTrial(const mjModel* m, const TrialConfig& config, bool keep_log,
                     std::string* error) {
  DataPtr data;
  TrialResult failed;
  auto trial = CreateTrialWithData(m, config, keep_log, &data, &failed, error);
  if (!trial) return failed;
  trial->SetResultOnly(true);  // the data dies here
  return trial->Run();
}

}  // namespace ssc
