// Replay: the logged tool path driven through the twin, its pressures and F/T against the log.
#ifndef SSC_COMPARE_REPLAY_H_
#define SSC_COMPARE_REPLAY_H_

#include <mujoco/mujoco.h>

#include <array>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "robotlog/log_types.h"
#include "trial/robot_effects.h"

namespace ssc {

// Per-chamber and summary agreement of simulated and logged pressures.
struct ReplayComparison {
  std::array<double, 4> rms_pa{}, rms_log10{}, correlation{}, mean_ratio{};
  double pbar_rms_pa = 0, pbar_bias_pa = 0;
  // g from sim vs from the log, over the samples where both exceed P_n; NaN without any (a
  // replay off the object), never a 0 that reads as perfect agreement.
  double direction_rms_deg = std::numeric_limits<double>::quiet_NaN();
  double direction_median_deg = std::numeric_limits<double>::quiet_NaN();
  int direction_samples = 0;
  std::vector<double> t_s;
  std::vector<std::array<double, 4>> sim_pa, log_pa;
  std::vector<std::array<double, 3>> tcp_m;
  std::vector<double> sim_ft_normal_n;  // the twin's tared F/T compression (+ = pressed), N
};

// Drives the replay scene's mocap body (named "probe", holding tool0) along the logged tool
// centre point (scene frame) and orientation, stepping the simulation through the log's time
// span, and samples the plugin output and the F/T force at the log's time stamps.
// `lip` is the lip-drag reading effect the closed loop applies (trial/robot_effects.h):
// the replay drags the lip along the logged path and applies it too, so its pressures are what
// the host would read, as the log's are. LipShearParams{} (slip 0) compares the plugin alone.
// `progress` (optional) sees the fraction of the log replayed, every 1 %.
bool ReplayLog(const mjModel* m, const ProcessedLog& log, double tcp_offset_m,
               const LipShearParams& lip, ReplayComparison* out, std::string* error,
               const std::function<void(double)>& progress = nullptr);
// The same, taking the log's clock, positions and pressures into `out` instead of copying
// them (a long log is held once, not twice); `log` is left without them.
bool ReplayLogConsuming(const mjModel* m, ProcessedLog* log, double tcp_offset_m,
                        const LipShearParams& lip, ReplayComparison* out, std::string* error,
                        const std::function<void(double)>& progress = nullptr);

// Pearson correlation; NaN (undefined) when either side is constant or shorter than 2.
// CorrelationText shows it: "0.991" or "n/a (constant)".
double Correlation(const std::vector<double>& a, const std::vector<double>& b);
std::string CorrelationText(double r);

}  // namespace ssc

#endif  // SSC_COMPARE_REPLAY_H_
