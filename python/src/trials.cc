// ssc_twin._core, trials: one trial (run_trial), the law on four pressures (contour_step), a
// trial stepped from Python (SteppedTrial) and the controller check.
#include "python/src/binding_common.h"
#include "python/src/binding_controller.h"
#include "python/src/binding_topics.h"

namespace ssc {
namespace {

// A trial that Python steps one control iteration at a time (the Gymnasium environment), with
// the law's step or one given per iteration.
class SteppedTrial {
 public:
  SteppedTrial(const std::string& scene, double pref, double beta, double step_mm,
               const nb::object& seed, const std::string& object, double timeout_s,
               const std::string& effects, const nb::object& controller,
               const std::string& controller_params) {
    scene_ = scene;
    config_ = MakeConfig(pref, beta, step_mm, SeedArg(seed), object, effects, &scene_);
    SetTimeout(timeout_s, &config_);
    if (!controller.is_none()) {
      config_.controller = ChoiceFrom(controller, controller_params);
      if (const std::string e = config_.controller.Validate(); !e.empty()) Invalid(e);
    } else if (!controller_params.empty()) {
      Invalid("controller_params apply to a registered controller; no controller given");
    }
    // The mujoco package owns the model and the data (MjModel._from_model_ptr takes ownership
    // of a compiled mjModel; both sides use the same libmujoco), so Python sees the live
    // MjModel/MjData the trial steps: renderers, viewers and mujoco functions work on them.
    ModelPtr model = Load(scene_);
    nb::module_ mujoco = nb::module_::import_("mujoco");
    model_ = model.get();
    py_model_ = mujoco.attr("MjModel").attr("_from_model_ptr")(
        reinterpret_cast<std::uintptr_t>(model.release()));
    py_data_ = mujoco.attr("MjData")(py_model_);
    data_ = reinterpret_cast<mjData*>(nb::cast<std::uintptr_t>(py_data_.attr("_address")));
    std::string error;
    trial_ = ContourTrial::Create(model_, data_, config_, false, &error);
    if (!trial_) Fail(error);
  }
  // Resets to the start of following. The approach and the move to the start read neither the
  // seed nor the policy (runtime/approach_cache.h), so with the reset cache on, the first reset
  // simulates them and keeps that state, and later ones with the same approach copy it and
  // re-derive the sensor noise for their seed: the episode is the one a reset from scratch
  // gives, to the bit (ResetCacheGivesTheEpisodeOfAResetFromScratch in package_test.py).
  void Reset(const nb::object& seed) {
    trial_->mutable_config().seed = SeedArg(seed);
    trial_->Reset();
    if (!reset_cache_ || !CanShareApproach()) return;
    const ApproachKey key = ApproachKeyOf(trial_->config());
    if (follow_start_data_ && key == follow_start_key_) {
      trial_->ResumeAtFollowStart(follow_start_data_.get(), follow_start_);
      ++resets_from_cache_;
      return;
    }
    bool following = false;
    {
      nb::gil_scoped_release release;
      following = trial_->RunToFollowStart();
    }
    RaisePendingInterrupt();
    if (!following) return;
    std::string error;
    if (!follow_start_data_) follow_start_data_ = MakeData(model_, &error);
    if (!follow_start_data_) return;
    mj_copyData(follow_start_data_.get(), model_, data_);
    follow_start_ = trial_->SaveFollowStart();
    follow_start_key_ = key;
  }
  void SetResetCache(bool on) {
    reset_cache_ = on;
    if (!on) follow_start_data_.reset();
  }
  int ResetsFromCache() const { return resets_from_cache_; }
  // The policy: the contour law inside the trial, or Python (apply_step at each iteration).
  void SetExternalPolicy(bool on, bool controller_in_loop) {
    trial_->SetExternalPolicy(on, controller_in_loop);
  }
  std::array<double, 2> ControllerStep() const { return trial_->controller_command().step_m; }
  // As RunTrialShared decides (runtime/approach_cache.h).
  bool CanShareApproach() const {
    return ApproachUnshareableReason(model_).empty() && TrialMayShareApproach(*trial_);
  }
  bool RunToNextIteration() {
    bool more = false;
    {
      nb::gil_scoped_release release;
      more = trial_->RunToNextIteration();
    }
    RaisePendingInterrupt();
    return more;
  }
  void ApplyStep(std::array<double, 2> step_m) {
    // NaN or inf would reach the controls and throw the tool; refuse them here.
    if (!std::isfinite(step_m[0]) || !std::isfinite(step_m[1])) {
      Invalid("apply_step: step_m = (" + FormatNumber(step_m[0]) + ", " + FormatNumber(step_m[1]) +
              ") m is not finite");
    }
    trial_->ApplyStep(step_m);
  }
  std::array<double, 4> IterationPressures() const { return trial_->HostPressures(); }
  std::array<double, 4> Pressures() const { return trial_->Pressures(); }
  std::array<double, 3> ToolPosition() const {
    const double* p = data_->site_xpos + 3 * trial_->tool_site();
    return {p[0], p[1], p[2]};
  }
  // The F/T (force then torque, N and N m, its site's frame): the sensors on a rigid lip, the
  // trial's contact balance on a flex skirt (runtime/tool_force.h).
  std::array<double, 6> ForceTorque() const { return trial_->ToolWrench(); }
  std::string Phase() const { return PhaseName(trial_->phase()); }
  nb::dict Result() const { return ResultDict(scene_, trial_->config(), trial_->result()); }
  nb::dict LastStep() const { return StepDict(trial_->last_step()); }
  double Time() const { return data_->time; }
  double SweptDeg() const { return trial_->swept_deg(); }
  double TrackedArcM() const { return trial_->tracked_arc_m(); }
  nb::dict Target() const {
    const TrialTarget& t = trial_->config().target;
    const bool swept = t.goal.kind == TrialGoal::Kind::kSweptAngle;
    const std::array<double, 2> centre = {t.goal.centre[0], t.goal.centre[1]};
    return Dict({{"goal", nb::cast(std::string(swept ? "swept_angle" : "goal_point"))},
                 {"sweep_deg", nb::cast(t.goal.sweep_deg)},
                 {"goal_arc_m", nb::cast(t.goal.goal_arc_m)},
                 {"centre", nb::cast(centre)},
                 {"disk_radius_m", nb::cast(t.disk_radius_m)},
                 {"control_period_s", nb::cast(trial_->config().control_period_s)},
                 {"timeout_s", nb::cast(trial_->config().timeout_s)}});
  }
  // Signed distance of (x, y) from the followed edge (negative on the object), m.
  double ContourDistanceM(double x, double y) const {
    const TrialTarget& t = trial_->config().target;
    if (t.edge) return t.edge->SignedDistance(x, y);
    return std::hypot(x - t.goal.centre[0], y - t.goal.centre[1]) - t.disk_radius_m;
  }
  std::string scene() const { return scene_; }
  nb::object model() const { return py_model_; }
  nb::object data() const { return py_data_; }
  int tool_site() const { return trial_->tool_site(); }

