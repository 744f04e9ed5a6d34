// ssc compare: the twin against a robot log (compare/comparison.h does the work).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "compare/comparison.h"

namespace ssc {

namespace {

// The command line's values that are not CompareOptions' own until parsed.
struct CompareArgs {
  CompareOptions options;
  long average = 7;
  double tcp_mm = kToolCentreOffsetM * 1e3;
  std::string frame = "base_link";
  bool no_plot = false;
  std::string effects = "default";
  std::string controller_name = "published", controller_params;
};

void AddCompareOptions(cli::Command* cmd, CompareArgs* a) {
  cmd->Positional("LOG", &a->options.log_path,
                  "the robot log (folder, one of its files, .mat, plain CSV)", true);
  cmd->Text("scene", &a->options.scene, "replay scene with a mocap body 'probe' holding the tool");
  cmd->OutputDir("out", &a->options.out_dir, "output directory");
  cmd->Number("offset-window", &a->options.processing.offset_window_s,
              "in-air offset: mean absolute pressure over the first ... of the log", "s",
              NumberRange::Positive(60));
  cmd->Integer("average", &a->average, "host moving-average window applied to the log, samples",
               NumberRange::Closed(1, 1000));
  cmd->Number("tcp-offset", &a->tcp_mm, "tool centre point along the tool0 z axis", "mm",
              NumberRange::Closed(0, kMaxTcpOffsetM * 1e3));
  cmd->Choice("log-frame", &a->frame,
              "frame of the lab log's poses: ROS base_link (the lab's tf) or the UR base (RTDE)",
              {"base_link", "base"});
  cmd->NumberList("object-pose", &a->options.object_pose,
                  "the object in the log's frame: centre x,y and top z (m) [,yaw (deg)]; "
                  "default: from the log (disk benchmark)",
                  "m / deg", NumberRange::Closed(-360, 360), true);
  cmd->Flag("closed-loop", &a->options.closed_loop,
            "also run the twin's controller from the log's start (P_ref, beta, dL, force band "
            "from a .mat's script arguments)");
  cmd->Text("loop-scene", &a->options.loop_scene,
            "disk scene for the closed loop and the lip depth");
  TrialConfig& tc = a->options.loop_config;
  cmd->Number("pref", &tc.law.p_ref_pa, "closed loop: P_ref when the file has none", "Pa",
              NumberRange::Positive(1e6).OpenHigh());
  cmd->Number("beta", &tc.law.beta, "closed loop: beta when the file has none", "",
              NumberRange::Closed(0, 100));
  cmd->Number("step", &tc.law.step_mm, "closed loop: the step dL when the file has none", "mm",
              NumberRange::Closed(kMinStepMm, kMaxStepMm));
  cmd->Flag("override-law", &a->options.override_law,
            "closed loop: use --pref, --beta, --step even when the file records them");
  cmd->Seed("seed", &tc.seed, "closed loop: noise seed");
  AddEffectsOption(cmd,
                   "robot effects (docs/fidelity.md) of the closed loop, and the lip's (slip_mm, "
                   "tilt_decades, peel_decades) also in the replay",
                   &a->effects, &tc.effects);
  AddControllerOptions(cmd, &a->controller_name, &a->controller_params, &tc.controller);
  cmd->Flag("no-plot", &a->no_plot, "skip the PNG plot");
  cmd->Check([a]() { return a->options.loop_config.Validate(); });
  cmd->Check([a]() -> std::string {
    const CompareOptions& o = a->options;
    if (o.object_pose.empty()) return "";
    if (o.object_pose.size() != 3 && o.object_pose.size() != 4) {
      return "--object-pose takes x,y,z or x,y,z,yaw (got " + std::to_string(o.object_pose.size()) +
             " numbers)";
    }
    for (int k = 0; k < 3; ++k) {
      if (std::fabs(o.object_pose[k]) > 5) {
        return "--object-pose: x, y, z are metres within 5 m of the robot base (got " +
               std::to_string(o.object_pose[k]) + ": millimetres?)";
      }
    }
    return "";
  });
}

// Progress on stderr once a replay has run 2 s (a long log): a line per 10 %, or a bar on a
// terminal.
std::function<void(double)> ReplayProgress() {
  const bool tty = isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  auto shown_pct = std::make_shared<int>(-1);
  return [tty, start, shown_pct](double fraction) {
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int pct = static_cast<int>(fraction * 100);
    if (elapsed_s < 2 || pct == *shown_pct || (!tty && pct % 10 != 0)) return;
    *shown_pct = pct;
    const double eta_s = fraction > 0 ? elapsed_s * (1 - fraction) / fraction : 0;
    std::fprintf(stderr,
                 tty ? "\rssc compare: replay %3d%% (%.0f s, ETA %.0f s) %s"
                     : "ssc compare: replay %3d%% (%.0f s, ETA %.0f s)%s\n",
                 pct, elapsed_s, eta_s, tty && pct == 100 ? "\n" : "");
    std::fflush(stderr);
  };
}

// The comparison's figures on stdout, its warnings on stderr.
void PrintComparison(const CompareResult& r) {
  for (const std::string& w : r.log_warnings) {
    std::fprintf(stderr, "ssc compare: warning: %s\n", w.c_str());
  }
  const ComparisonSetup& s = r.setup;
  std::printf("%s, frame %s; scene object '%s', closest approach %.1f mm\n", s.format.c_str(),
              s.log_frame.c_str(), s.scene_object.name.c_str(), s.reach.closest_m * 1e3);
  if (s.object.known) {
    std::printf("object in the log frame: (%.4f, %.4f) m, top %.4f m, from %s\n", s.object.x_m,
                s.object.y_m, s.object.top_z_m, s.object.source.c_str());
  }
  const ReplayComparison& c = r.replay;
  for (int k = 0; k < 4; ++k) {
    std::printf("chamber %d: RMS %.1f Pa (%.3f in log10), correlation %s, mean ratio %.3f\n", k + 1,
                c.rms_pa[k], c.rms_log10[k], CorrelationText(c.correlation[k]).c_str(),
                c.mean_ratio[k]);
  }
  std::printf(
      "mean P: RMS %.1f Pa, bias %.1f Pa; direction error RMS %.1f deg (median %.1f, "
      "%d samples)\n",
      c.pbar_rms_pa, c.pbar_bias_pa, c.direction_rms_deg, c.direction_median_deg,
      c.direction_samples);
  if (r.history.ran) {
    const HistoryComparison& h = r.history;
    std::printf(
        "history: %d iterations (log time = history + %.3f s, %.2f mm); r_p median "
        "%.1f deg, r_p_final %.1f deg, F_normal RMS %.2f N, P1 RMS %.1f Pa\n",
        h.iterations, h.time_offset_s, h.match_rms_mm, h.r_p_median_deg, h.r_p_final_median_deg,
        h.f_normal_rms_n, h.p_rms_pa[0]);
  } else if (!r.history_warning.empty()) {
    std::fprintf(stderr, "ssc compare: warning: history not compared: %s\n",
                 r.history_warning.c_str());
  }
  if (r.closed.ran) {
    const ClosedLoopComparison& cl = r.closed;
    std::printf(
        "closed loop (controller %s; %s): twin %s; dr %.2f vs %.2f mm (log), sigma_r %.2f vs "
        "%.2f mm, s_c %.3f vs %.3f, duration %.1f vs %.1f s; path distance mean %.2f, max %.2f "
        "mm\n",
        cl.controller.c_str(), cl.parameters.c_str(), cl.twin_outcome.c_str(), cl.twin.dr_mm,
        cl.log.dr_mm, cl.twin.sigma_r_mm, cl.log.sigma_r_mm, cl.twin.s_c, cl.log.s_c,
        cl.twin.duration_s, cl.log.duration_s, cl.path_distance_mean_mm, cl.path_distance_max_mm);
  }
}

}  // namespace

int RunCompareCommand(int argc, char** argv) {
  cli::Command cmd(
      "compare",
      "ssc compare LOG [options]: replays the logged tool path in the twin and compares the\n"
      "chamber pressures with the logged ones (RMS in Pa and log10, correlation, mean-pressure\n"
      "error, direction error of the controller's g), and the lab controller's iterations\n"
      "(edgeFollowing_history) with the twin's at the same poses. LOG, unchanged as the lab\n"
      "records it: a recording folder of dataLog_<stamp>_<topic>.csv files or any one of them\n"
      "(either logger version), a DataLog_*.mat, or a plain CSV (docs/robot_logs.md).\n"
      "Writes OUT/report.md, report.json, series.csv, history.csv and compare.png.");
  CompareArgs args;
  AddCompareOptions(&cmd, &args);
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  CompareOptions& o = args.options;
  o.processing.moving_average = static_cast<int>(args.average);
  o.processing.tcp_offset_m = args.tcp_mm * 1e-3;
  ParseLogFrame(args.frame, &o.frame);
  o.progress = ReplayProgress();
  CompareResult r;
  std::string error;
  if (!RunComparison(o, &r, &error)) {
    std::fprintf(stderr, "ssc compare: %s\n", error.c_str());
    // A write that failed is a failure; anything else is the log or its set-up.
    if (error.find("cannot write") == std::string::npos) cli::NoteInputError(error);
    return 1;
  }
  PrintComparison(r);
  const std::filesystem::path out = o.out_dir;
  std::printf("wrote %s\n", (out / "report.md").c_str());
  if (!args.no_plot) {
    const std::string png = (out / "compare.png").string();
    if (RunPlotScript("plot_compare.py",
                      {(out / "series.csv").string(), png, (out / "report.json").string()})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
