// ssc trial: one contour-following trial, headless.
#include <cstdio>
#include <filesystem>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "runtime/mujoco_model.h"
#include "compare/log_replay.h"
#include "studies/trial_io.h"

namespace ssc {

int RunTrialCommand(int argc, char** argv) {
  std::vector<cli::Option> options = {
      {"scene", "disk_benchmark", "scene (name under scenes/ or a path)"},
      {"pref", "100", "P_ref, set point of the mean vacuum, Pa"},
      {"beta", "2", "beta, correction gain (dimensionless)"},
      {"step", "7.5", "step length dL per control iteration, mm"},
      {"seed", "1", "sensor noise seed"},
      {"out", "out/trial", "output directory (trial.csv, summary.json, trajectory.png)"},
      {"robot-log", "", "also write the run as a robot-format log into this directory "
                        "(per-topic CSVs + log.mat), for ssc compare"},
      {"stop-at", "", "stop after this many simulated seconds and print the tool position, s"},
      {"no-plot", "", "skip the PNG plot", true}};
  for (const cli::Option& o : TrialSettingOptions()) options.push_back(o);
  cli::Parser p("trial",
                "Runs one disk trial headless: approach to the start-up force, move 32 mm toward\n"
                "the edge, follow it; prints the outcome and metrics, writes the log.",
                options);
  if (!p.Parse(argc, argv)) {
    if (p.help_requested()) return 0;
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  TrialConfig config;
  long seed = 0;
  std::string error;
  if (!p.GetDouble("pref", &config.law.p_ref_pa) || !p.GetDouble("beta", &config.law.beta) ||
      !p.GetDouble("step", &config.law.step_mm) || !p.GetInt("seed", &seed)) {
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  if (!ReadTrialSettings(&p, &config, &error)) {
    std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
    return 2;
  }
  if (seed < 0) {
    std::fprintf(stderr, "ssc trial: --seed must be >= 0\n");
    return 2;
  }
  config.seed = static_cast<std::uint64_t>(seed);
  if (const std::string e = config.Validate(); !e.empty()) {
    std::fprintf(stderr, "ssc trial: %s\n", e.c_str());
    return 2;
  }
  const std::string scene = ResolveScenePath(p.Get("scene"));
  ModelPtr model = LoadModel(scene, &error);
  if (!model) {
    std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
    return 1;
  }
  if (!p.Get("stop-at").empty()) {
    // A partial run, for comparing with `ssc view --screenshot --time T` (same steps).
    double stop = 0;
    if (!p.GetDouble("stop-at", &stop) || stop <= 0) {
      std::fprintf(stderr, "ssc trial: --stop-at expects a positive time in s\n");
      return 2;
    }
    DataPtr data = MakeData(model.get(), &error);
    auto trial = data ? ContourTrial::Create(model.get(), data.get(), config, false, &error) : nullptr;
    if (!trial) {
      std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
      return 1;
    }
    trial->Run(stop);
    const Vec3 tool = {data->site_xpos[3 * trial->tool_site()],
                       data->site_xpos[3 * trial->tool_site() + 1],
                       data->site_xpos[3 * trial->tool_site() + 2]};
    std::printf("stopped at t = %.4f s; phase %s; tool at %.9f %.9f %.9f m\n", data->time,
                PhaseName(trial->phase()), tool[0], tool[1], tool[2]);
    return 0;
  }
  const TrialResult r = RunTrial(model.get(), config, true, &error);
  const DiskTrialMetrics& m = r.metrics;
  std::printf("scene %s, P_ref %.0f Pa, beta %.2f, dL %.2f mm, seed %ld\n", p.Get("scene").c_str(),
              config.law.p_ref_pa, config.law.beta, config.law.step_mm, seed);
  std::printf("outcome: %s (%s)\n", r.outcome.c_str(), r.detail.c_str());
  std::printf("path s = %.1f mm, s_c = %.1f %%, r_mean = %.2f mm, dr = %.2f mm, sigma_r = %.2f mm\n",
              m.s_mm, m.s_c * 100, m.r_mean_mm, m.dr_mm, m.sigma_r_mm);
  std::printf("contour distance mean %.2f mm, max %.2f mm; swept %.0f deg in %d iterations\n",
              m.contour_mean_mm, m.contour_max_mm, r.swept_deg, r.iterations);
  std::printf("follow %.1f s, speed %.1f mm/s (%.2f body diameters/s); %.1f s simulated in "
              "%.2f s wall (%.0fx real time)\n",
              m.duration_s, m.speed_mm_s, m.speed_body_d_s, r.sim_time_s, r.wall_time_s,
              r.wall_time_s > 0 ? r.sim_time_s / r.wall_time_s : 0.0);
  const std::filesystem::path out = p.Get("out");
  std::filesystem::create_directories(out);
  if (!WriteTrialLogCsv((out / "trial.csv").string(), r, &error) ||
      !WriteTrialSummaryJson((out / "summary.json").string(), scene, config, r, &error)) {
    std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s and %s\n", (out / "trial.csv").c_str(), (out / "summary.json").c_str());
  if (!p.Get("robot-log").empty()) {
    const RobotLog log = RobotLogFromTrial(r, 0.146, 1.0, 0.0);
    const std::string dir = p.Get("robot-log");
    if (!WriteRobotLogDir(dir, log, &error) ||
        !WriteRobotLogMat((std::filesystem::path(dir) / "log.mat").string(), log, &error)) {
      std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
      return 1;
    }
    std::printf("wrote the robot-format log into %s\n", dir.c_str());
  }
  if (!p.Flag("no-plot")) {
    const std::string png = (out / "trajectory.png").string();
    if (RunPlotScript("plot_trajectories.py", {png, (out / "trial.csv").string()})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return r.outcome == "unstable" ? 3 : 0;
}

}  // namespace ssc
