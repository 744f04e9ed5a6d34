#include "studies/sim_cost_table.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <thread>

#include "compare/replay.h"
#include "compare/twin_log.h"
#include "geometry/dimensions.h"
#include "runtime/guarded_trial.h"
#include "runtime/mujoco_model.h"
#include "studies/edge_probe.h"

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

bool RunSimCostTable(const SimCostTrial& logged, const std::string& replay_scene,
                     const std::string& arm_scene,
                     const std::function<void(const SimCostRow&)>& row_done,
                     std::vector<SimCostRow>* rows, std::string* error) {
  const TrialConfig& trial_config = logged.config;
  const TrialResult& trial = logged.result;
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
  // Full arm against the trial's scene: the same trial on both; the arm run is the reference
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
  add({"arm scene (UR-10)", arm->opt.timestep * 1e3, a.wall_time_s / a.sim_time_s, 0.0001, 0,
       false});
  add({logged.scene + " vs arm", logged.timestep_s * 1e3, trial.wall_time_s / trial.sim_time_s,
       e[0], 0, false});
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

std::vector<SimTier> SimTiers() {
  std::vector<SimTier> tiers;
  for (const RigTier& t : RigTiers()) {
    if (*t.probe == '\0') continue;  // the disk tiers: those with a straight-edge probe
    tiers.push_back({t.name, t.what, t.scene, RigTierNamed(t.probe)->scene, t.probe_press_mm,
                     t.object_template, ObjectSceneKindOfTier(t)});
  }
  return tiers;
}

bool SimTiersByNames(const std::string& names, std::vector<SimTier>* tiers, std::string* error) {
  const std::vector<SimTier> all = SimTiers();
  std::string valid;
  for (const SimTier& t : all) valid += (valid.empty() ? "" : ", ") + t.name;
  std::stringstream in(names);
  std::string name;
  tiers->clear();
  while (std::getline(in, name, ',')) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const SimTier& t) { return t.name == name; });
    if (it == all.end()) {
      *error = "unknown tier '" + name + "' (valid: " + valid + ")";
      return false;
    }
    for (const SimTier& t : *tiers) {
      if (t.name == name) {
        *error = "tier '" + name + "' is listed twice";
        return false;
      }
    }
    tiers->push_back(*it);
  }
  if (tiers->empty() || names.back() == ',') {
    *error = "no tier in '" + names + "' (valid: " + valid + ")";
    return false;
  }
  return true;
}

namespace {

// Runs fn(0..count-1) on `threads` threads.
void ParallelFor(int count, int threads, const std::function<void(int)>& fn) {
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, std::min(threads, count)); ++t) {
    pool.emplace_back([&]() {
      for (int i = next++; i < count; i = next++) fn(i);
    });
  }
  for (std::thread& t : pool) t.join();
}

// Mean and sample sd (n - 1) of `v`; 0 for what fewer values cannot give.
void MeanAndSd(const std::vector<double>& v, double* mean, double* sd) {
  *mean = *sd = 0;
  if (v.empty()) return;
  for (double x : v) *mean += x / static_cast<double>(v.size());
  if (v.size() < 2) return;
  double ss = 0;
  for (double x : v) ss += (x - *mean) * (x - *mean);
  *sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
}

}  // namespace

