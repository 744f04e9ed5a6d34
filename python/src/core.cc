// ssc_twin._core: the twin's C++ for Python (nanobind). Trials, sweeps, map validation, the
// kinematic probe and log comparison run here; results come back as dicts of numbers and NumPy
// arrays. No physics or control is re-written in Python.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/exit_codes.h"
#include "common/strict_number.h"
#include "common/tool_names.h"
#include "compare/comparison.h"
#include "compare/frames.h"
#include "compare/twin_log.h"
#include "controller/pure/contour_law.h"
#include "controller/pure/controller_registry.h"
#include "controller/trial/robot_effects.h"
#include "geometry/dimensions.h"
#include "objects/object_mjcf.h"
#include "objects/object_spec.h"
#include "plugin/chamber_pressure_config.h"
#include "plugin/chamber_pressure_sensor.h"
#include "robotlog/mat_log.h"
#include "robotlog/topic_csv.h"
#include "runtime/approach_cache.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "runtime/tool_servo.h"
#include "runtime/trial.h"
#include "studies/edge_probe.h"
#include "studies/object_study.h"
#include "studies/object_trials.h"
#include "studies/statistics/intervals.h"
#include "studies/sweep.h"
#include "studies/tool_variants.h"
#include "studies/validation.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace ssc {
namespace {

// A NumPy array that owns a copy of `values` laid out as `shape`.
template <typename T>
nb::object ToNumpy(std::vector<T> values, std::vector<size_t> shape) {
  auto* heap = new std::vector<T>(std::move(values));
  nb::capsule owner(heap, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::ndarray<nb::numpy, T>(heap->data(), shape.size(), shape.data(), owner).cast();
}
nb::object ToNumpy(std::vector<double> values, std::vector<size_t> shape) {
  return ToNumpy<double>(std::move(values), std::move(shape));
}

// One value per chamber as a NumPy vector.
nb::object PerChamber(const std::array<double, 4>& a) {
  return ToNumpy({a[0], a[1], a[2], a[3]}, {4});
}

template <size_t N>
nb::object Rows(const std::vector<std::array<double, N>>& rows) {
  std::vector<double> flat;
  flat.reserve(rows.size() * N);
  for (const auto& r : rows) flat.insert(flat.end(), r.begin(), r.end());
  return ToNumpy(std::move(flat), {rows.size(), N});
}

// A NumPy bool array (std::vector<bool> holds bits, not bools).
nb::object Flags(const std::vector<bool>& v) {
  bool* heap = new bool[v.size()];
  std::copy(v.begin(), v.end(), heap);
  nb::capsule owner(heap, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
  const size_t shape[1] = {v.size()};
  return nb::ndarray<nb::numpy, bool>(heap, 1, shape, owner).cast();
}

template <typename T>
nb::object Column(const std::vector<T>& v) {
  return ToNumpy<T>(v, {v.size()});
}

// {"key", nb::cast(value)}, ... -> a dict.
nb::dict Dict(std::initializer_list<std::pair<const char*, nb::object>> items) {
  nb::dict d;
  for (const auto& [key, value] : items) d[key] = value;
  return d;
}

[[noreturn]] void Fail(const std::string& what) { throw std::runtime_error(what); }
// A bad argument: ValueError in Python. The message comes from the same C++ check the command
// line uses (one validation home per input).
[[noreturn]] void Invalid(const std::string& what) { throw std::invalid_argument(what); }
// A study stopped by SIGINT/SIGTERM (the job runner takes the signal while it runs and keeps
// the finished results): KeyboardInterrupt, as Python's own Ctrl-C, saying what was kept.
[[noreturn]] void Interrupted(const std::string& what) {
  PyErr_SetString(PyExc_KeyboardInterrupt, what.c_str());
  throw nb::python_error();
}

// Ctrl-C (KeyboardInterrupt) or SystemExit raised inside a Python controller: kept here while
// the trial it stopped unwinds, and raised again when the binding returns to Python (never
// swallowed into a controller fault). Touched only with the GIL held.
std::unique_ptr<nb::python_error>& PendingInterrupt() {
  static std::unique_ptr<nb::python_error> pending;
  return pending;
}

// Raises the pending interrupt, or one Python's signal handler has noted since the GIL was
// released (a Ctrl-C during the physics).
void RaisePendingInterrupt() {
  if (std::unique_ptr<nb::python_error> e = std::move(PendingInterrupt())) {
    e->restore();
    throw nb::python_error();
  }
  if (PyErr_CheckSignals() != 0) throw nb::python_error();
}

// Names as the bindings take them, like sweep's lists: a list (or tuple) of strings, or one
// string of comma-separated names as the command line's --objects takes them.
std::string NameListArg(const nb::object& names, const char* what) {
  if (nb::isinstance<nb::str>(names)) return nb::cast<std::string>(names);
  if (!nb::isinstance<nb::list>(names) && !nb::isinstance<nb::tuple>(names)) {
    Invalid(std::string(what) + " must be a list of names or one comma-separated string");
  }
  std::string joined;
  for (nb::handle item : names) {
    if (!nb::isinstance<nb::str>(item)) {
      Invalid(std::string(what) + ": " + nb::cast<std::string>(nb::repr(item)) +
              " is not a name (a string)");
    }
    joined += (joined.empty() ? "" : ",") + nb::cast<std::string>(item);
  }
  if (joined.empty()) Invalid(std::string(what) + ": the list is empty");
  return joined;
}

// timeout_s as the bindings take it: 0 = the default, else the trial's own range check.
void SetTimeout(double timeout_s, TrialConfig* config) {
  if (timeout_s != 0) config->timeout_s = timeout_s;
  if (const std::string e = config->Validate(); !e.empty()) Invalid(e);
}

ModelPtr Load(const std::string& scene) {
  std::string error;
  ModelPtr m = LoadModel(ResolveScenePath(scene), &error);
  if (!m) Fail(error);
  return m;
}

// A seed from Python: a whole number in kSeedRange, an int (or anything with __index__) or a
// float holding one, as every ssc --seed takes it. Anything else is a ValueError naming the
// argument and the range: a seed above 2^53 - 1 would lose its last bits on the way through
// doubles, one above 2^64 would wrap, and a fraction would be cut.
std::uint64_t SeedArg(const nb::handle& value) {
  PyObject* o = value.ptr();
  auto refuse = [&]() {
    Invalid("seed = " + std::string(nb::repr(value).c_str()) + " is not " + kSeedRange.ToString());
  };
  if (PyBool_Check(o)) refuse();  // an int to Python, but True is not a seed anyone meant
  if (PyFloat_Check(o)) {
    const double v = PyFloat_AsDouble(o);
    if (!kSeedRange.Contains(v)) refuse();
    return static_cast<std::uint64_t>(v);
  }
  if (!PyIndex_Check(o)) refuse();
  nb::object index = nb::steal(PyNumber_Index(o));
  if (!index.is_valid()) throw nb::python_error();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (v == -1 && PyErr_Occurred()) throw nb::python_error();
  if (overflow != 0 || v < 0 || static_cast<double>(v) > kSeedRange.hi) refuse();
  return static_cast<std::uint64_t>(v);
}

// Where the trials' test objects' scenes are written: a folder of this process in the temp dir,
// removed when the process that made it exits (a forked child leaves it to its parent).
const std::filesystem::path& ObjectSceneDir() {
  struct Dir {
    std::filesystem::path path;
    int owner_pid;
    ~Dir() {
      std::error_code ec;
      if (getpid() == owner_pid) std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir{
      std::filesystem::temp_directory_path() / ("ssc_twin_objects_" + std::to_string(getpid())),
      getpid()};
  return dir.path;
}

// effects: "default" (the fitted set), "off" or key=value,... (as --effects).
TrialConfig MakeConfig(double pref, double beta, double step_mm, std::uint64_t seed,
                       const std::string& object, const std::string& effects, std::string* scene) {
  TrialConfig config;
  config.law.p_ref_pa = pref;
  config.law.beta = beta;
  config.law.step_mm = step_mm;
  config.seed = seed;
  if (!object.empty()) {
    // A test object: its scenes are written next to the other generated files (like ssc view).
    const ObjectSpec spec = ObjectByName(object);
    if (spec.name.empty())
      Invalid("unknown test object '" + object +
              "' (e.g. disk_d10, hole_d10, corner_a090, volute)");
    // The object's scene of the scene's tier (the rig's table: arm, gantry or flex).
    ObjectSceneKind kind = ObjectSceneKind::kGantry;
    if (std::string e; !ObjectSceneKindOfScene(*scene, &kind, &e)) Invalid(e);
    const std::filesystem::path& dir = ObjectSceneDir();
    std::string error;
    if (!WriteObjectFiles(spec, dir.string(), ResourceDir(), RigObjectSceneTemplates(), &error)) {
      Fail(error);
    }
    *scene = (dir / ObjectSceneFile(spec, kind)).string();
    config = ObjectTrialConfig(spec, config);
  }
  if (std::string e; !ParseRobotEffects(effects, &config.effects, &e)) Invalid(e);
  if (const std::string e = config.Validate(); !e.empty()) Invalid(e);
  return config;
}

nb::dict MetricsDict(const TrialResult& r) {
  const DiskTrialMetrics& m = r.metrics;
  nb::dict d;
  d["s_mm"] = m.s_mm;
  d["r_mean_mm"] = m.r_mean_mm;
  d["dr_mm"] = m.dr_mm;
  d["sigma_r_mm"] = m.sigma_r_mm;
  d["s_c"] = m.s_c;
  d["duration_s"] = m.duration_s;
  d["speed_mm_s"] = m.speed_mm_s;
  d["speed_body_d_s"] = m.speed_body_d_s;
  d["contour_mean_mm"] = m.contour_mean_mm;
  d["contour_max_mm"] = m.contour_max_mm;
  d["swept_deg"] = r.swept_deg;
  d["end_arc_mm"] = r.end_arc_mm;
  d["iterations"] = r.iterations;
  return d;
}

nb::dict LogDict(const std::vector<TrialLogRow>& log) {
  std::vector<double> t, pbar, dpx, dpy, cf, ft, phase, iteration;
  std::vector<std::array<double, 3>> tool;
  std::vector<std::array<double, 4>> p;
  std::vector<std::array<double, 2>> step;
  for (const TrialLogRow& row : log) {
    t.push_back(row.t_s);
    tool.push_back(row.tool_m);
    p.push_back(row.p_pa);
    pbar.push_back(row.pbar_pa);
    dpx.push_back(row.dpx_pa);
    dpy.push_back(row.dpy_pa);
    cf.push_back(row.cf);
    step.push_back({row.step_x_m, row.step_y_m});
    ft.push_back(row.ft_normal_n);
    phase.push_back(static_cast<double>(row.phase));
    iteration.push_back(row.iteration ? 1 : 0);
  }
  nb::dict d;
  d["t_s"] = Column(t);
  d["tool_m"] = Rows(tool);
  d["p_pa"] = Rows(p);
  d["pbar_pa"] = Column(pbar);
  d["dpx_pa"] = Column(dpx);
  d["dpy_pa"] = Column(dpy);
  d["cf"] = Column(cf);
  d["step_m"] = Rows(step);
  d["ft_normal_n"] = Column(ft);
  d["phase"] = Column(phase);  // 0 approach, 1 move, 2 follow, 3 done (phase_names)
  d["iteration"] = Column(iteration);
  return d;
}

nb::dict ResultDict(const std::string& scene, const TrialConfig& c, const TrialResult& r) {
  nb::dict d;
  d["scene"] = scene;
  d["outcome"] = std::string(OutcomeName(r.outcome));
  d["detail"] = r.detail;
  d["seed"] = c.seed;
  d["parameters"] = Dict({{"pref_pa", nb::cast(c.law.p_ref_pa)},
                          {"beta", nb::cast(c.law.beta)},
                          {"step_mm", nb::cast(c.law.step_mm)},
                          {"timeout_s", nb::cast(c.timeout_s)},
                          {"control_period_s", nb::cast(c.control_period_s)}});
  d["metrics"] = MetricsDict(r);
  d["follow_time_s"] = r.follow_time_s;
  d["sim_time_s"] = r.sim_time_s;
  d["wall_time_s"] = r.wall_time_s;
  d["hold_height_mm"] = r.hold_height_m * 1e3;
  if (!r.log.empty()) d["log"] = LogDict(r.log);
  return d;
}

nb::dict StepDict(const ContourStep& s) {
  nb::dict d;
  d["p_mean_pa"] = s.p_mean_pa;
  d["dpx_pa"] = s.dpx_pa;
  d["dpy_pa"] = s.dpy_pa;
  d["cf"] = s.cf;
  d["moving"] = s.moving;
  d["along_edge"] = ToNumpy({s.along_edge[0], s.along_edge[1]}, {2});
  d["correction"] = ToNumpy({s.correction[0], s.correction[1]}, {2});
  d["direction"] = ToNumpy({s.direction[0], s.direction[1]}, {2});
  d["step_m"] = ToNumpy({s.step_m[0], s.step_m[1]}, {2});
  return d;
}

ContourLawParams Law(double pref, double beta, double step_mm) {
  ContourLawParams law;
  law.p_ref_pa = pref;
  law.beta = beta;
  law.step_mm = step_mm;
  if (const std::string e = law.Validate(); !e.empty()) Invalid(e);
  return law;
}

// The per-cell results of a validation as cells.csv has them (one entry per cell, map order):
// NumPy arrays of numbers and counts, lists of class / failure names.
nb::dict CellsDict(const std::vector<CellScore>& cells) {
  std::vector<double> step, beta, pref, p, p_low, p_high, agreement, surface_p;
  std::vector<std::int64_t> of3, successes, trials, off_edge, grasp, timeout, unstable, lost;
  std::vector<bool> match, opposite;
  std::vector<std::string> published, twin, main_failure;
  for (const CellScore& c : cells) {
    step.push_back(c.cell.step_mm);
    beta.push_back(c.cell.beta);
    pref.push_back(c.cell.pref_pa);
    published.emplace_back(MapClassName(c.cell.published));
    twin.emplace_back(MapClassName(c.twin_class));
    of3.push_back(c.successes_of_3);
    match.push_back(c.class_match);
    successes.push_back(c.successes);
    trials.push_back(c.trials);
    p.push_back(c.p_success);
    p_low.push_back(c.p_interval[0]);
    p_high.push_back(c.p_interval[1]);
    agreement.push_back(c.expected_agreement);
    opposite.push_back(c.opposite);
    off_edge.push_back(c.failure_off_edge);
    grasp.push_back(c.failure_grasp);
    timeout.push_back(c.timeout);
    unstable.push_back(c.unstable);
    lost.push_back(c.lost_edge);
    main_failure.push_back(c.main_failure);
    surface_p.push_back(c.surface_p);
  }
  nb::dict d;
  d["step_mm"] = Column(step);
  d["beta"] = Column(beta);
  d["pref_pa"] = Column(pref);
  d["published"] = nb::cast(published);  // "3", "2" or "<=1"
  d["twin_class"] = nb::cast(twin);      // from the first 3 seeds
  d["successes_of_3"] = Column(of3);
  d["class_match"] = Flags(match);
  d["successes"] = Column(successes);
  d["trials"] = Column(trials);
  d["p_success"] = Column(p);
  d["p_low"] = Column(p_low);  // Wilson 95 % interval
  d["p_high"] = Column(p_high);
  d["expected_agreement"] = Column(agreement);
  d["opposite"] = Flags(opposite);
  d["failure_I"] = Column(off_edge);
  d["failure_II"] = Column(grasp);
  d["timeout"] = Column(timeout);
  d["unstable"] = Column(unstable);
  d["lost_edge"] = Column(lost);
  d["main_failure"] = nb::cast(main_failure);  // "" when every trial succeeded
  d["surface_p"] = Column(surface_p);          // the smooth surface's rate (NaN: none fitted)
  return d;
}

// A study's progress for Python: None (quiet), True (a line on sys.stderr each time another 5 %
// of the trials is done) or a callable progress(done, total, elapsed_s). Called from the
// study's worker threads, which hold no GIL: it takes the GIL for each call. An exception in
// the callable stops further calls and is raised once the study returns (Raise()).
class PyProgress {
 public:
  PyProgress(nb::object progress, std::string name)
      : progress_(std::move(progress)), name_(std::move(name)) {
    if (!progress_.is_none() && !nb::isinstance<nb::bool_>(progress_) &&
        !PyCallable_Check(progress_.ptr())) {
      throw nb::type_error("progress must be None, True or a callable (done, total, elapsed_s)");
    }
  }
  std::function<void(const SweepProgress&)> Callback() {
    if (progress_.is_none() || (nb::isinstance<nb::bool_>(progress_) && !nb::cast<bool>(progress_)))
      return nullptr;
    return [this](const SweepProgress& s) { Report(s); };
  }
  void Raise() {
    if (error_) {
      std::unique_ptr<nb::python_error> e = std::move(error_);
      e->restore();
      throw nb::python_error();
    }
  }

 private:
  void Report(const SweepProgress& s) {
    nb::gil_scoped_acquire gil;
    if (error_ || s.total <= 0) return;
    try {
      if (nb::isinstance<nb::bool_>(progress_)) {
        const int percent = 100 * s.done / s.total;
        if (percent < next_percent_ && s.done < s.total) return;
        next_percent_ = (percent / 5 + 1) * 5;
        const int ran = s.done - s.skipped;
        const double rate = s.elapsed_s > 0 ? ran / s.elapsed_s : 0;
        const double eta = rate > 0 ? (s.total - s.done) / rate : 0;
        char line[160];
        std::snprintf(line, sizeof line,
                      "%s: %d/%d trials (%d %%), %.1f trials/s, %.0f s, ETA %.0f s\n",
                      name_.c_str(), s.done, s.total, percent, rate, s.elapsed_s, eta);
        nb::module_::import_("sys").attr("stderr").attr("write")(std::string(line));
      } else {
        progress_(s.done, s.total, s.elapsed_s);
      }
    } catch (nb::python_error& e) {
      error_ = std::make_unique<nb::python_error>(std::move(e));
    }
  }

  nb::object progress_;
  std::string name_;
  int next_percent_ = 0;
  std::unique_ptr<nb::python_error> error_;
};

// A Python object kept alive by C++ that may be dropped on a thread without the GIL (a worker
// of a sweep): the reference is released under the GIL.
struct PyRef {
  explicit PyRef(nb::object o) : object(std::move(o)) {}
  ~PyRef() {
    nb::gil_scoped_acquire gil;
    object.reset();
  }
  PyRef(const PyRef&) = delete;
  PyRef& operator=(const PyRef&) = delete;
  nb::object object;
};

// "TypeError: message" of a Python exception (its traceback is Python's to print).
std::string PythonErrorText(const nb::python_error& e) {
  return "Python " + nb::cast<std::string>(nb::str(e.type().attr("__name__"))) + ": " +
         nb::cast<std::string>(nb::str(e.value()));
}

nb::dict LawDict(const ContourLawParams& law) {
  return Dict({{"pref_pa", nb::cast(law.p_ref_pa)},
               {"beta", nb::cast(law.beta)},
               {"step_mm", nb::cast(law.step_mm)},
               {"p_noise_pa", nb::cast(law.p_noise_pa)},
               {"p_grasp_pa", nb::cast(law.p_grasp_pa)},
               {"object_on_left", nb::cast(law.side == FollowSide::kObjectOnLeft)},
               {"dead_band", nb::cast(law.dead_band)}});
}

// A Python callable as a controller (controller/pure/controller.h): called with a dict of the
// host's reading, it returns the planar step (dx, dy) in m, tool frame, or a dict with "step_m"
// and optionally "height_offset_m" and "lifted". Each call takes the GIL, so trials on several
// threads call it one at a time. An exception or a malformed answer ends the trial as
// controller_fault with the reason.
class PyController : public Controller {
 public:
  PyController(std::shared_ptr<PyRef> fn, const ControllerContext& context)
      : fn_(std::move(fn)), law_(context.law), period_s_(context.control_period_s) {}
  ~PyController() override {
    nb::gil_scoped_acquire gil;
    fn_.reset();
  }

  ControllerCommand Step(const ControllerInput& in) override {
    nb::gil_scoped_acquire gil;
    ControllerCommand bad;
    std::string answer_type;
    bad.step_m = {std::nan(""), std::nan("")};
    try {
      nb::dict d;
      d["t_s"] = in.t_s;
      d["follow_s"] = in.follow_s;
      d["iteration"] = in.iteration;
      d["p_pa"] = nb::cast(in.p_pa);
      d["ft_normal_n"] = in.ft_normal_n;
      d["tool_m"] = nb::cast(in.tool_m);
      d["tool_rotation"] = nb::cast(in.tool_rotation);
      d["hold_z_m"] = in.hold_z_m;
      d["control_period_s"] = period_s_;
      d["law"] = LawDict(law_);
      nb::object r = fn_->object(d);
      answer_type = nb::cast<std::string>(nb::str(r.type().attr("__name__")));
      ControllerCommand c;
      if (nb::isinstance<nb::dict>(r)) {
        nb::dict rd = nb::borrow<nb::dict>(r);
        if (!rd.contains("step_m")) {
          fault_ = "the controller's dict has no 'step_m'";
          return bad;
        }
        c.step_m = nb::cast<std::array<double, 2>>(rd["step_m"]);
        if (rd.contains("height_offset_m"))
          c.height_offset_m = nb::cast<double>(rd["height_offset_m"]);
        if (rd.contains("lifted")) c.lifted = nb::cast<bool>(rd["lifted"]);
      } else {
        c.step_m = nb::cast<std::array<double, 2>>(r);
      }
      fault_.clear();
      return c;
    } catch (nb::python_error& e) {
      if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_SystemExit)) {
        fault_ = "interrupted: " + PythonErrorText(e);
        if (!PendingInterrupt())
          PendingInterrupt() = std::make_unique<nb::python_error>(std::move(e));
        interrupted_ = true;
        return bad;
      }
      fault_ = PythonErrorText(e);
    } catch (const std::exception&) {
      fault_ = "the controller returned " +
               (answer_type.empty() ? "something" : "a " + answer_type) +
               ", not (dx, dy) in m or a dict with 'step_m' (and height_offset_m, lifted)";
    }
    return bad;
  }
  std::string FaultDetail() const override { return fault_; }
  bool Interrupted() const override { return interrupted_; }

 private:
  bool interrupted_ = false;
  std::shared_ptr<PyRef> fn_;
  ContourLawParams law_;
  double period_s_;
  std::string fault_;
};

// `controller`: a registered name (with `params` as --controller-param), a callable, or a class
// whose instance (one per trial, made with no arguments) is the callable.
ControllerChoice ChoiceFrom(const nb::object& controller, const std::string& params) {
  ControllerChoice choice;
  if (nb::isinstance<nb::str>(controller)) {
    std::string error;
    if (!ParseControllerChoice(nb::cast<std::string>(controller), params, &choice, &error))
      Invalid(error);
    return choice;
  }
  if (!PyCallable_Check(controller.ptr()))
    Invalid("controller must be a registered name (" + ControllerNames() + ") or a callable");
  if (!params.empty())
    Invalid("controller_params apply to a registered controller, not a callable");
  const bool per_trial = PyType_Check(controller.ptr());
  auto ref = std::make_shared<PyRef>(controller);
  std::string label =
      nb::cast<std::string>(nb::str(nb::getattr(controller, "__name__", nb::str("python"))));
  choice.name = "python:" + label;
  choice.custom =
      std::make_shared<const std::function<std::unique_ptr<Controller>(const ControllerContext&)>>(
          [ref, per_trial](const ControllerContext& context) -> std::unique_ptr<Controller> {
            if (!per_trial) return std::make_unique<PyController>(ref, context);
            nb::gil_scoped_acquire gil;
            try {
              return std::make_unique<PyController>(std::make_shared<PyRef>(ref->object()),
                                                    context);
            } catch (const nb::python_error& e) {
              // Made inside the trial's setup: a failure there is reported by the first step.
              struct Failed : Controller {
                explicit Failed(std::string why) : why_(std::move(why)) {}
                ControllerCommand Step(const ControllerInput&) override {
                  ControllerCommand c;
                  c.step_m = {std::nan(""), std::nan("")};
                  return c;
                }
                std::string FaultDetail() const override { return why_; }
                std::string why_;
              };
              return std::make_unique<Failed>(PythonErrorText(e));
            }
          });
  return choice;
}

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
  // As RunTrialShared decides: the one pressure plugin, no callbacks that could feed the
  // pressures into the physics, and a controller that does not read the approach.
  bool CanShareApproach() const {
    const bool callbacks = mjcb_passive || mjcb_act_dyn || mjcb_act_gain || mjcb_act_bias ||
                           mjcb_sensor || mjcb_contactfilter;
    return ApproachUnshareableReason(model_).empty() && !callbacks &&
           !trial_->ControllerObservesApproach();
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
  std::array<double, 6> ForceTorque() const {
    // The F/T sensors as the model names them (force then torque, N and N m).
    std::array<double, 6> ft{};
    const RigBinding& rig = trial_->rig();
    for (int k = 0; k < 3; ++k) {
      ft[k] = data_->sensordata[rig.force_adr + k];
      if (rig.torque_adr >= 0) ft[3 + k] = data_->sensordata[rig.torque_adr + k];
    }
    return ft;
  }
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

// The plant behind the software-in-the-loop stand-ins (ssc_twin.sil): a scene stepped one physics
// step at a time, its tool site driven to a Cartesian target through the scene's servo (the UR
// servoL look-ahead smoothing, runtime/tool_servo.h), read back as the sensors report it. The
// pressure plugin's host average is set to one sample so each reading is one raw sensor packet
// (the lab's host code averages 7 itself). Positions are the tool site (lip-plane centre) in the
// scene frame, m.
class SilPlant {
 public:
  SilPlant(const std::string& scene, const nb::object& seed, int average_samples) {
    scene_ = scene;
    std::string error;
    model_ = ToolModelVariant(ResolveScenePath(scene),
                              {{"average_samples", std::to_string(average_samples)}}, &error);
    if (!model_) Fail(error);
    data_ = MakeData(model_.get(), &error);
    if (!data_) Fail(error);
    if (std::string e = rig_.Bind(model_.get(), data_.get()); !e.empty()) Fail(scene + ": " + e);
    if (rig_.torque_adr < 0) Fail(scene + ": no F/T torque sensor");
    Reset(seed);
  }
  void Reset(const nb::object& seed) {
    rig_.Reset(model_.get(), data_.get(), SeedArg(seed));
    std::string error;
    if (!rig_.servo->Init(model_.get(), data_.get(), rig_.tool_site, &error)) Fail(error);
  }
  // The target the servo tracks, tool site in the scene frame, m.
  void SetTarget(std::array<double, 3> xyz) { rig_.servo->SetTarget({xyz[0], xyz[1], xyz[2]}); }
  std::array<double, 3> Target() const { return rig_.servo->target(); }
  // smoothing_s: the look-ahead time constant (0 = none); max_speed_m_s: the command's speed
  // limit (moveL's speed).
  void SetServo(double smoothing_s, double max_speed_m_s) {
    if (!(smoothing_s >= 0) || !(max_speed_m_s > 0)) {
      Fail("servo: smoothing_s must be >= 0 and max_speed_m_s > 0");
    }
    ServoParams s;
    s.smoothing_s = smoothing_s;
    s.max_speed_m_s = max_speed_m_s;
    rig_.servo->set_params(s);
  }
  // Holds the command where the tool is now (servoStop): no motion left to realise.
  void Stop() {
    ToolServo::State s = rig_.servo->state();
    const Vec3 here = rig_.servo->Measured(data_.get());
    s.target = here;
    s.command = here;
    s.velocity = {0, 0, 0};
    rig_.servo->set_state(s);
  }
  // Physics steps until the simulated time reaches t_s (at least none); returns the time.
  double AdvanceTo(double t_s) {
    nb::gil_scoped_release release;
    const double dt = model_->opt.timestep;
    while (data_->time + 0.5 * dt <= t_s) {
      rig_.servo->Track(model_.get(), data_.get());
      mj_step(model_.get(), data_.get());
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(data_->qpos[k])) Fail("the simulation became unstable");
      }
    }
    return data_->time;
  }
  std::array<double, 3> ToolPosition() const {
    const double* p = data_->site_xpos + 3 * rig_.tool_site;
    return {p[0], p[1], p[2]};
  }
  // The tool site's rotation, row-major (mjData.site_xmat).
  std::array<double, 9> ToolRotation() const {
    std::array<double, 9> r{};
    for (int k = 0; k < 9; ++k) r[k] = data_->site_xmat[9 * rig_.tool_site + k];
    return r;
  }
  // The newest sensor sample: four chamber vacuums, Pa (positive = vacuum).
  std::array<double, 4> Vacuum() const {
    const double* p = data_->sensordata + rig_.pressure_adr;
    return {p[0], p[1], p[2], p[3]};
  }
  // Force (N) and torque (N m) the transducer exerts on the cup, F/T site frame (z down the cup
  // axis: pressing on a surface reads +z).
  std::array<double, 6> ForceTorque() const {
    std::array<double, 6> ft{};
    for (int k = 0; k < 3; ++k) {
      ft[k] = data_->sensordata[rig_.force_adr + k];
      ft[3 + k] = data_->sensordata[rig_.torque_adr + k];
    }
    return ft;
  }
  double Time() const { return data_->time; }
  double Timestep() const { return model_->opt.timestep; }
  // The sensor's sample rate, Hz (its config).
  double SampleRateHz() const {
    return FindChamberPressureDiagnostics(model_.get(), data_.get())
        ->config()
        .sensor.sample_rate_hz;
  }
  std::string scene() const { return scene_; }
  // A static geom's centre x, y and top z in the scene frame, m (cylinders and boxes).
  std::array<double, 3> GeomTop(const std::string& name) const {
    const int g = mj_name2id(model_.get(), mjOBJ_GEOM, name.c_str());
    if (g < 0) Fail(scene_ + ": no geom '" + name + "'");
    const int type = model_->geom_type[g];
    if (type != mjGEOM_CYLINDER && type != mjGEOM_BOX)
      Fail("geom '" + name + "' is not a cylinder or box");
    const double* p = data_->geom_xpos + 3 * g;
    const double half = model_->geom_size[3 * g + (type == mjGEOM_BOX ? 2 : 1)];
    return {p[0], p[1], p[2] + half};
  }
  // Raw model/data addresses for the viewer (mujoco.MjModel/MjData cannot wrap them; the viewer
  // re-loads the scene and copies qpos).
  std::vector<double> Qpos() const {
    return std::vector<double>(data_->qpos, data_->qpos + model_->nq);
  }

 private:
  std::string scene_;
  ModelPtr model_;
  DataPtr data_;
  RigBinding rig_;
};

double DictNumber(const nb::dict& d, const char* key) {
  return d.contains(key) ? nb::cast<double>(d[key]) : kNoValue;
}
std::vector<double> DictNumbers(const nb::dict& d, const char* key) {
  return d.contains(key) ? nb::cast<std::vector<double>>(d[key]) : std::vector<double>{};
}

// The lab's merged .mat from one logger recording (its per-topic CSVs) and the script's
// arguments, written by the C++ MAT writer (robotlog/mat_log.h) as the lab's saver lays it out.
std::string WriteLabMat(const std::string& recording, const std::string& mat_dir,
                        const std::string& append_txt, const nb::dict& args) {
  RobotLog log;
  LoadError error;
  if (!LoadTopicCsvRecording(recording, &log, &error)) Fail(error.ToString());
  LabRunArgs& a = log.args;
  a.p_ref_pa = DictNumber(args, "Pref");
  a.beta = DictNumber(args, "beta");
  a.d_lat_m = DictNumber(args, "d_lat");
  a.disk_radius_mm = DictNumber(args, "diskRadius");
  a.start_offset_m = DictNumber(args, "start_offset");
  a.success = DictNumber(args, "success");
  a.p_lims_pa = DictNumbers(args, "P_lims");
  a.alpha_beta = DictNumbers(args, "alpha_beta");
  a.fz_set_n = DictNumbers(args, "Fz_set");
  if (args.contains("edgeFollowing_history")) {
    for (nb::handle row : nb::iter(args["edgeFollowing_history"])) {
      const std::vector<double> v = nb::cast<std::vector<double>>(row);
      if (v.size() != kHistoryRowNumbers) {
        Fail(
            "edgeFollowing_history: each row needs 14 numbers [t, x, y, r_p(2), corr_p(2), "
            "r_p_final(2), F_normal, P1..P4], got " +
            std::to_string(v.size()));
      }
      a.history.push_back(HistoryRowFromNumbers(v.data()));
    }
  }
  const std::string stamp = RecordingStamp(log.t0_ns);
  const std::string path =
      mat_dir + "/DataLog_" + stamp + (append_txt.empty() ? "" : "_" + append_txt) + ".mat";
  std::string werr;
  if (!WriteRobotLogMat(path, log, &werr)) Fail(werr);
  return path;
}

}  // namespace
}  // namespace ssc

