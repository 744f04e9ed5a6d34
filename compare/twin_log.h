// Robot logs made from twin trials: the one place a trial becomes a robot log (in the lab's
// frames and formats), for `ssc trial --robot-log`, the charts and the tests' generator.
#ifndef SSC_COMPARE_TWIN_LOG_H_
#define SSC_COMPARE_TWIN_LOG_H_

#include <string>
#include <vector>

#include "compare/frames.h"
#include "robotlog/synthetic_log.h"
#include "runtime/trial.h"

namespace ssc {

// The trial's log rows as samples (TCP, tool0 orientation, gauge vacuum, raw F/T with
// compression negative along z, PWM 100 %), from the first row above the landing point (where
// the lab's recording starts) on; rows at a repeated time are dropped.
std::vector<TwinSample> TwinRunFromTrial(const TrialResult& trial, const TrialConfig& config);

// Where the twin's disk lies in the lab's log frame (default: the lab's disk benchmark).
struct LabSetup {
  LogFrame frame = LogFrame::kBaseLink;
  double disk_x_m = kLabDiskCentreX, disk_y_m = kLabDiskCentreY;
  double disk_top_z_m = 0.005;       // the disk's top in the log frame
  double history_time_offset_s = 0;  // edgeFollowing_history time = trial time - first row + this
};

// A lab recording of a twin trial in `scene` (its disk object): the streams (MakeRobotLog with
// `perturbation`, whose X_scene_base is set here from `setup`) and the disk benchmark script's
// arguments, with edgeFollowing_history from the trial's control iterations as the script
// stores them (TCP x, y in the log frame; r_p, corr_p, r_p_final in [y, x] order; F_normal
// negative for compression; P = -vacuum x the perturbation's pressure scale, as the host saw it).
RobotLog LabLogFromTrial(const TrialResult& trial, const TrialConfig& config,
                         const SceneObject& scene_disk, const LabSetup& setup,
                         LogPerturbation perturbation);

// Writes a twin trial on `scene` as a lab recording into `dir`: the newer logger's per-topic CSVs
// and the DataLog_<stamp>_..._deleteMe.mat (default LabSetup, no perturbation). `written` gets
// the paths.
bool WriteLabRecordingFromTrial(const mjModel* scene, const TrialResult& trial,
                                const TrialConfig& config, const std::string& dir,
                                std::vector<std::string>* written, std::string* error);

// The twin controller's output for one pressure sample, in the lab script's terms.
struct LabControllerVectors {
  std::array<double, 2> r_p{}, corr_p{}, r_p_final{};  // [y, x] of tool-frame unit vectors
};
LabControllerVectors LabVectorsFromPressures(const std::array<double, 4>& vacuum_pa,
                                             const ContourLawParams& law);

}  // namespace ssc

#endif  // SSC_COMPARE_TWIN_LOG_H_
