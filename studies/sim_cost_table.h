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
#include "studies/object_trials.h"
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

// The logged twin trial the table replays (e.g. dL 5 mm): its scene's name (for the row that
// sets it against the arm) and time step.
struct SimCostTrial {
  std::string scene;
  double timestep_s = 0;
  TrialConfig config;
  TrialResult result;
};

// Runs the table: `trial` gives the replayed path; replays run in `replay_scene` (the rig's
// replay tier); the arm row runs the same trial config in `arm_scene`. `row_done` (optional) sees
// each row as it is made. False + *error on a load or replay failure.
bool RunSimCostTable(const SimCostTrial& trial, const std::string& replay_scene,
                     const std::string& arm_scene,
                     const std::function<void(const SimCostRow&)>& row_done,
                     std::vector<SimCostRow>* rows, std::string* error);

// The table as CSV: setting, timestep_ms, wall_per_sim_s, rms_log10_vs_reference,
// rms_pa_vs_reference, is_default.
std::string SimCostCsv(const std::vector<SimCostRow>& rows);

// The fidelity tiers side by side (ssc charts --tiers): per tier, its cost per step, the
// straight-edge static curve, the Fig. 6 targets on the disk and outcomes on a few test objects.
// The rig's disk tiers (runtime/rig.h) with their probe scenes.
struct SimTier {
  std::string name;             // picked by this name
  std::string what;             // one line for the table
  std::string disk_scene;       // the disk benchmark (name under scenes/)
  std::string probe_scene;      // the straight-edge probe (mocap cup; name under scenes/)
  double probe_press_mm = 1.0;  // the lip's press in the probe: what the tier's approach gives
  bool has_object_scenes = false;
  ObjectSceneKind object_kind = ObjectSceneKind::kGantry;
};
// arm, gantry, light, fast, flex.
std::vector<SimTier> SimTiers();
// Tiers by comma-separated names; false + *error naming an unknown or repeated one.
bool SimTiersByNames(const std::string& names, std::vector<SimTier>* tiers, std::string* error);

struct SimTierSpec {
  std::vector<SimTier> tiers;
  int seeds = 2;                    // disk trials per beta (seeds seed, seed + 1, ...)
  std::uint64_t seed = 7;           // unseen by the fits
  std::vector<ObjectSpec> objects;  // run with seed `seed`, dL 0.5 mm (none: skipped)
  std::string object_dir;           // where the objects' scenes are written
  int threads = 1;
};

// The published targets the table is read against (docs/pneumatics.md, docs/fidelity.md).
inline constexpr double kStaticOffsetsMm[3] = {0.7, 2.5, 3.2};  // P̄ 40, 100, 200 Pa there
inline constexpr double kFig6Beta[3] = {1.5, 2.5, 3.5};         // P_ref 100 Pa, dL 5 mm

struct SimTierRow {
  std::string tier;
  double us_per_step = 0;                  // disk trials: wall time per physics step, this run
  double approach_compression_mm = 0;      // disk trials: lip plane below the top after approach
  std::array<double, 3> static_pbar_pa{};  // probe at kStaticOffsetsMm inside the edge, pressed
                                           // probe_press_mm
  double static_diff_pa = 0;               // |(dPx, dPy)| at 2.5 mm inside
  std::array<double, 3> sigma_r_mm{}, s_c{}, dr_mm{};  // per kFig6Beta, mean over successes
  // Their sample sd over the successful seeds (0 with fewer than two); the standard error of a
  // mean is sd / sqrt(successes).
  std::array<double, 3> sigma_r_sd_mm{}, s_c_sd{}, dr_sd_mm{};
  std::array<int, 3> successes{}, trials{};
  std::string objects;  // "name outcome (end); ..." ("" when skipped or not available)
};

// Runs every tier; `row_done` (optional) sees each finished row. False + *error on a load
// failure.
bool RunSimTierTable(const SimTierSpec& spec,
                     const std::function<void(const SimTierRow&)>& row_done,
                     std::vector<SimTierRow>* rows, std::string* error);
std::string SimTierCsv(const std::vector<SimTierRow>& rows);

}  // namespace ssc

#endif  // SSC_STUDIES_SIM_COST_TABLE_H_
