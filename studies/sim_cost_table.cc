#include "studies/sim_cost_table.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "compare/replay.h"
#include "compare/twin_log.h"
#include "geometry/dimensions.h"

namespace ssc {

std::vector<SimCostSetting> SimCostSettings() {
  const PluginConfig quiet = {{"noise_pa", "0"}};  // compare the physics, not the noise
  auto with = [&](const char* key, const std::string& value) {
    PluginConfig c = quiet;
    c[key] = value;
    return c;
  };
  std::vector<SimCostSetting> s = {{"reference: 16 rays, 32 lip segments, 0.25 ms, RK4",
                                    {with("rays_per_chamber", "16"), 32},
                                    0.00025,
                                    mjINT_RK4,
                                    true,
                                    false},
                                   {"default: 4 rays, 160 Hz, 2 ms, implicitfast",
                                    {quiet, 0},
                                    0.002,
                                    mjINT_IMPLICITFAST,
                                    false,
                                    true}};
  for (int rays : {1, 2, 8, 16}) {
    s.push_back(
        {std::to_string(rays) + " rays", {with("rays_per_chamber", std::to_string(rays)), 0}});
  }
  for (const char* hz : {"40", "80", "320"}) {
    s.push_back({std::string(hz) + " Hz sensor", {with("sample_rate_hz", hz), 0}});
  }
  for (double dt : {0.0005, 0.001, 0.004, 0.008}) {
    char name[32];
    std::snprintf(name, sizeof(name), "%.1f ms step", dt * 1e3);
    s.push_back({name, {quiet, 0}, dt});
  }
  for (int lips : {8, 32, 64}) s.push_back({std::to_string(lips) + " lip segments", {quiet, lips}});
  s.push_back({"Euler", {quiet, 0}, 0.002, mjINT_EULER});
  s.push_back({"RK4", {quiet, 0}, 0.002, mjINT_RK4});
  return s;
}

std::array<double, 2> PressureRmsError(const std::vector<std::array<double, 4>>& a,
                                       const std::vector<std::array<double, 4>>& b) {
  double e_log = 0, e_pa = 0;
  const size_t n = std::min(a.size(), b.size());
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 4; ++k) {
      e_log += std::pow(std::log10(std::max(1.0, a[i][k])) - std::log10(std::max(1.0, b[i][k])), 2);
      e_pa += std::pow(a[i][k] - b[i][k], 2);
    }
  }
  if (n == 0) return {0, 0};
  const double count = 4.0 * static_cast<double>(n);
  return {std::sqrt(e_log / count), std::sqrt(e_pa / count)};
}

bool RunSimCostTable(const TrialConfig& trial_config, const TrialResult& trial,
                     const std::string& replay_scene, const std::string& arm_scene,
                     const std::function<void(const SimCostRow&)>& row_done,
                     std::vector<SimCostRow>* rows, std::string* error) {
  auto add = [&](const SimCostRow& row) {
    rows->push_back(row);
    if (row_done) row_done(row);
  };
  ProcessedLog path;
  LoadError load_error;
  ProcessOptions po;
  po.moving_average = 1;
  LogPerturbation as_recorded;
  as_recorded.in_air_s = 0;  // the trial's approach starts in air
  if (!ProcessRobotLog(MakeRobotLog(TwinRunFromTrial(trial, trial_config), as_recorded), po, &path,
                       &load_error)) {
    *error = load_error.ToString();
    return false;
  }
  const auto variants = ToolModelVariants::Read(replay_scene, error);
  if (!variants) return false;
  std::vector<std::array<double, 4>> reference;
  for (const SimCostSetting& s : SimCostSettings()) {
    ModelPtr m = variants->Compile(s.tool, error);
    if (!m) return false;
    m->opt.timestep = s.timestep_s;
    m->opt.integrator = s.integrator;
    ReplayComparison r;
    const auto t0 = std::chrono::steady_clock::now();
    // The plugin alone: the variants differ in the model, not in the host's reading.
    if (!ReplayLog(m.get(), path, kToolCentreOffsetM, LipShearParams{}, &r, error)) return false;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s.reference) reference = r.sim_pa;
    const std::array<double, 2> e = PressureRmsError(r.sim_pa, reference);
    add({s.name, s.timestep_s * 1e3, wall / (path.t_s.back() - path.t_s.front()), e[0], e[1],
         s.is_default});
  }
  // Full arm against the light gantry: the same trial on both; the arm run is the reference
  // (pressures compared at equal times).
  ModelPtr arm = LoadModel(arm_scene, error);
  if (!arm) return false;
  const TrialResult a = RunTrial(arm.get(), trial_config, true, error);
  std::map<long, std::array<double, 4>> arm_rows;
  for (const TrialLogRow& r : a.log) arm_rows[std::lround(r.t_s * 1e4)] = r.p_pa;
  std::vector<std::array<double, 4>> arm_p, gantry_p;
  for (const TrialLogRow& r : trial.log) {
    const auto it = arm_rows.find(std::lround(r.t_s * 1e4));
    if (it == arm_rows.end()) continue;
    arm_p.push_back(it->second);
    gantry_p.push_back(r.p_pa);
  }
  const std::array<double, 2> e = PressureRmsError(gantry_p, arm_p);
  add({"arm scene (UR-10)", 2, a.wall_time_s / a.sim_time_s, 0.0001, 0, false});
  add({"gantry scene vs arm", 2, trial.wall_time_s / trial.sim_time_s, e[0], 0, false});
  return true;
}

std::string SimCostCsv(const std::vector<SimCostRow>& rows) {
  std::ostringstream os;
  os << "setting,timestep_ms,wall_per_sim_s,rms_log10_vs_reference,rms_pa_vs_reference,"
        "is_default\n";
  for (const SimCostRow& r : rows) {
    os << '"' << r.setting << "\"," << r.timestep_ms << ',' << r.wall_per_sim_s << ','
       << r.rms_log10 << ',' << r.rms_pa << ',' << (r.is_default ? 1 : 0) << '\n';
  }
  return os.str();
}

}  // namespace ssc
