// A Python callable or class as a trial's controller (ChoiceFrom), for the trial and study
// bindings.
#ifndef SSC_PYTHON_SRC_BINDING_CONTROLLER_H_
#define SSC_PYTHON_SRC_BINDING_CONTROLLER_H_

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
#include "python/src/binding_common.h"
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
#include "trial/robot_effects.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace ssc {

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
inline std::string PythonErrorText(const nb::python_error& e) {
  return "Python " + nb::cast<std::string>(nb::str(e.type().attr("__name__"))) + ": " +
         nb::cast<std::string>(nb::str(e.value()));
}

// A Python callable as a controller (controller/controller.h): called with a dict of the
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
inline ControllerChoice ChoiceFrom(const nb::object& controller, const std::string& params) {
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

}  // namespace ssc

#endif  // SSC_PYTHON_SRC_BINDING_CONTROLLER_H_
