// Options shared by `ssc trial` and `ssc sweep`: the controller and trial settings.
#ifndef SSC_APPS_SSC_TRIAL_OPTIONS_H_
#define SSC_APPS_SSC_TRIAL_OPTIONS_H_

#include <vector>

#include "apps/ssc/cli.h"
#include "runtime/trial.h"

namespace ssc {

// The options that configure a trial beyond P_ref, beta and the step.
std::vector<cli::Option> TrialSettingOptions();

// Reads those options into *config; false with p->error() on a malformed value.
bool ReadTrialSettings(cli::Parser* p, TrialConfig* config, std::string* error);

}  // namespace ssc

#endif  // SSC_APPS_SSC_TRIAL_OPTIONS_H_
