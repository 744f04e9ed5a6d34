// ssc trial: one contour-following trial, headless.
#include <cstdio>
#include <filesystem>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "common/exit_codes.h"
#include "compare/twin_log.h"
#include "geometry/dimensions.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/trial_io.h"

namespace ssc {

int RunTrialCommand(int argc, char** argv) {
  cli::Command cmd(
      "trial",
      "Runs one disk trial headless: approach to the start-up force, move 32 mm toward\n"
      "the edge, follow it; prints the outcome and metrics, writes the log.");
  TrialConfig config;
  TrialSettings settings;
  std::string scene_name = DefaultScene(), out_dir = "out/trial", robot_log_dir;
  double stop_at = 0;
  bool no_plot = false;
  cmd.Text("scene", &scene_name, "scene (name under scenes/ or a path)");
  AddLawOptions(&cmd, &config.law);
  cmd.Seed("seed", &config.seed, "sensor noise seed");
  cmd.OutputDir("out", &out_dir, "output directory (trial.csv, summary.json, trajectory.png)");
  cmd.OutputDir("robot-log", &robot_log_dir,
                "also write the run as the lab records it into this directory (per-topic "
                "dataLog_*.csv + DataLog_*.mat, base_link frame), for ssc compare");
  cmd.Number("stop-at", &stop_at,
             "stop after this many simulated seconds and print the tool position", "s",
             NumberRange::Positive(3600), false);
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  AddControllerOptions(&cmd, &settings.controller, &settings.controller_params, &config.controller);
  AddTrialSettingOptions(&cmd, &config, &settings);
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  std::string error;
  const std::string scene = ResolveScenePath(scene_name);
  ModelPtr model = LoadTrialScene(cmd, scene, config);
  if (!model) return 1;
  if (cmd.Given("stop-at")) {
    // A partial run, for comparing with `ssc view --screenshot --time T` (same steps).
    DataPtr data = MakeData(model.get(), &error);
    auto trial =
        data ? ContourTrial::Create(model.get(), data.get(), config, false, &error) : nullptr;
    if (!trial) {
      std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
      return 1;
    }
    trial->Run(stop_at);
    const Vec3 tool = {data->site_xpos[3 * trial->tool_site()],
                       data->site_xpos[3 * trial->tool_site() + 1],
                       data->site_xpos[3 * trial->tool_site() + 2]};
    std::printf("stopped at t = %.4f s; phase %s; tool at %.9f %.9f %.9f m\n", data->time,
                PhaseName(trial->phase()), tool[0], tool[1], tool[2]);
    return 0;
  }
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  const TrialResult r = RunTrial(model.get(), config, true, &error);
  const DiskTrialMetrics& m = r.metrics;
  std::printf("scene %s, P_ref %.0f Pa, beta %.2f, dL %.2f mm, seed %llu\n", scene_name.c_str(),
              config.law.p_ref_pa, config.law.beta, config.law.step_mm,
              static_cast<unsigned long long>(config.seed));
  std::printf("outcome: %s (%s)\n", OutcomeName(r.outcome), r.detail.c_str());
  std::printf(
      "path s = %.1f mm, s_c = %.1f %%, r_mean = %.2f mm, dr = %.2f mm, sigma_r = %.2f mm\n",
      m.s_mm, m.s_c * 100, m.r_mean_mm, m.dr_mm, m.sigma_r_mm);
  std::printf("contour distance mean %.2f mm, max %.2f mm; swept %.0f deg in %d iterations\n",
              m.contour_mean_mm, m.contour_max_mm, r.swept_deg, r.iterations);
  std::printf(
      "follow %.1f s, speed %.1f mm/s (%.2f body diameters/s); %.1f s simulated in "
      "%.2f s wall (%.0fx real time)\n",
      m.duration_s, m.speed_mm_s, m.speed_body_d_s, r.sim_time_s, r.wall_time_s,
      r.wall_time_s > 0 ? r.sim_time_s / r.wall_time_s : 0.0);
  const std::filesystem::path out = out_dir;
  if (!WriteTrialLogCsv((out / "trial.csv").string(), r, &error) ||
      !WriteTrialSummaryJson((out / "summary.json").string(), scene, config, r, &error)) {
    std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s and %s\n", (out / "trial.csv").c_str(), (out / "summary.json").c_str());
  if (!robot_log_dir.empty()) {
    std::vector<std::string> files;
    if (!WriteLabRecordingFromTrial(model.get(), r, config, robot_log_dir, &files, &error)) {
      std::fprintf(stderr, "ssc trial: %s\n", error.c_str());
      return 1;
    }
    std::printf("wrote the run as a lab recording (%zu files) into %s\n", files.size(),
                robot_log_dir.c_str());
  }
  if (!no_plot) {
    const std::string png = (out / "trajectory.png").string();
    if (RunPlotScript("plot_trajectories.py", {png, (out / "trial.csv").string()})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return r.outcome == Outcome::kSuccess ? kExitOk : kExitTrialFailed;
}

}  // namespace ssc