 private:
  bool reset_cache_ = true;
  DataPtr follow_start_data_;  // the state at the start of following, after the approach
  FollowStart follow_start_;
  ApproachKey follow_start_key_{};
  int resets_from_cache_ = 0;
  std::string scene_;
  TrialConfig config_;
  // Declared before trial_ so that the trial is destroyed first.
  nb::object py_model_, py_data_;
  const mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::unique_ptr<ContourTrial> trial_;
};

}  // namespace

void BindTrialFunctions(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "contour_step",
      [](std::array<double, 4> p_pa, double pref, double beta, double step_mm) {
        for (int k = 0; k < 4; ++k) {
          // Beyond 1e6 Pa (ten atmospheres) the law's sums overflow nothing but mean nothing.
          if (!(std::fabs(p_pa[k]) <= 1e6)) {
            Invalid("p_pa[" + std::to_string(k) + "] = " + FormatNumber(p_pa[k]) +
                    " is out of range [-1e6, 1e6] Pa (a chamber pressure)");
          }
        }
        return StepDict(ComputeContourStep(p_pa, Law(pref, beta, step_mm)));
      },
      "p_pa"_a, "pref"_a = law.p_ref_pa, "beta"_a = law.beta, "step_mm"_a = law.step_mm,
      "The published contour law on four chamber pressures (tool frame step, m).");

