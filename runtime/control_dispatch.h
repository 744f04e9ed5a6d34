// One MuJoCo control callback for the whole process, many controllers.
//
// mjcb_control is a single global function pointer, yet trials run in parallel threads and the
// viewer runs its own mjData. The dispatcher installs one callback that looks up the controller
// registered for the mjData being stepped and calls it; mjData without a controller get no
// control. Registration is thread-safe; lookups take a shared lock only.
#ifndef SSC_RUNTIME_CONTROL_DISPATCH_H_
#define SSC_RUNTIME_CONTROL_DISPATCH_H_

#include <mujoco/mujoco.h>

namespace ssc {

class ControlCallback {
 public:
  virtual ~ControlCallback() = default;
  // Called from mjcb_control for the mjData this callback is registered with.
  virtual void Control(const mjModel* m, mjData* d) = 0;
};

// Routes mjcb_control for `d` to `callback` until Unregister(d) (or the registration object
// goes away). Installs the dispatcher into mjcb_control on first use; refuses (returns false)
// if some other code already owns mjcb_control.
bool RegisterControl(const mjData* d, ControlCallback* callback);
void UnregisterControl(const mjData* d);

// RAII registration.
class ScopedControl {
 public:
  ScopedControl(const mjData* d, ControlCallback* callback)
      : d_(d), ok_(RegisterControl(d, callback)) {}
  ~ScopedControl() {
    if (ok_) UnregisterControl(d_);
  }
  ScopedControl(const ScopedControl&) = delete;
  ScopedControl& operator=(const ScopedControl&) = delete;
  bool ok() const { return ok_; }

 private:
  const mjData* d_;
  bool ok_;
};

}  // namespace ssc

#endif  // SSC_RUNTIME_CONTROL_DISPATCH_H_
