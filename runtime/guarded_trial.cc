#include "runtime/guarded_trial.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace ssc {
namespace {

// MuJoCo calls mju_user_error on fatal errors (the default exits the process); a study turns
// them into an exception caught per trial so the study goes on.
thread_local bool t_in_trial = false;
void ThrowingError(const char* msg) {
  if (t_in_trial) throw std::runtime_error(msg);
  std::fprintf(stderr, "MuJoCo error: %s\n", msg);
  std::abort();
}

}  // namespace

ScopedTrialErrorGuard::ScopedTrialErrorGuard() : previous_(mju_user_error) {
  mju_user_error = ThrowingError;
}
ScopedTrialErrorGuard::~ScopedTrialErrorGuard() { mju_user_error = previous_; }

TrialResult RunGuardedTrial(const mjModel* m, const TrialConfig& config, ApproachCache* cache,
                            std::string* error, bool keep_log) {
  TrialResult result;
  std::string trial_error;
  t_in_trial = true;
  try {
    result = keep_log ? RunTrial(m, config, true, &trial_error)
                      : RunTrialShared(m, config, cache, &trial_error);
  } catch (const std::exception& e) {
    result = TrialResult();
    result.outcome = Outcome::kUnstable;
    result.detail = std::string("MuJoCo error: ") + e.what();
  }
  t_in_trial = false;
  if (error != nullptr) *error = trial_error;
  return result;
}

}  // namespace ssc
