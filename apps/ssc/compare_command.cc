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
  cli::Parser p(
      "compare",
      "ssc compare LOG [options]: replays the logged tool path in the twin and compares the\n"
      "chamber pressures with the logged ones (RMS in Pa and log10, correlation, mean-pressure\n"
      "error, direction error of the controller's g). LOG: a directory of the robot's per-topic\n"
      "CSVs (pressure.csv, tool_pose.csv, ft.csv, pwm.csv), the merged .mat file, or a plain CSV\n"
      "(docs/robot_logs.md). Writes OUT/report.md, report.json, series.csv and compare.png.",
      {{"scene", "disk_replay", "replay scene with a mocap body 'probe' holding the tool"},
       {"out", "out/compare", "output directory"},
       {"offset-window", "1.0", "in-air offset: mean absolute pressure over the first ... s"},
       {"average", "7", "host moving-average window applied to the log, samples"},
       {"tcp-offset", "146", "tool centre point along the tool0 z axis, mm"},
       {"closed-loop", "", "also run the twin's controller from the log's start pose", true},
       {"loop-scene", "disk_benchmark_gantry", "disk scene for the closed loop"},
       {"pref", "100", "closed loop: the log's P_ref, Pa"},
       {"beta", "2", "closed loop: the log's beta"},
       {"step", "7.5", "closed loop: the log's step, mm"},
       {"seed", "1", "closed loop: noise seed"},
       {"no-plot", "", "skip the PNG plot", true}});
  if (!p.Parse(argc, argv)) {
    if (p.help_requested()) return 0;
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  if (p.positional().size() != 1) {
    std::fprintf(stderr, "ssc compare: give exactly one LOG (see ssc compare --help)\n");
    return 2;
  }
  ProcessOptions options;
  long average = 0;
  double tcp_mm = 0;
  if (!p.GetDouble("offset-window", &options.offset_window_s) || !p.GetInt("average", &average) ||
      !p.GetDouble("tcp-offset", &tcp_mm)) {
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  if (average < 1 || average > 1000 || options.offset_window_s <= 0) {
    std::fprintf(stderr, "ssc compare: need --average in [1, 1000] and --offset-window > 0\n");
    return 2;
  }
  options.moving_average = static_cast<int>(average);
  options.tcp_offset_m = tcp_mm * 1e-3;
  ProcessedLog log;
  LoadError load_error;
  if (!LoadAnyLog(p.positional()[0], options, &log, &load_error)) {
    std::fprintf(stderr, "ssc compare: %s\n", load_error.ToString().c_str());
    return 1;
  }
  std::string error;
  ModelPtr model = LoadModel(ResolveScenePath(p.Get("scene")), &error);
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
  if (p.Flag("closed-loop")) {
    TrialConfig tc;
    long seed = 0;
    if (!p.GetDouble("pref", &tc.law.p_ref_pa) || !p.GetDouble("beta", &tc.law.beta) ||
        !p.GetDouble("step", &tc.law.step_mm) || !p.GetInt("seed", &seed) || seed < 0) {
      std::fprintf(stderr, "ssc compare: %s\n", p.error().c_str());
      return 2;
    }
    tc.seed = static_cast<std::uint64_t>(seed);
    ModelPtr loop = LoadModel(ResolveScenePath(p.Get("loop-scene")), &error);
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
  if (!WriteComparisonReport(p.Get("out"), p.positional()[0], c, &closed, &error)) {
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
  const std::filesystem::path out = p.Get("out");
  std::printf("wrote %s\n", (out / "report.md").c_str());
  if (!p.Flag("no-plot")) {
    const std::string png = (out / "compare.png").string();
    if (RunPlotScript("plot_compare.py", {(out / "series.csv").string(), png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
