// What every topic of ssc_twin._core shares: NumPy and dict conversions, argument checks
// (seeds, timeouts, scenes, effects) and the Python exceptions they raise. Inline: one copy
// per process however many topic files include it.
#ifndef SSC_PYTHON_SRC_BINDING_COMMON_H_
#define SSC_PYTHON_SRC_BINDING_COMMON_H_

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
#include "controller/contour_law.h"
#include "controller/controller_registry.h"
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
#include "runtime/tool_force.h"
#include "runtime/tool_servo.h"
#include "runtime/trial.h"
#include "studies/edge_probe.h"
#include "studies/object_study.h"
#include "studies/object_trials.h"
#include "studies/statistics/intervals.h"
#include "studies/sweep.h"
#include "studies/tool_variants.h"
#include "studies/validation.h"
#include "trial/robot_effects.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace ssc {

// A NumPy array that owns a copy of `values` laid out as `shape`.
template <typename T>
inline nb::object ToNumpy(std::vector<T> values, std::vector<size_t> shape) {
  auto* heap = new std::vector<T>(std::move(values));
  nb::capsule owner(heap, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::ndarray<nb::numpy, T>(heap->data(), shape.size(), shape.data(), owner).cast();
}
inline nb::object ToNumpy(std::vector<double> values, std::vector<size_t> shape) {
  return ToNumpy<double>(std::move(values), std::move(shape));
}

// One value per chamber as a NumPy vector.
inline nb::object PerChamber(const std::array<double, 4>& a) {
  return ToNumpy({a[0], a[1], a[2], a[3]}, {4});
}

template <size_t N>
inline nb::object Rows(const std::vector<std::array<double, N>>& rows) {
  std::vector<double> flat;
  flat.reserve(rows.size() * N);
  for (const auto& r : rows) flat.insert(flat.end(), r.begin(), r.end());
  return ToNumpy(std::move(flat), {rows.size(), N});
}

// A NumPy bool array (std::vector<bool> holds bits, not bools).
inline nb::object Flags(const std::vector<bool>& v) {
  bool* heap = new bool[v.size()];
  std::copy(v.begin(), v.end(), heap);
  nb::capsule owner(heap, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
  const size_t shape[1] = {v.size()};
  return nb::ndarray<nb::numpy, bool>(heap, 1, shape, owner).cast();
}

template <typename T>
inline nb::object Column(const std::vector<T>& v) {
  return ToNumpy<T>(v, {v.size()});
}

// {"key", nb::cast(value)}, ... -> a dict.
inline nb::dict Dict(std::initializer_list<std::pair<const char*, nb::object>> items) {
  nb::dict d;
  for (const auto& [key, value] : items) d[key] = value;
  return d;
}

[[noreturn]] inline void Fail(const std::string& what) { throw std::runtime_error(what); }
// A bad argument: ValueError in Python. The message comes from the same C++ check the command
// line uses (one validation home per input).
[[noreturn]] inline void Invalid(const std::string& what) { throw std::invalid_argument(what); }
// A study stopped by SIGINT/SIGTERM (the job runner takes the signal while it runs and keeps
// the finished results): KeyboardInterrupt, as Python's own Ctrl-C, saying what was kept.
[[noreturn]] inline void Interrupted(const std::string& what) {
  PyErr_SetString(PyExc_KeyboardInterrupt, what.c_str());
  throw nb::python_error();
}

// Ctrl-C (KeyboardInterrupt) or SystemExit raised inside a Python controller: kept here while
// the trial it stopped unwinds, and raised again when the binding returns to Python (never
// swallowed into a controller fault). Touched only with the GIL held.
inline std::unique_ptr<nb::python_error>& PendingInterrupt() {
  static std::unique_ptr<nb::python_error> pending;
  return pending;
}

// Raises the pending interrupt, or one Python's signal handler has noted since the GIL was
// released (a Ctrl-C during the physics).
inline void RaisePendingInterrupt() {
  if (std::unique_ptr<nb::python_error> e = std::move(PendingInterrupt())) {
    e->restore();
    throw nb::python_error();
  }
  if (PyErr_CheckSignals() != 0) throw nb::python_error();
}

// Names as the bindings take them, like sweep's lists: a list (or tuple) of strings, or one
// string of comma-separated names as the command line's --objects takes them.
inline std::string NameListArg(const nb::object& names, const char* what) {
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
inline void SetTimeout(double timeout_s, TrialConfig* config) {
  if (timeout_s != 0) config->timeout_s = timeout_s;
  if (const std::string e = config->Validate(); !e.empty()) Invalid(e);
}

inline ModelPtr Load(const std::string& scene) {
  std::string error;
  ModelPtr m = LoadModel(ResolveScenePath(scene), &error);
  if (!m) Fail(error);
  return m;
}

// A seed from Python: a whole number in kSeedRange, an int (or anything with __index__) or a
// float holding one, as every ssc --seed takes it. Anything else is a ValueError naming the
// argument and the range: a seed above 2^53 - 1 would lose its last bits on the way through
// doubles, one above 2^64 would wrap, and a fraction would be cut.
inline std::uint64_t SeedArg(const nb::handle& value) {
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
inline const std::filesystem::path& ObjectSceneDir() {
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
inline TrialConfig MakeConfig(double pref, double beta, double step_mm, std::uint64_t seed,
                              const std::string& object, const std::string& effects,
                              std::string* scene) {
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
    *scene = (dir / ObjectSceneFile(spec, kind, config.law.step_mm)).string();
    config = ObjectTrialConfig(spec, config);
  }
  if (std::string e; !ParseRobotEffects(effects, &config.effects, &e)) Invalid(e);
  if (const std::string e = config.Validate(); !e.empty()) Invalid(e);
  return config;
}

inline nb::dict MetricsDict(const TrialResult& r) {
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

inline nb::dict LogDict(const std::vector<TrialLogRow>& log) {
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

inline nb::dict ResultDict(const std::string& scene, const TrialConfig& c, const TrialResult& r) {
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

inline nb::dict StepDict(const ContourStep& s) {
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

inline ContourLawParams Law(double pref, double beta, double step_mm) {
  ContourLawParams law;
  law.p_ref_pa = pref;
  law.beta = beta;
  law.step_mm = step_mm;
  if (const std::string e = law.Validate(); !e.empty()) Invalid(e);
  return law;
}

inline nb::dict LawDict(const ContourLawParams& law) {
  return Dict({{"pref_pa", nb::cast(law.p_ref_pa)},
               {"beta", nb::cast(law.beta)},
               {"step_mm", nb::cast(law.step_mm)},
               {"p_noise_pa", nb::cast(law.p_noise_pa)},
               {"p_grasp_pa", nb::cast(law.p_grasp_pa)},
               {"object_on_left", nb::cast(law.side == FollowSide::kObjectOnLeft)},
               {"dead_band", nb::cast(law.dead_band)}});
}

}  // namespace ssc

#endif  // SSC_PYTHON_SRC_BINDING_COMMON_H_
