// ssc compare: the twin against a robot log (replay of the logged tool path).
#include <cstdio>
#include <filesystem>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "compare/log_replay.h"
#include "runtime/mujoco_model.h"

namespace ssc {

int RunCompareCommand(int argc, char** argv) {
  cli::Command cmd(
      "compare",
      "ssc compare LOG [options]: replays the logged tool path in the twin and compares the\n"
      "chamber pressures with the logged ones (RMS in Pa and log10, correlation, mean-pressure\n"
      "error, direction error of the controller's g). LOG: a directory of the robot's per-topic\n"
      "CSVs (pressure.csv, tool_pose.csv, ft.csv, pwm.csv), the merged .mat file, or a plain CSV\n"
      "(docs/robot_logs.md). Writes OUT/report.md, report.json, series.csv and compare.png.");
  std::string log_path, scene_name = "disk_replay", loop_scene = "disk_benchmark_gantry",
                        out_dir = "out/compare";
  ProcessOptions options;
  long average = 7;
  double tcp_mm = 146;
  bool closed_loop = false, no_plot = false;
  TrialConfig tc;
  cmd.Positional("LOG", &log_path, "the robot log (directory, .mat or plain CSV)", true);
  cmd.Text("scene", &scene_name, "replay scene with a mocap body 'probe' holding the tool");
  cmd.OutputDir("out", &out_dir, "output directory");
  options.offset_window_s = 1.0;
  cmd.Number("offset-window", &options.offset_window_s,
             "in-air offset: mean absolute pressure over the first ... of the log", "s",
             NumberRange::Positive(60));
  cmd.Integer("average", &average, "host moving-average window applied to the log, samples",
              NumberRange::Closed(1, 1000));
  cmd.Number("tcp-offset", &tcp_mm, "tool centre point along the tool0 z axis", "mm",
             NumberRange::Closed(0, 1000));
  cmd.Flag("closed-loop", &closed_loop, "also run the twin's controller from the log's start pose");
  cmd.Text("loop-scene", &loop_scene, "disk scene for the closed loop");
  cmd.Number("pref", &tc.law.p_ref_pa, "closed loop: the log's P_ref", "Pa",
             NumberRange::Positive(1e6).OpenHigh());
  cmd.Number("beta", &tc.law.beta, "closed loop: the log's beta", "", NumberRange::Closed(0, 100));
  cmd.Number("step", &tc.law.step_mm, "closed loop: the log's step", "mm",
             NumberRange::Positive(100));
  cmd.Seed("seed", &tc.seed, "closed loop: noise seed");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Check([&tc]() { return tc.Validate(); });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  options.moving_average = static_cast<int>(average);
  options.tcp_offset_m = tcp_mm * 1e-3;
  ProcessedLog log;
  LoadError load_error;
  if (!LoadAnyLog(log_path, options, &log, &load_error)) {
    std::fprintf(stderr, "ssc compare: %s\n", load_error.ToString().c_str());
    return 1;
  }
  std::string error;
  ModelPtr model = LoadModel(ResolveScenePath(scene_name), &error);
  if (!model) {
    std::fprintf(stderr, "ssc compare: %s\n", error.c_str());
    return 1;
  }
  ReplayComparison c;
  if (!ReplayLog(model.get(), log, options.tcp_offset_m, &c, &error)) {
    std::fprintf(stderr, "ssc compare: %s\n", error.c_str());
    return 1;
  }
  ClosedLoopComparison closed;
  if (closed_loop) {
    ModelPtr loop = LoadModel(ResolveScenePath(loop_scene), &error);
    if (!loop || !CompareClosedLoop(loop.get(), log, tc, &closed, &error)) {
      std::fprintf(stderr, "ssc compare: closed loop: %s\n", error.c_str());
      return 1;
    }
    std::printf("closed loop: twin %s; dr %.2f vs %.2f mm (log), sigma_r %.2f vs %.2f mm, "
                "s_c %.3f vs %.3f, duration %.1f vs %.1f s; path distance mean %.2f, max %.2f mm\n",
                closed.twin_outcome.c_str(), closed.twin.dr_mm, closed.log.dr_mm,
                closed.twin.sigma_r_mm, closed.log.sigma_r_mm, closed.twin.s_c, closed.log.s_c,
                closed.twin.duration_s, closed.log.duration_s, closed.path_distance_mean_mm,
                closed.path_distance_max_mm);
  }
  if (!WriteComparisonReport(out_dir, log_path, c, &closed, &error)) {
    std::fprintf(stderr, "ssc compare: %s\n", error.c_str());
    return 1;
  }
  for (int k = 0; k < 4; ++k) {
    std::printf("chamber %d: RMS %.1f Pa (%.3f in log10), correlation %.3f, mean ratio %.3f\n",
                k + 1, c.rms_pa[k], c.rms_log10[k], c.correlation[k], c.mean_ratio[k]);
  }
  std::printf("mean P: RMS %.1f Pa, bias %.1f Pa; direction error RMS %.1f deg (median %.1f, "
              "%d samples)\n", c.pbar_rms_pa, c.pbar_bias_pa, c.direction_rms_deg,
              c.direction_median_deg, c.direction_samples);
  const std::filesystem::path out = out_dir;
  std::printf("wrote %s\n", (out / "report.md").c_str());
  if (!no_plot) {
    const std::string png = (out / "compare.png").string();
    if (RunPlotScript("plot_compare.py", {(out / "series.csv").string(), png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
