// The trial every study runs: MuJoCo's fatal errors inside it become an 'unstable' result while
// a ScopedTrialErrorGuard is alive, instead of ending the process and the study with it.
#ifndef SSC_RUNTIME_GUARDED_TRIAL_H_
#define SSC_RUNTIME_GUARDED_TRIAL_H_

#include <mujoco/mujoco.h>

#include <string>

#include "runtime/approach_cache.h"
#include "runtime/trial.h"

namespace ssc {

// While alive, MuJoCo's fatal errors inside RunGuardedTrial become 'unstable' results instead of
// ending the process (mju_user_error is process-wide: one guard at a time, around a whole run).
class ScopedTrialErrorGuard {
 public:
  ScopedTrialErrorGuard();
  ~ScopedTrialErrorGuard();
  ScopedTrialErrorGuard(const ScopedTrialErrorGuard&) = delete;
  ScopedTrialErrorGuard& operator=(const ScopedTrialErrorGuard&) = delete;

 private:
  void (*previous_)(const char*);
};

// One trial: through `cache` (runtime/approach_cache.h) when given and no log is kept; with
// `keep_log` its log (never through the cache). `error` (optional) receives why a trial could not
// start (the model or config refused; the result then is not run).
TrialResult RunGuardedTrial(const mjModel* m, const TrialConfig& config,
                            ApproachCache* cache = nullptr, std::string* error = nullptr,
                            bool keep_log = false);

}  // namespace ssc

#endif  // SSC_RUNTIME_GUARDED_TRIAL_H_
