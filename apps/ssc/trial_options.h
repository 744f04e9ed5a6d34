// Options shared by the commands that run trials (trial, sweep, view): the controller and trial
// settings beyond P_ref, beta and the step, read straight into a TrialConfig.
#ifndef SSC_APPS_SSC_TRIAL_OPTIONS_H_
#define SSC_APPS_SSC_TRIAL_OPTIONS_H_

#include <string>

#include "apps/ssc/cli.h"
#include "geometry/dimensions.h"
#include "runtime/mujoco_model.h"
#include "runtime/trial.h"
#include "studies/sweep.h"

namespace ssc {

// The law's P_ref, beta and step (each command gives its own defaults in *law).
void AddLawOptions(cli::Command* cmd, ContourLawParams* law);

// The trial settings. Their values land in *config when cmd->Parse() succeeds (the disk target,
// the follow side and the dead band are set by a check that also runs config->Validate()).
// `settings` must outlive the parse.
struct TrialSettings {
  double start_offset_mm = kBenchmarkStartOffsetM * 1e3;
  std::string land_at = DiskLandingName(kDefaultDiskLanding);
  double sweep_deg = 0;
  std::string object_on = "left";
  bool no_dead_band = false;
  std::string effects = "default";
  std::string controller = "published", controller_params;
};
void AddTrialSettingOptions(cli::Command* cmd, TrialConfig* config, TrialSettings* settings);
// --effects: the text goes to *text and is parsed onto *effects by a check registered here (so
// before any check registered after it). `what` leads the help line.
void AddEffectsOption(cli::Command* cmd, const std::string& what, std::string* text,
                      RobotEffectsParams* effects);

// --threads: worker threads, a whole number in [1, 256] (the one range every command takes).
void AddThreadsOption(cli::Command* cmd, long* threads);

// --controller NAME and --controller-param key=value,...: parsed onto *choice by a check
// registered here (unknown names and keys, values out of range are errors naming the key and
// its range). `name` and `params` hold the texts and must outlive the parse.
void AddControllerOptions(cli::Command* cmd, std::string* name, std::string* params,
                          ControllerChoice* choice);

// Loads the scene at `scene_path` and checks that `config` can run on it; on failure prints
// "ssc COMMAND: ..." to stderr and returns null.
ModelPtr LoadTrialScene(const cli::Command& cmd, const std::string& scene_path,
                        const TrialConfig& config);

// One summary line on the shared approach (runtime/approach_cache.h) of this rank's trials.
void PrintApproachSharing(bool on, const SweepSummary& summary);

}  // namespace ssc

#endif  // SSC_APPS_SSC_TRIAL_OPTIONS_H_