bool RunSimTierTable(const SimTierSpec& spec,
                     const std::function<void(const SimTierRow&)>& row_done,
                     std::vector<SimTierRow>* rows, std::string* error) {
  for (const SimTier& tier : spec.tiers) {
    SimTierRow row;
    row.tier = tier.name;
    // The straight-edge static curve: the cup held into the plate as its approach presses it
    // (the segment lip about 1 mm, the skirt 0.3 mm: docs/pneumatics.md).
    auto probe = EdgeProbe3d::Create(ResolveScenePath(tier.probe_scene), error);
    if (!probe) return false;
    ProbeStudySpec ps;
    for (int k = 0; k < 3; ++k) {
      const ProbeReading r = probe->Read(-kStaticOffsetsMm[k] * 1e-3, 0, 0, 0.010,
                                         tier.probe_press_mm * 1e-3, ps.settle_s);
      row.static_pbar_pa[k] = r.pbar_pa;
      if (k == 1) row.static_diff_pa = std::hypot(r.dpx_pa, r.dpy_pa);
    }
    // Fig. 6 on the disk: P_ref 100 Pa, dL 5 mm, beta 1.5 / 2.5 / 3.5, default effects.
    ModelPtr disk = LoadModel(ResolveScenePath(tier.disk_scene), error);
    if (!disk) return false;
    const int n = 3 * spec.seeds;
    std::vector<TrialResult> results(n);
    ParallelFor(n, spec.threads, [&](int i) {
      TrialConfig c;
      c.law.p_ref_pa = 100;
      c.law.beta = kFig6Beta[i / spec.seeds];
      c.law.step_mm = 5;
      c.seed = spec.seed + static_cast<std::uint64_t>(i % spec.seeds);
      std::string e;
      results[i] = RunGuardedTrial(disk.get(), c, nullptr, &e);
      if (results[i].outcome == Outcome::kRunning) results[i].detail = e;
    });
    double wall = 0, steps = 0, compression = 0;
    std::array<std::vector<double>, 3> sigma_r, s_c, dr;  // per beta, over the successes
    for (int i = 0; i < n; ++i) {
      const TrialResult& r = results[i];
      const int b = i / spec.seeds;
      wall += r.wall_time_s;
      steps += r.sim_time_s / disk->opt.timestep;
      compression += (0.010 - r.hold_height_m) * 1e3 / n;
      ++row.trials[b];
      if (r.outcome != Outcome::kSuccess) continue;
      ++row.successes[b];
      sigma_r[b].push_back(r.metrics.sigma_r_mm);
      s_c[b].push_back(r.metrics.s_c);
      dr[b].push_back(r.metrics.dr_mm);
    }
    for (int b = 0; b < 3; ++b) {
      MeanAndSd(sigma_r[b], &row.sigma_r_mm[b], &row.sigma_r_sd_mm[b]);
      MeanAndSd(s_c[b], &row.s_c[b], &row.s_c_sd[b]);
      MeanAndSd(dr[b], &row.dr_mm[b], &row.dr_sd_mm[b]);
    }
    row.us_per_step = steps > 0 ? wall / steps * 1e6 : 0;
    row.approach_compression_mm = compression;
    // Outcomes on the objects, in the tier's object scenes.
    if (tier.has_object_scenes && !spec.objects.empty()) {
      std::vector<std::string> outcomes(spec.objects.size());
      ParallelFor(static_cast<int>(spec.objects.size()), spec.threads, [&](int i) {
        const ObjectSpec& o = spec.objects[i];
        std::string e;
        const std::string dir = spec.object_dir + "/" + tier.name;
        ContourLawParams law;
        law.step_mm = 0.5;
        ModelPtr m;
        if (WriteObjectFiles(o, dir, SourceDir(), RigObjectSceneTemplates(), &e)) {
          m = LoadModel(dir + "/" + ObjectSceneFile(o, tier.object_kind, law.step_mm), &e);
        }
        if (!m) {
          outcomes[i] = o.name + " not run: " + e;
          return;
        }
        const ObjectTrialRow r =
            RunObjectTrial(m.get(), o, law, FittedRobotEffects(), spec.seed, false);
        char text[160];
        std::snprintf(text, sizeof(text), "%s %s (%.1f %s)", o.name.c_str(),
                      OutcomeName(r.result.outcome), o.closed() ? r.end_swept_deg : r.end_arc_mm,
                      o.closed() ? "deg" : "mm");
        outcomes[i] = text;
      });
      for (const std::string& o : outcomes) row.objects += (row.objects.empty() ? "" : "; ") + o;
    }
    rows->push_back(row);
    if (row_done) row_done(row);
  }
  return true;
}

std::string SimTierCsv(const std::vector<SimTierRow>& rows) {
  std::ostringstream os;
  os << "tier,us_per_step,approach_compression_mm,pbar_0.7mm_pa,pbar_2.5mm_pa,pbar_3.2mm_pa,"
        "diff_2.5mm_pa";
  for (const char* m : {"sigma_r_mm", "s_c", "dr_mm", "sigma_r_sd_mm", "s_c_sd", "dr_sd_mm",
                        "successes", "trials"}) {
    for (double b : kFig6Beta) os << ',' << m << "_beta" << b;
  }
  os << ",objects\n";
  for (const SimTierRow& r : rows) {
    os << r.tier << ',' << r.us_per_step << ',' << r.approach_compression_mm;
    for (double p : r.static_pbar_pa) os << ',' << p;
    os << ',' << r.static_diff_pa;
    for (const auto* a :
         {&r.sigma_r_mm, &r.s_c, &r.dr_mm, &r.sigma_r_sd_mm, &r.s_c_sd, &r.dr_sd_mm}) {
      for (double v : *a) os << ',' << v;
    }
    for (const auto* a : {&r.successes, &r.trials}) {
      for (int v : *a) os << ',' << v;
    }
    os << ",\"" << r.objects << "\"\n";
  }
  return os.str();
}

}  // namespace ssc
