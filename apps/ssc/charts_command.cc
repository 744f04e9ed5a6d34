// ssc charts: the speed-accuracy charts, for the cup and for the simulator, from the project's
// own runs.
//   cup: a sweep over step length (so speed) for a few (P_ref, beta) -> success, sigma_r, |dr|,
//        contour error vs speed, and the Pareto front of speed vs tracking error;
//   simulator: one logged path replayed with cheaper and dearer settings (rays per chamber,
//        sensor rate, time step, integrator, lip segments) -> wall time per simulated second vs
//        pressure error against a high-fidelity reference replay (16 rays per chamber, 32 lip
//        segments, 0.25 ms, RK4).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "compare/log_replay.h"
#include "runtime/mujoco_model.h"
#include "studies/sweep.h"
#include "studies/tool_variants.h"
#include "geometry/dimensions.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

std::string Key(const char* k, const std::string& v) {
  return std::string("<config key=\"") + k + "\" value=\"" + v + "\"/>";
}

}  // namespace

int RunChartsCommand(int argc, char** argv) {
  cli::Command cmd("charts",
                   "Makes the speed-accuracy charts from the project's own runs: OUT/cup.csv (a\n"
                   "sweep over dL), OUT/simulator.csv (replays at several fidelities), and\n"
                   "OUT/speed_accuracy.png. Re-running resumes the sweep.");
  SweepSpec spec;
  spec.pref_pa = {70, 100, 200};
  spec.beta = {1, 2, 3};
  spec.step_mm = {1, 2.5, 5, 7.5, 10, 12.5};
  long repeats = 3, threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "out/charts";
  cmd.NumberList("pref", &spec.pref_pa, "P_ref values", "Pa", NumberRange::Positive(1e6).OpenHigh());
  cmd.NumberList("beta", &spec.beta, "beta values", "", NumberRange::Closed(0, 100));
  cmd.NumberList("step", &spec.step_mm, "step lengths", "mm", NumberRange::Positive(100));
  cmd.Integer("repeats", &repeats, "trials per point", NumberRange::Closed(1, 1000));
  cmd.Integer("threads", &threads, "threads for the sweep", NumberRange::Closed(1, 256));
  cmd.OutputDir("out", &out_dir, "output directory");
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  spec.repeats = static_cast<int>(repeats);
  spec.threads = static_cast<int>(threads);
  spec.scene_name = "disk_benchmark_gantry";
  const fs::path out = out_dir;
  spec.out_csv = (out / "cup.csv").string();
  std::string error;
  ModelPtr gantry = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
  if (!gantry) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  SweepSummary summary;
  if (!RunSweep(gantry.get(), spec, nullptr, &summary, &error)) {
    std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
    return 1;
  }
  std::printf("cup sweep: %d trials (%d run now) in %.1f s -> %s\n", summary.total, summary.ran,
              summary.wall_s, spec.out_csv.c_str());

  // The simulator: a path from one twin trial, replayed at several fidelities.
  TrialConfig c;
  c.law.step_mm = 5;
  const TrialResult trial = RunTrial(gantry.get(), c, true, &error);
  ProcessedLog path;
  LoadError load_error;
  ProcessOptions po;
  po.moving_average = 1;
  if (!ProcessRobotLog(RobotLogFromTrial(trial, kToolCentreOffsetM, 1, 0), po, &path, &load_error)) {
    std::fprintf(stderr, "ssc charts: %s\n", load_error.ToString().c_str());
    return 1;
  }
  struct Setting {
    std::string name, config;
    double dt;
    int integrator;
    bool reference, is_default;
    int lip_segments = 16;
  };
  const std::string quiet = Key("noise_pa", "0");  // compare the physics, not the noise
  std::vector<Setting> settings = {
      {"reference: 16 rays, 32 lip segments, 0.25 ms, RK4", quiet + Key("rays_per_chamber", "16"),
       0.00025, mjINT_RK4, true, false, 32},
      {"default: 4 rays, 160 Hz, 2 ms, implicitfast", quiet, 0.002, mjINT_IMPLICITFAST, false, true}};
  for (int rays : {1, 2, 8, 16}) {
    settings.push_back({std::to_string(rays) + " rays", quiet + Key("rays_per_chamber", std::to_string(rays)),
                        0.002, mjINT_IMPLICITFAST, false, false});
  }
  for (const char* hz : {"40", "80", "320"}) {
    settings.push_back({std::string(hz) + " Hz sensor", quiet + Key("sample_rate_hz", hz), 0.002,
                        mjINT_IMPLICITFAST, false, false});
  }
  for (double dt : {0.0005, 0.001, 0.004, 0.008}) {
    char name[32];
    std::snprintf(name, sizeof(name), "%.1f ms step", dt * 1e3);
    settings.push_back({name, quiet, dt, mjINT_IMPLICITFAST, false, false});
  }
  for (int lips : {8, 32, 64}) {
    settings.push_back({std::to_string(lips) + " lip segments", quiet, 0.002, mjINT_IMPLICITFAST,
                        false, false, lips});
  }
  settings.push_back({"Euler", quiet, 0.002, mjINT_EULER, false, false});
  settings.push_back({"RK4", quiet, 0.002, mjINT_RK4, false, false});
  std::ofstream csv(out / "simulator.csv");
  csv << "setting,timestep_ms,wall_per_sim_s,rms_log10_vs_reference,rms_pa_vs_reference,"
         "is_default\n";
  std::vector<std::array<double, 4>> reference;
  for (const Setting& s : settings) {
    const std::string dir = (out / "scenes" / std::to_string(&s - settings.data())).string();
    std::string scene = SceneWithToolConfig(SourceDir() + "/scenes/disk_replay.xml", dir, s.config,
                                            &error);
    if (!scene.empty() && s.lip_segments != 16) {
      const std::string tool = ToolWithLipSegments(ToolModelWithConfig(s.config, &error),
                                                   s.lip_segments, &error);
      if (tool.empty()) {
        scene.clear();
      } else {
        std::ofstream(fs::path(dir) / "models" / "ssc_tool.xml") << tool;
      }
    }
    ModelPtr m = scene.empty() ? nullptr : LoadModel(scene, &error);
    if (!m) {
      std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
      return 1;
    }
    m->opt.timestep = s.dt;
    m->opt.integrator = s.integrator;
    ReplayComparison r;
    const auto t0 = std::chrono::steady_clock::now();
    if (!ReplayLog(m.get(), path, kToolCentreOffsetM, &r, &error)) {
      std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
      return 1;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double sim = path.t_s.back() - path.t_s.front();
    if (s.reference) reference = r.sim_pa;
    double e_log = 0, e_pa = 0;
    for (size_t i = 0; i < r.sim_pa.size() && i < reference.size(); ++i) {
      for (int k = 0; k < 4; ++k) {
        e_log += std::pow(std::log10(std::max(1.0, r.sim_pa[i][k])) -
                              std::log10(std::max(1.0, reference[i][k])), 2);
        e_pa += std::pow(r.sim_pa[i][k] - reference[i][k], 2);
      }
    }
    const double n = 4.0 * static_cast<double>(r.sim_pa.size());
    std::printf("  %-44s wall/sim %.4f  error %.4f log10, %.1f Pa\n", s.name.c_str(), wall / sim,
                std::sqrt(e_log / n), std::sqrt(e_pa / n));
    csv << '"' << s.name << "\"," << s.dt * 1e3 << ',' << wall / sim << ',' << std::sqrt(e_log / n)
        << ',' << std::sqrt(e_pa / n) << ',' << (s.is_default ? 1 : 0) << '\n';
  }
  // Full arm against the light gantry: the same trial on both; the arm run is the reference
  // (pressures compared at equal times), cost is wall time per simulated second.
  {
    ModelPtr arm = LoadModel(SourceDir() + "/scenes/disk_benchmark.xml", &error);
    if (!arm) {
      std::fprintf(stderr, "ssc charts: %s\n", error.c_str());
      return 1;
    }
    const TrialResult a = RunTrial(arm.get(), c, true, &error);
    const TrialResult g = trial;  // the gantry run above, same config and seed
    std::map<long, std::array<double, 4>> arm_rows;
    for (const TrialLogRow& r : a.log) arm_rows[std::lround(r.t_s * 1e4)] = r.p_pa;
    double e_log = 0;
    int n = 0;
    for (const TrialLogRow& r : g.log) {
      auto it = arm_rows.find(std::lround(r.t_s * 1e4));
      if (it == arm_rows.end()) continue;
      for (int k = 0; k < 4; ++k) {
        e_log += std::pow(std::log10(std::max(1.0, r.p_pa[k])) -
                              std::log10(std::max(1.0, it->second[k])), 2);
      }
      n += 4;
    }
    const double err = n ? std::sqrt(e_log / n) : 0;
    std::printf("  %-44s wall/sim %.4f  (reference of this pair)\n", "arm scene (UR-10)",
                a.wall_time_s / a.sim_time_s);
    std::printf("  %-44s wall/sim %.4f  error %.4f log10 vs the arm run\n", "gantry scene",
                g.wall_time_s / g.sim_time_s, err);
    csv << "\"arm scene (UR-10)\",2," << a.wall_time_s / a.sim_time_s << ",0.0001,0,0\n";
    csv << "\"gantry scene vs arm\",2," << g.wall_time_s / g.sim_time_s << ',' << err << ",0,0\n";
  }
  csv.close();
  const std::string png = (out / "speed_accuracy.png").string();
  if (RunPlotScript("plot_speed_accuracy.py",
                    {(out / "cup.csv").string(), (out / "simulator.csv").string(), png})) {
    std::printf("wrote %s\n", png.c_str());
  }
  return 0;
}

}  // namespace ssc