  m.def(
      "run_trial",
      [](const std::string& scene, double pref, double beta, double step_mm, const nb::object& seed,
         const std::string& object, bool keep_log, double stop_at_s, double timeout_s,
         const std::string& effects, const nb::object& controller,
         const std::string& controller_params) {
        std::string scene_path = scene;
        TrialConfig config =
            MakeConfig(pref, beta, step_mm, SeedArg(seed), object, effects, &scene_path);
        SetTimeout(timeout_s, &config);
        if (!(stop_at_s >= 0 && stop_at_s <= 3600)) {
          Invalid("stop_at_s = " + FormatNumber(stop_at_s) +
                  " is out of range [0, 3600] s (0: run to the end)");
        }
        config.controller = ChoiceFrom(controller, controller_params);
        ModelPtr model = Load(scene_path);
        std::string error;
        TrialResult r;
        {
          nb::gil_scoped_release release;
          DataPtr data = MakeData(model.get(), &error);
          auto trial = data
                           ? ContourTrial::Create(model.get(), data.get(), config, keep_log, &error)
                           : nullptr;
          if (trial) r = stop_at_s > 0 ? trial->Run(stop_at_s) : trial->Run();
        }
        RaisePendingInterrupt();
        if (!error.empty()) Fail(error);
        return ResultDict(ResolveScenePath(scene_path), config, r);
      },
      "scene"_a = DefaultScene(), "pref"_a = law.p_ref_pa, "beta"_a = law.beta,
      "step_mm"_a = law.step_mm, "seed"_a = 1, "object"_a = "", "keep_log"_a = true,
      "stop_at_s"_a = 0.0, "timeout_s"_a = 0.0, "effects"_a = "default",
      "controller"_a = "published", "controller_params"_a = "",
      "One contour-following trial, as `ssc trial` runs it. effects: 'default' (the fitted set), "
      "'off' or key=value,... as --effects. object: a test object by name "
      "(its arm scene; 'gantry' in scene picks the gantry one). controller: a registered name "
      "(controller_params as --controller-param) or a callable: f(reading) -> (dx, dy) m in the "
      "tool frame, or a dict with step_m, height_offset_m, lifted (docs/controllers.md); a class "
      "is instantiated once per trial.");
}

void BindSteppedTrial(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "check_controller",
      [](const nb::object& controller, const std::string& controller_params) {
        const ControllerChoice choice = ChoiceFrom(controller, controller_params);
        if (const std::string e = choice.Validate(); !e.empty()) Invalid(e);
      },
      "controller"_a, "controller_params"_a = "",
      "Raises ValueError when the controller (a registered name with its key=value parameters, "
      "or a callable) would be refused.");

  nb::class_<SteppedTrial>(m, "SteppedTrial",
                           "A trial stepped one control iteration at a time from Python.")
      .def(nb::init<const std::string&, double, double, double, const nb::object&,
                    const std::string&, double, const std::string&, const nb::object&,
                    const std::string&>(),
           "scene"_a = DefaultScene(), "pref"_a = law.p_ref_pa, "beta"_a = law.beta,
           "step_mm"_a = law.step_mm, "seed"_a = 1, "object"_a = "", "timeout_s"_a = 0.0,
           "effects"_a = "default", "controller"_a = nb::none(), "controller_params"_a = "")
      .def("reset", &SteppedTrial::Reset, "seed"_a,
           "Resets to the start of following (from the kept approach when the reset cache is on "
           "and the approach is the same: the same episode, at once).")
      .def("set_reset_cache", &SteppedTrial::SetResetCache, "on"_a,
           "Keep the approach's end state and start later resets from it (on by default).")
      .def_prop_ro("resets_from_cache", &SteppedTrial::ResetsFromCache)
      .def("set_external_policy", &SteppedTrial::SetExternalPolicy, "on"_a,
           "controller_in_loop"_a = false,
           "On: each following iteration waits for apply_step instead of taking the law's step. "
           "controller_in_loop: the trial's controller still decides and apply_step's step is "
           "added to its command.")
      .def("controller_step", &SteppedTrial::ControllerStep,
           "The controller's planar step at the waiting iteration (controller in the loop), m.")
      .def("run_to_next_iteration", &SteppedTrial::RunToNextIteration,
           "Steps until the next control iteration read the sensor (or the trial ended: False).")
      .def("apply_step", &SteppedTrial::ApplyStep, "step_m"_a,
           "The waiting iteration's planar step, tool frame, m.")
      .def("iteration_pressures", &SteppedTrial::IterationPressures,
           "The four filtered pressures the last iteration read, Pa.")
      .def("pressures", &SteppedTrial::Pressures)
      .def("tool_position", &SteppedTrial::ToolPosition)
      .def("force_torque", &SteppedTrial::ForceTorque)
      .def("last_step", &SteppedTrial::LastStep)
      .def("result", &SteppedTrial::Result)
      .def("target", &SteppedTrial::Target)
      .def("contour_distance_m", &SteppedTrial::ContourDistanceM, "x"_a, "y"_a)
      .def_prop_ro("phase", &SteppedTrial::Phase)
      .def_prop_ro("time", &SteppedTrial::Time)
      .def_prop_ro("swept_deg", &SteppedTrial::SweptDeg)
      .def_prop_ro("tracked_arc_m", &SteppedTrial::TrackedArcM)
      .def_prop_ro("scene", &SteppedTrial::scene)
      .def_prop_ro("model", &SteppedTrial::model, "The trial's mujoco.MjModel (live).")
      .def_prop_ro("data", &SteppedTrial::data, "The trial's mujoco.MjData (live).")
      .def_prop_ro("tool_site", &SteppedTrial::tool_site, "Site id of the cup's lip centre.");
}

void BindTrials(nb::module_& m) {
  BindTrialFunctions(m);
  BindSteppedTrial(m);
}

}  // namespace ssc
