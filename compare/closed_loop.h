// The controller side of a comparison: the twin's controller against the lab's, iteration by
// iteration at the logged poses (edgeFollowing_history), and in closed loop from the logged
// start with the parameters the file records.
#ifndef SSC_COMPARE_CLOSED_LOOP_H_
#define SSC_COMPARE_CLOSED_LOOP_H_

#include <mujoco/mujoco.h>

#include <array>
#include <string>
#include <vector>

#include "compare/frames.h"
#include "compare/replay.h"
#include "compare/twin_log.h"
#include "runtime/trial.h"
#include "trial/trial_metrics.h"

namespace ssc {

// How far below a flat top the twin's lip plane settles when pressed to `force_n` (the
// approach phase of a trial on `disk_scene`), m.
bool TwinContactDepth(const mjModel* disk_scene, double force_n, double* depth_m,
                      std::string* error);

// The disk benchmark's controller parameters from the file's arguments over `defaults`
// (P_ref, beta, dL = d_lat in metres, the approach force = the middle of Fz_set, the disk
// radius); `what` lists which came from the file.
TrialConfig ConfigFromArgs(const LabRunArgs& args, const TrialConfig& defaults, std::string* what);

// One controller iteration: the lab's values and the twin's at the same pose and time.
struct HistoryPair {
  double t_log_s = 0;  // on the log's clock (history time + the found offset)
  HistoryRow lab;
  LabControllerVectors twin;
  std::array<double, 4> twin_vacuum_pa{};
  double twin_f_normal_n = 0;                             // lab sign: negative = compression
  double r_p_deg = 0, corr_p_deg = 0, r_p_final_deg = 0;  // angle twin - lab; NaN if undefined
};

struct HistoryComparison {
  bool ran = false;
  int iterations = 0;
  double time_offset_s = 0;         // log time = history time + this (found by matching x, y)
  double match_rms_mm = 0;          // history x, y against the logged TCP at the matched times
  bool history_in_ur_base = false;  // x, y matched only after turning them 180 deg (RTDE frame)
  double r_p_median_deg = 0, r_p_rms_deg = 0;
  double corr_p_median_deg = 0;
  int corr_p_samples = 0;
  double r_p_final_median_deg = 0;
  std::array<double, 4> p_rms_pa{}, p_correlation{}, p_mean_ratio{};  // twin vs lab vacuum
  double f_normal_rms_n = 0, f_normal_bias_n = 0;                     // twin - lab
  std::vector<HistoryPair> rows;
};

// `base_log`: the processed log in its own base frame (times as `replay`'s); `replay`: the
// twin's replay of it. Errors when the history's x, y match the logged path nowhere.
bool CompareHistory(const LabRunArgs& args, const ProcessedLog& base_log,
                    const ReplayComparison& replay, const ContourLawParams& law,
                    HistoryComparison* out, std::string* error);

// Closed loop: the twin's controller (config) from the logged start on the scene's disk, its
// trajectory against the logged one from that time on.
struct ClosedLoopComparison {
  bool ran = false;
  double start_t_s = 0;
  Point2 start{};
  DiskTrialMetrics log, twin;
  std::string twin_outcome;
  std::string parameters;  // where P_ref, beta, dL, force came from
  std::string controller;  // the controller that ran, with its values ("fast:lead=0.5,...")
  double path_distance_mean_mm = 0, path_distance_max_mm = 0;  // twin path to the logged path
};
// `start_t_s` < 0: the start is the first sample whose pressures show an edge (mean and
// differential above P_n). `scene_log` in the scene frame.
bool CompareClosedLoop(const mjModel* disk_scene, const ProcessedLog& scene_log,
                       const SceneObject& disk, double start_t_s, const TrialConfig& config,
                       ClosedLoopComparison* out, std::string* error);

}  // namespace ssc

#endif  // SSC_COMPARE_CLOSED_LOOP_H_
