#include "compare/twin_log.h"

#include <cmath>

#include "controller/contour_law.h"
#include "robotlog/mat_log.h"
#include "robotlog/topic_csv.h"

namespace ssc {
namespace {

// tool0's orientation in the twin's scenes: tool z down, tool x = world -y (the probe body of
// the replay tier and the gantry's tool).
constexpr double kTwinToolQuat[4] = {0, M_SQRT1_2, -M_SQRT1_2, 0};

// Within this of the disk's centre the cup is over it: the recording starts there, as the lab's
// starts over its engage point (the centre), before the cup moves out to the start.
constexpr double kOverCentreM = 0.5e-3;

}  // namespace

std::vector<TwinSample> TwinRunFromTrial(const TrialResult& trial, const TrialConfig& config) {
  std::vector<TwinSample> run;
  bool above = false;
  for (const TrialLogRow& r : trial.log) {
    above = above || std::hypot(r.tool_m[0] - config.target.goal.centre[0],
                                r.tool_m[1] - config.target.goal.centre[1]) < kOverCentreM;
    if (!above || (!run.empty() && r.t_s <= run.back().t_s)) continue;
    TwinSample s;
    s.t_s = r.t_s;
    s.tcp_m = {r.tool_m[0], r.tool_m[1], r.tool_m[2]};
    s.quat = {kTwinToolQuat[0], kTwinToolQuat[1], kTwinToolQuat[2], kTwinToolQuat[3]};
    s.p_pa = r.p_pa;
    s.ft = {0, 0, -r.ft_normal_n, 0, 0, 0};  // the transducer reads compression negative
    s.pwm_pct = 100;
    run.push_back(s);
  }
  return run;
}

LabControllerVectors LabVectorsFromPressures(const std::array<double, 4>& vacuum_pa,
                                             const ContourLawParams& law) {
  const ContourStep s = ComputeContourStep(vacuum_pa, law);
  LabControllerVectors v;
  v.r_p = {s.along_edge[1], s.along_edge[0]};
  // The script's corr_p: toward the object below P_ref, away above, zero at it.
  const double sign = s.cf > 0 ? 1.0 : (s.cf < 0 ? -1.0 : 0.0);
  v.corr_p = {sign * s.correction[1], sign * s.correction[0]};
  v.r_p_final = {s.direction[1], s.direction[0]};
  return v;
}

RobotLog LabLogFromTrial(const TrialResult& trial, const TrialConfig& config,
                         const SceneObject& scene_disk, const LabSetup& setup,
                         LogPerturbation perturbation) {
  ObjectPose disk;
  disk.known = true;
  disk.x_m = setup.disk_x_m;
  disk.y_m = setup.disk_y_m;
  disk.top_z_m = setup.disk_top_z_m;
  const Eigen::Isometry3d X_scene_log = SceneFromLog(setup.frame, disk, scene_disk);
  perturbation.X_scene_base = X_scene_log;
  const std::vector<TwinSample> run = TwinRunFromTrial(trial, config);
  RobotLog log = MakeRobotLog(run, perturbation);
  if (run.empty()) return log;

  LabRunArgs& a = log.args;
  const ContourLawParams& law = config.law;
  a.p_ref_pa = law.p_ref_pa;
  a.beta = law.beta;
  a.d_lat_m = law.step_mm * 1e-3;
  a.disk_radius_mm = config.target.disk_radius_m * 1e3;
  // The lab's start_offset runs from the disk's centre (its engage point) to the start.
  a.start_offset_m = std::hypot(config.target.start[0] - config.target.goal.centre[0],
                                config.target.start[1] - config.target.goal.centre[1]);
  a.p_lims_pa = {law.p_ref_pa, law.p_ref_pa};
  a.alpha_beta = {0.0, law.beta, 0.0, law.beta};
  a.success = trial.outcome == Outcome::kSuccess ? 1 : 0;
  a.fz_set_n = {config.approach_force_n - 0.05, config.approach_force_n + 0.05};
  const Eigen::Isometry3d X_log_scene = X_scene_log.inverse();
  for (const TrialLogRow& r : trial.log) {
    if (!r.iteration || r.phase != TrialPhase::kFollow) continue;
    HistoryRow h;
    h.t_s = r.t_s - run.front().t_s + setup.history_time_offset_s;
    const Eigen::Vector3d p = X_log_scene * Eigen::Vector3d(r.tool_m[0], r.tool_m[1], r.tool_m[2]);
    h.x_m = p.x();
    h.y_m = p.y();
    const LabControllerVectors v = LabVectorsFromPressures(r.p_pa, law);
    h.r_p = v.r_p;
    h.corr_p = v.corr_p;
    h.r_p_final = v.r_p_final;
    h.f_normal_n = -r.ft_normal_n;
    // What the host saw: the logged sensors' scale, vacuum negative (absolute - offset).
    for (int c = 0; c < 4; ++c) h.p_pa[c] = -perturbation.pressure_scale * r.p_pa[c];
    if (!a.history.empty() && h.t_s <= a.history.back().t_s) continue;
    a.history.push_back(h);
  }
  return log;
}

bool WriteLabRecordingFromTrial(const mjModel* scene, const TrialResult& trial,
                                const TrialConfig& config, const std::string& dir,
                                std::vector<std::string>* written, std::string* error) {
  const std::vector<SceneObject> objects = FindSceneObjects(scene);
  ObjectPose at;
  at.x_m = config.target.goal.centre[0];
  at.y_m = config.target.goal.centre[1];
  const SceneObject* disk = NearestSceneObject(objects, LogFrame::kUrBase, at);
  if (disk == nullptr) {
    *error = "the trial's scene has no object to place in the lab's frame";
    return false;
  }
  const RobotLog log = LabLogFromTrial(trial, config, *disk, LabSetup(), LogPerturbation());
  if (!WriteTopicCsvRecording(dir, log, LoggerVersion::kNewer, written, error)) return false;
  const std::string mat = dir + "/" + DiskBenchmarkMatName(RecordingStamp(log.t0_ns), log.args);
  if (!WriteRobotLogMat(mat, log, error)) return false;
  if (written != nullptr) written->push_back(mat);
  return true;
}

}  // namespace ssc
