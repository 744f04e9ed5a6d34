// The options that define a trial's results, as a resumable study records them beside its rows
// (studies/sweep_io.h: SweepManifest): the scene, its compiled model's hash and the trial
// settings a row does not hold itself. Shared by ssc sweep, ssc stability and ssc tune.
#ifndef SSC_STUDIES_TRIAL_MANIFEST_H_
#define SSC_STUDIES_TRIAL_MANIFEST_H_

#include <mujoco/mujoco.h>

#include <string>

#include "runtime/trial.h"
#include "studies/sweep_io.h"

namespace ssc {

// Without the law's P_ref, beta and step and the seed (a sweep's rows hold them).
SweepManifest TrialManifest(const mjModel* m, const std::string& scene, const TrialConfig& c);

}  // namespace ssc

#endif  // SSC_STUDIES_TRIAL_MANIFEST_H_