NB_MODULE(_core, m) {
  // A Python controller held by a trial that Python still held at exit (a closure over the
  // environment that owns the trial) is a cycle through C++ that Python's collector cannot see:
  // freed by the process's end, not a leak to report on every exit.
  nb::set_leak_warnings(false);
  using namespace ssc;
  m.doc() = "Smart Suction Cup twin: trials, sweeps, validation, probe and log comparison (C++).";
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "law_defaults",
      [law] {
        return Dict({{"pref", nb::cast(law.p_ref_pa)},
                     {"beta", nb::cast(law.beta)},
                     {"step_mm", nb::cast(law.step_mm)}});
      },
      "The contour law's default P_ref (Pa), beta and step (mm): ContourLawParams{} in C++.");

  m.attr("max_seed") = static_cast<std::uint64_t>(kSeedRange.hi);
  m.def(
      "check_seed", [](const nb::object& seed) { return SeedArg(seed); }, "seed"_a,
      "The seed as an int when it is a whole number in [0, max_seed] (2^53 - 1, as every ssc "
      "--seed), else ValueError naming the range.");
  m.def("resource_dir", &ResourceDir, "The folder holding models/ and scenes/.");
  m.def("set_resource_dir", &SetResourceDir, "dir"_a);
  m.def("scene_path", &ResolveScenePath, "scene"_a,
        "Path of a scene given by name (under scenes/) or path.");
  m.def("default_scene", &DefaultScene,
        "The scene every trial entry point runs when none is named (runtime/rig.h).");
  m.def(
      "scene_tiers",
      [] {
        nb::list tiers;
        for (const RigTier& t : RigTiers()) {
          tiers.append(Dict({{"name", nb::cast(std::string(t.name))},
                             {"scene", nb::cast(std::string(t.scene))},
                             {"kind", nb::cast(std::string(RigKindName(t.kind)))},
                             {"timestep_s", nb::cast(t.timestep_s)},
                             {"what", nb::cast(std::string(t.what))}}));
        }
        return tiers;
      },
      "The rig's scene tiers (runtime/rig.h): name, scene, kind (arm, gantry, flex, replay, "
      "probe), time step and what each is.");
  m.def("mujoco_version", [] { return std::string(mj_versionString()); });
  m.def("check_mujoco_version", &CheckMuJoCoVersion,
        "Empty when the loaded libmujoco matches the headers this was built with.");
  m.def("install_message_handlers", [] {
    // Only where the host (e.g. the mujoco package) set none: no MUJOCO_LOG.TXT litter.
    InstallMuJoCoMessageHandlers();
  });
  m.attr("default_control_period_s") = TrialConfig{}.control_period_s;
  m.def(
      "plugin_registered",
      [] { return mjp_getPlugin(kChamberPressurePluginName, nullptr) != nullptr; },
      "Whether the running libmujoco has the ssc.chamber_pressure plugin.");
  m.def("phase_names", [] {
    return std::vector<std::string>{PhaseName(TrialPhase::kApproach),
                                    PhaseName(TrialPhase::kMoveToStart),
                                    PhaseName(TrialPhase::kFollow), PhaseName(TrialPhase::kDone)};
  });
  m.def(
      "controllers",
      [] {
        nb::dict d;
        for (const ControllerType& t : ControllerTypes()) {
          nb::list keys;
          for (const ControllerParamKey& k : t.keys) {
            keys.append(Dict({{"key", nb::cast(k.key)},
                              {"unit", nb::cast(k.unit)},
                              {"default", nb::cast(k.default_value)},
                              {"min", nb::cast(k.min)},
                              {"max", nb::cast(k.max)},
                              {"what", nb::cast(k.what)}}));
          }
          d[t.name.c_str()] = Dict({{"what", nb::cast(t.what)}, {"keys", keys}});
        }
        return d;
      },
      "The registered controllers: name -> what it is and its parameter keys (unit, default, "
      "range).");
  m.def("object_names", [] {
    std::vector<std::string> names;
    for (const ObjectSpec& s : AllObjects()) names.push_back(s.name);
    return names;
  });

  m.def("wilson_interval", &WilsonInterval, "successes"_a, "trials"_a,
        "The Wilson score interval (95 %) of a success rate (studies/statistics/intervals.h).");
  m.def("student_t95", &StudentT95, "dof"_a,
        "The two-sided 95 % Student t quantile for dof degrees of freedom (dof >= 1).");
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

  m.def(
      "sweep",
      [](const std::string& scene, std::vector<double> pref, std::vector<double> beta,
         std::vector<double> step_mm, int repeats, const nb::object& seed, int threads,
         const std::string& out_csv, const std::string& effects, const nb::object& controller,
         const std::string& controller_params, nb::object progress) {
        PyProgress reporter(std::move(progress), "ssc_twin.sweep");
        SweepSpec spec;
        if (std::string e; !ParseRobotEffects(effects, &spec.base.effects, &e)) Fail(e);
        spec.base.controller = ChoiceFrom(controller, controller_params);
        spec.scene_name = scene;
        spec.pref_pa = std::move(pref);
        spec.beta = std::move(beta);
        spec.step_mm = std::move(step_mm);
        spec.repeats = repeats;
        spec.seed = SeedArg(seed);
        spec.threads = threads;
        spec.out_csv = out_csv;
        if (out_csv.empty()) Invalid("out_csv is empty: give the sweep CSV's path");
        if (const std::string e = CheckSweepGrid(spec); !e.empty()) Invalid(e);
        ModelPtr model = Load(scene);
        SweepSummary summary;
        std::string error;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunSweep(model.get(), spec, reporter.Callback(), &summary, &error);
        }
        reporter.Raise();
        RaisePendingInterrupt();
        if (!ok) Fail(error);
        if (summary.interrupted) {
          Interrupted("sweep interrupted: " + std::to_string(summary.ran) +
                      " finished rows kept in " + out_csv + "; call it again to resume");
        }
        return Dict({{"csv", nb::cast(out_csv)},
                     {"total", nb::cast(summary.total)},
                     {"ran", nb::cast(summary.ran)},
                     {"skipped", nb::cast(summary.skipped)},
                     {"wall_s", nb::cast(summary.wall_s)}});
      },
      "scene"_a = DefaultScene(), "pref"_a, "beta"_a, "step_mm"_a, "repeats"_a = 3, "seed"_a = 1,
      "threads"_a = 1, "out_csv"_a, "effects"_a = "default", "controller"_a = "published",
      "controller_params"_a = "", "progress"_a = nb::none(),
      "A P_ref x beta x step x repeats grid of trials into a resumable CSV (ssc sweep). "
      "controller as in run_trial (a callable is called under the GIL: threads > 1 run the "
      "physics in parallel, the callable one call at a time). progress: None (quiet), True (a "
      "line on stderr per 5 % of the trials) or a callable progress(done, total, elapsed_s).");

  m.def(
      "validate",
      [](const std::string& map, const std::string& out_dir, const std::string& scene, int seeds,
         const nb::object& seed, int threads, double timeout_s, const std::string& effects,
         const nb::object& controller, const std::string& controller_params, nb::object progress) {
        PyProgress reporter(std::move(progress), "ssc_twin.validate");
        ValidateSpec spec;
        spec.base.controller = ChoiceFrom(controller, controller_params);
        spec.map_path = map.empty() ? ResourceDir() + "/data/published/success_map_dl5.csv" : map;
        spec.scene_name = scene;
        spec.seed = SeedArg(seed);
        spec.out_dir = out_dir;
        if (seeds < 3 || seeds > 10000) {
          Invalid("seeds = " + std::to_string(seeds) +
                  " is out of range [3, 10000] (trials per cell)");
        }
        if (threads < 1 || threads > 256) {
          Invalid("threads = " + std::to_string(threads) + " is out of range [1, 256]");
        }
        spec.seeds = seeds;
        spec.threads = threads;
        std::string error;
        if (!ParseRobotEffects(effects, &spec.base.effects, &error)) Invalid(error);
        SetTimeout(timeout_s, &spec.base);
        // The map before anything is created (a FIFO, a device or a binary file is refused).
        if (std::vector<MapCell> cells; !ReadPublishedMap(spec.map_path, &cells, &error)) {
          Invalid(error);
        }
        if (out_dir.empty()) Invalid("out_dir is empty: give the output directory");
        std::error_code ec;
        std::filesystem::create_directories(out_dir, ec);
        if (ec || !std::filesystem::is_directory(out_dir)) {
          Fail("cannot create the output directory '" + out_dir + "'" +
               (ec ? ": " + ec.message() : std::string()));
        }
        ModelPtr model = Load(scene);
        MapScore score;
        SweepSummary summary;
        MapCeilings ceilings;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunValidation(model.get(), spec, reporter.Callback(), &score, &summary, &error,
                             nullptr, &ceilings);
        }
        reporter.Raise();
        RaisePendingInterrupt();
        if (summary.interrupted) Interrupted("validate " + error);
        if (!ok) Fail(error);
        nb::dict d;
        d["scores"] = Dict({{"cells", nb::cast(score.cells_scored)},
                            {"class_match", nb::cast(score.class_match)},
                            {"expected_agreement", nb::cast(score.expected_agreement)},
                            {"expected_agreement_interval",
                             nb::cast(std::vector<double>(score.agreement_interval.begin(),
                                                          score.agreement_interval.end()))},
                            {"opposite_cells", nb::cast(score.opposite)},
                            {"log_loss", nb::cast(score.log_loss)}});
        // What any twin can expect on this map (validate.json's "ceilings", "surface_ceilings").
        nb::list priors;
        for (const MapCeiling& c : ceilings.priors) {
          priors.append(Dict({{"prior", nb::cast(c.prior_name)},
                              {"prior_a", nb::cast(c.prior.a)},
                              {"prior_b", nb::cast(c.prior.b)},
                              {"rerun_agreement", nb::cast(c.rerun_agreement)},
                              {"oracle_agreement", nb::cast(c.oracle_agreement)},
                              {"rerun_reaches_goal", nb::cast(c.rerun_reaches_goal)},
                              {"oracle_reaches_goal", nb::cast(c.oracle_reaches_goal)}}));
        }
        d["ceilings"] = priors;
        nb::list surfaces;
        for (const SurfaceCeiling& s : ceilings.surfaces) {
          if (!s.fitted) continue;
          surfaces.append(Dict({{"step_mm", nb::cast(s.step_mm)},
                                {"rerun_agreement", nb::cast(s.rerun_agreement)},
                                {"oracle_agreement", nb::cast(s.oracle_agreement)},
                                {"loo_agreement", nb::cast(s.loo_agreement)}}));
        }
        d["surface_ceilings"] = surfaces;
        d["cells"] = CellsDict(score.cells);
        d["summary"] = Dict({{"total", nb::cast(summary.total)},
                             {"ran", nb::cast(summary.ran)},
                             {"skipped", nb::cast(summary.skipped)},
                             {"wall_s", nb::cast(summary.wall_s)}});
        d["map"] = spec.map_path;
        d["scene"] = scene;
        d["seeds_per_cell"] = seeds;
        d["base_seed"] = spec.seed;
        d["effects"] = FormatRobotEffects(spec.base.effects);
        d["out_dir"] = out_dir;
        return d;
      },
      "map"_a = "", "out_dir"_a = "out/validate", "scene"_a = DefaultScene(), "seeds"_a = 10,
      "seed"_a = 1, "threads"_a = 1, "timeout_s"_a = 0.0, "effects"_a = "default",
      "controller"_a = "published", "controller_params"_a = "", "progress"_a = nb::none(),
      "The twin on every cell of a published success map, scored (ssc validate). map: CSV "
      "step_mm,beta,pref_pa,successes_of_3 ('' = the published dL 5 mm map). Writes "
      "out_dir/trials.csv (resumable), cells.csv and validate.json; returns the scores, the "
      "per-cell results (NumPy arrays, cells.csv's columns) and the run summary. controller as "
      "in run_trial; progress as sweep's.");

  m.def(
      "objects",
      [](const nb::object& names, const std::string& out_dir, int seeds, const nb::object& seed,
         const std::string& scene_kind, double pref, double beta, double step_mm, int threads,
         const std::string& effects, const nb::object& controller,
         const std::string& controller_params) {
        ObjectStudySpec spec;
        std::string error;
        if (!ObjectsByNames(NameListArg(names, "objects"), &spec.objects, &error))
          Invalid("objects: " + error);
        if (seeds < 1 || seeds > 1000)
          Invalid("seeds = " + std::to_string(seeds) + " is out of range [1, 1000]");
        if (threads < 1 || threads > 256)
          Invalid("threads = " + std::to_string(threads) + " is out of range [1, 256]");
        if (!ObjectSceneKindByName(scene_kind, &spec.scene_kind, &error))
          Invalid("scene_kind: " + error);
        spec.seeds = seeds;
        spec.seed = SeedArg(seed);
        spec.law = Law(pref, beta, step_mm);
        spec.threads = threads;
        spec.out_dir = out_dir;
        if (!ParseRobotEffects(effects, &spec.effects, &error)) Invalid(error);
        spec.controller = ChoiceFrom(controller, controller_params);
        if (const std::string e = spec.controller.Validate(); !e.empty()) Invalid(e);
        std::error_code ec;
        std::filesystem::create_directories(out_dir, ec);
        if (ec || !std::filesystem::is_directory(out_dir)) {
          Fail("cannot create the output directory '" + out_dir + "'" +
               (ec ? ": " + ec.message() : std::string()));
        }
        ObjectStudySummary summary;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunObjectStudy(spec, nullptr, &summary, &error);
        }
        RaisePendingInterrupt();
        if (!ok) Fail(error);
        if (summary.interrupted) {
          Interrupted("objects interrupted: " + std::to_string(summary.finished) + " of " +
                      std::to_string(summary.trials) + " trials finished, their rows are in " +
                      summary.table_csv + "; call it again to resume");
        }
        return Dict({{"csv", nb::cast(summary.table_csv)},
                     {"paths_dir", nb::cast(summary.paths_dir)},
                     {"trials", nb::cast(summary.trials)},
                     {"skipped", nb::cast(summary.skipped)}});
      },
      "objects"_a = "all", "out_dir"_a = "out/objects", "seeds"_a = 1, "seed"_a = 1,
      "scene_kind"_a = ObjectSceneKindName(ObjectSceneKindOfTier(RigTierFor(RigUse::kTrial))),
      "pref"_a = law.p_ref_pa, "beta"_a = law.beta, "step_mm"_a = 0.5, "threads"_a = 1,
      "effects"_a = "default", "controller"_a = "published", "controller_params"_a = "",
      "The test objects' trials (ssc objects): writes out_dir/objects.csv (read it with "
      "read_sweep) and the cup paths; controller as in run_trial.");

  nb::class_<EdgeProbe3d>(m, "Probe",
                          "The cup on a mocap body placed over an edge; reads the sensor.")
      .def(
          "__init__",
          [](EdgeProbe3d* self, const std::string& scene) {
            std::string error;
            std::unique_ptr<EdgeProbe3d> p = EdgeProbe3d::Create(ResolveScenePath(scene), &error);
            if (!p) Fail(error);
            new (self) EdgeProbe3d(std::move(*p));
          },
          "scene"_a = RigTierFor(RigUse::kProbe).scene)
      .def(
          "read",
          [](EdgeProbe3d& p, double x_m, double y_m, double yaw_rad, double surface_z_m,
             double compression_m, double settle_s) {
            if (const std::string e = EdgeProbe3d::CheckPlacement(x_m, y_m, yaw_rad, surface_z_m,
                                                                  compression_m, settle_s);
                !e.empty()) {
              Invalid("Probe.read: " + e);
            }
            ProbeReading r;
            {
              nb::gil_scoped_release release;
              r = p.Read(x_m, y_m, yaw_rad, surface_z_m, compression_m, settle_s);
            }
            nb::dict d;
            d["filtered_pa"] = PerChamber(r.filtered_pa);
            d["static_pa"] = PerChamber(r.static_pa);
            d["sealed_area_mm2"] = PerChamber(r.sealed_area_mm2);
            d["leak_area_mm2"] = PerChamber(r.leak_area_mm2);
            d["lip_contacts"] = r.lip_contacts;
            d["pbar_pa"] = r.pbar_pa;
            d["dpx_pa"] = r.dpx_pa;
            d["dpy_pa"] = r.dpy_pa;
            d["g_world_rad"] = r.g_world_rad;
            d["travel_world_rad"] = r.travel_world_rad;
            d["static_pbar_pa"] = r.static_pbar_pa;
            return d;
          },
          "x_m"_a, "y_m"_a, "yaw_rad"_a = 0.0, "surface_z_m"_a = 0.010, "compression_m"_a = 0.001,
          "settle_s"_a = 0.3);

  m.def(
      "compare",
      [](const std::string& log_path, const std::string& scene, const std::string& out_dir,
         double tcp_offset_mm) {
        CompareOptions options;
        options.log_path = log_path;
        options.scene = scene;
        options.out_dir = out_dir;
        options.processing.tcp_offset_m = tcp_offset_mm * 1e-3;
        CompareResult result;
        std::string error;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunComparison(options, &result, &error);
        }
        if (!ok) Fail(error);
        const ReplayComparison& c = result.replay;
        nb::dict d;
        d["rms_pa"] = PerChamber(c.rms_pa);
        d["rms_log10"] = PerChamber(c.rms_log10);
        d["correlation"] = PerChamber(c.correlation);
        d["mean_ratio"] = PerChamber(c.mean_ratio);
        d["pbar_rms_pa"] = c.pbar_rms_pa;
        d["pbar_bias_pa"] = c.pbar_bias_pa;
        d["direction_rms_deg"] = c.direction_rms_deg;
        d["direction_median_deg"] = c.direction_median_deg;
        d["direction_samples"] = c.direction_samples;
        d["t_s"] = Column(c.t_s);
        d["sim_pa"] = Rows(c.sim_pa);
        d["log_pa"] = Rows(c.log_pa);
        d["tcp_m"] = Rows(c.tcp_m);
        d["report_dir"] = out_dir;
        d["warnings"] = nb::cast(result.log_warnings);  // e.g. a replay off the object
        return d;
      },
      "log"_a, "scene"_a = RigTierFor(RigUse::kReplay).scene, "out_dir"_a = "out/compare",
      "tcp_offset_mm"_a = kToolCentreOffsetM * 1e3,
      "Replays a robot log (lab per-topic CSVs, .mat or plain CSV) in the twin and compares the "
      "pressures, as `ssc compare` without the closed loop (report files into out_dir).");

  m.def(
      "write_robot_log",
      [](const std::string& dir, const std::string& scene, double pref, double beta, double step_mm,
         const nb::object& seed, const std::string& effects) {
        std::string scene_path = scene;
        const TrialConfig config =
            MakeConfig(pref, beta, step_mm, SeedArg(seed), "", effects, &scene_path);
        ModelPtr model = Load(scene_path);
        std::string error;
        TrialResult r;
        {
          nb::gil_scoped_release release;
          r = RunTrial(model.get(), config, true, &error);
        }
        std::vector<std::string> written;
        if (!WriteLabRecordingFromTrial(model.get(), r, config, dir, &written, &error)) {
          Fail(error);
        }
        return std::string(OutcomeName(r.outcome));
      },
      "dir"_a, "scene"_a = DefaultScene(), "pref"_a = law.p_ref_pa, "beta"_a = law.beta,
      "step_mm"_a = law.step_mm, "seed"_a = 1, "effects"_a = "default",
      "Runs a trial and writes it as a lab recording (ssc trial --robot-log).");

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
  nb::class_<SilPlant>(m, "SilPlant",
                       "A scene stepped from Python with its tool driven to Cartesian targets "
                       "(ssc_twin.sil's robot, sensors and pump).")
      .def(nb::init<const std::string&, const nb::object&, int>(), "scene"_a = DefaultScene(),
           "seed"_a = 1, "average_samples"_a = 1)
      .def("reset", &SilPlant::Reset, "seed"_a)
      .def("set_target", &SilPlant::SetTarget, "xyz_m"_a)
      .def("target", &SilPlant::Target)
      .def("set_servo", &SilPlant::SetServo, "smoothing_s"_a, "max_speed_m_s"_a)
      .def("stop", &SilPlant::Stop)
      .def("advance_to", &SilPlant::AdvanceTo, "t_s"_a)
      .def("tool_position", &SilPlant::ToolPosition)
      .def("tool_rotation", &SilPlant::ToolRotation)
      .def("vacuum", &SilPlant::Vacuum)
      .def("force_torque", &SilPlant::ForceTorque)
      .def("qpos", &SilPlant::Qpos)
      .def("geom_top", &SilPlant::GeomTop, "name"_a)
      .def_prop_ro("time", &SilPlant::Time)
      .def_prop_ro("timestep", &SilPlant::Timestep)
      .def_prop_ro("sample_rate_hz", &SilPlant::SampleRateHz)
      .def_prop_ro("scene", &SilPlant::scene);
  // The lab's disk benchmark set-up (compare/frames.h, geometry/dimensions.h).
  m.attr("LAB_DISK_CENTRE_BASE_LINK_M") = nb::make_tuple(kLabDiskCentreX, kLabDiskCentreY);
  m.attr("LAB_DISK_ENGAGE_Z_M") = kLabDiskEngageZ;
  m.attr("TOOL_CENTRE_OFFSET_M") = kToolCentreOffsetM;
  // How a trial ends (controller/trial/trial_outcome.h, trial_goal.h), for the SIL's verdict.
  nb::dict exit_codes;
  for (const ExitCodeRow& row : kExitCodeTable) exit_codes[row.name] = static_cast<int>(row.code);
  m.attr("EXIT_CODES") = exit_codes;  // common/exit_codes.h
  m.attr("OFF_EDGE_PA") = TrialThresholds{}.off_edge_pa;
  m.attr("GRASP_PA") = TrialThresholds{}.grasp_pa;
  m.attr("LOOP_SWEEP_DEG") = kLoopSweepDeg;
  m.def("write_lab_mat", &WriteLabMat, "recording"_a, "mat_dir"_a, "append_txt"_a, "args"_a,
        "The lab's DataLog_<stamp>_<append_txt>.mat from a logger recording (folder or one of "
        "its CSVs) and the script's arguments (Pref, beta, d_lat, ..., edgeFollowing_history "
        "rows of 14 numbers); returns its path.");
}
