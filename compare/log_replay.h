// Sim against robot logs: replay a logged tool path in the twin and compare the pressures, and
// make robot-format logs from twin runs (for tests and for users without a robot).
#ifndef SSC_COMPARE_LOG_REPLAY_H_
#define SSC_COMPARE_LOG_REPLAY_H_

#include <array>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "runtime/trial.h"
#include "robotlog/robot_log.h"

namespace ssc {

// Per-chamber and summary agreement of simulated and logged pressures.
struct ReplayComparison {
  std::array<double, 4> rms_pa{}, rms_log10{}, correlation{}, mean_ratio{};
  double pbar_rms_pa = 0, pbar_bias_pa = 0;
  double direction_rms_deg = 0, direction_median_deg = 0;  // g from sim vs from the log
  int direction_samples = 0;
  std::vector<double> t_s;
  std::vector<std::array<double, 4>> sim_pa, log_pa;
  std::vector<std::array<double, 3>> tcp_m;
};

// Loads a log: a directory of per-topic CSVs, a .mat file, or a plain CSV.
bool LoadAnyLog(const std::string& path, const ProcessOptions& options, ProcessedLog* log,
                LoadError* error);

// Drives the replay scene's mocap body (named "probe", holding tool0) along the logged tool
// centre point and orientation, stepping the simulation through the log's time span, and
// samples the plugin output at the log's time stamps.
bool ReplayLog(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
               ReplayComparison* out, std::string* error);

// A robot-format log from a twin trial (keep_log): absolute pressures at the trial's log rows
// (ambient `ambient_pa` minus gauge x `pressure_scale` + `pressure_offset_pa`), the tool0 pose
// in the base frame (= scene frame), F/T normal force.
// `noise_pa` adds Gaussian noise (seeded, deterministic) to every logged pressure.
RobotLog RobotLogFromTrial(const TrialResult& trial, double tcp_offset_m, double pressure_scale,
                           double pressure_offset_pa, double ambient_pa = 101325.0,
                           double noise_pa = 0.0, unsigned seed = 1);

// Closed loop: the twin's controller with given parameters from the log's start pose (the
// first sample where the logged pressures show an edge: mean and differential above P_n), on a
// disk scene, against the logged path from that sample on.
struct ClosedLoopComparison {
  bool ran = false;
  double start_t_s = 0;
  Point2 start{};
  DiskTrialMetrics log, twin;
  std::string twin_outcome;
  double path_distance_mean_mm = 0, path_distance_max_mm = 0;  // twin path to the logged path
};
bool CompareClosedLoop(const mjModel* disk_scene, const ProcessedLog& log,
                       const TrialConfig& config, ClosedLoopComparison* out, std::string* error);

// Report files: Markdown and JSON.
bool WriteComparisonReport(const std::string& dir, const std::string& log_name,
                           const ReplayComparison& c, const ClosedLoopComparison* closed,
                           std::string* error);

}  // namespace ssc

#endif  // SSC_COMPARE_LOG_REPLAY_H_
