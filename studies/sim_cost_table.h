// The simulator's cost table: one path from a twin trial replayed with cheaper and
// dearer settings (rays per chamber, sensor rate, time step, integrator, lip segments), each
// compared with the finest replay as reference (16 rays per chamber, 32 lip segments, 0.25 ms,
// RK4); and the full UR-10 arm against the light gantry on the same trial. Cost is wall time
// per simulated second; error is the RMS over chambers and samples of log10 pressure (and Pa).
// Tool variants are compiled in memory (studies/tool_variants.h).
#ifndef SSC_STUDIES_SIM_COST_TABLE_H_
#define SSC_STUDIES_SIM_COST_TABLE_H_

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "runtime/trial.h"
#include "studies/tool_variants.h"

namespace ssc {

struct SimCostSetting {
  std::string name;
  ToolVariant tool;  // plugin config keys and lip segments
  double timestep_s = 0.002;
  int integrator = mjINT_IMPLICITFAST;
  bool reference = false, is_default = false;
};

struct SimCostRow {
  std::string setting;
  double timestep_ms = 0;
  double wall_per_sim_s = 0;
  double rms_log10 = 0;  // against the reference replay (or, for the gantry, the arm run)
  double rms_pa = 0;
  bool is_default = false;
};

// The settings of the published chart; the first is the reference.
std::vector<SimCostSetting> SimCostSettings();

// RMS over every chamber and sample of log10(max(1, p)) differences, and of Pa differences, of
// two equally long pressure series ({0, 0} when empty).
std::array<double, 2> PressureRmsError(const std::vector<std::array<double, 4>>& a,
                                       const std::vector<std::array<double, 4>>& b);

// Runs the table: `trial` (a logged twin trial on `gantry_scene`'s model, e.g. dL 5 mm) gives
// the replayed path; replays run in `replay_scene` (disk_replay.xml); the arm row runs the same
// trial config in `arm_scene`. `row_done` (optional) sees each row as it is made. False +
// *error on a load or replay failure.
bool RunSimCostTable(const TrialConfig& trial_config, const TrialResult& trial,
                     const std::string& replay_scene, const std::string& arm_scene,
                     const std::function<void(const SimCostRow&)>& row_done,
                     std::vector<SimCostRow>* rows, std::string* error);

// The table as CSV: setting, timestep_ms, wall_per_sim_s, rms_log10_vs_reference,
// rms_pa_vs_reference, is_default.
std::string SimCostCsv(const std::vector<SimCostRow>& rows);

}  // namespace ssc

#endif  // SSC_STUDIES_SIM_COST_TABLE_H_
