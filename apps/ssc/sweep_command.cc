// ssc sweep: a grid of trials on all cores, resumable, one CSV row per trial.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "runtime/mujoco_model.h"
#include "studies/job_runner.h"
#include "studies/sweep.h"

namespace ssc {

int RunSweepCommand(int argc, char** argv) {
  const std::string cores = std::to_string(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<cli::Option> options = {
      {"scene", "disk_benchmark_gantry", "scene (name under scenes/ or a path)"},
      {"pref", "40,70,100,150,200,250,300", "P_ref values, comma-separated, Pa"},
      {"beta", "0,0.5,1,1.5,2,2.5,3,3.5,4", "beta values, comma-separated"},
      {"step", "2.5,5,7.5", "step lengths dL, comma-separated, mm"},
      {"repeats", "3", "trials per grid point"},
      {"seed", "1", "base seed (each trial's seed derives from it and its grid point)"},
      {"threads", cores, "worker threads"},
      {"out", "out/sweep", "output directory (sweep.csv, success_maps.png)"},
      {"no-plot", "", "skip the PNG plot", true},
      {"no-progress", "", "no progress bar even on a terminal", true}};
  for (const cli::Option& o : TrialSettingOptions()) options.push_back(o);
  cli::Parser p("sweep",
                "Runs a grid P_ref x beta x dL x repeats of disk trials (the published grid by\n"
                "default) on all cores. Rows are appended to OUT/sweep.csv as trials end;\n"
                "re-running the same command resumes, skipping finished rows.",
                options);
  if (!p.Parse(argc, argv)) {
    if (p.help_requested()) return 0;
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  SweepSpec spec;
  long repeats = 0, seed = 0, threads = 0;
  std::string error;
  if (!p.GetDoubleList("pref", &spec.pref_pa) || !p.GetDoubleList("beta", &spec.beta) ||
      !p.GetDoubleList("step", &spec.step_mm) || !p.GetInt("repeats", &repeats) ||
      !p.GetInt("seed", &seed) || !p.GetInt("threads", &threads)) {
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  if (repeats < 1 || repeats > 1000 || seed < 0 || threads < 1 || threads > 256) {
    std::fprintf(stderr, "ssc sweep: need repeats in [1, 1000], seed >= 0, threads in [1, 256]\n");
    return 2;
  }
  if (!ReadTrialSettings(&p, &spec.base, &error)) {
    std::fprintf(stderr, "ssc sweep: %s\n", error.c_str());
    return 2;
  }
  spec.repeats = static_cast<int>(repeats);
  spec.seed = static_cast<std::uint64_t>(seed);
  spec.threads = static_cast<int>(threads);
  spec.scene_name = p.Get("scene");
  const std::filesystem::path out = p.Get("out");
  std::filesystem::create_directories(out);
  spec.out_csv = (out / "sweep.csv").string();

  const std::string scene = ResolveScenePath(p.Get("scene"));
  ModelPtr model = LoadModel(scene, &error);
  if (!model) {
    std::fprintf(stderr, "ssc sweep: %s\n", error.c_str());
    return 1;
  }
  const bool rank0 = JobRunnerRank() == 0;
  const bool bar = rank0 && !p.Flag("no-progress") && isatty(STDERR_FILENO);
  auto progress = [&](const SweepProgress& s) {
    if (!bar) return;
    const int ran = s.done - s.skipped;
    const double rate = s.elapsed_s > 0 ? ran / s.elapsed_s : 0;
    const double eta = rate > 0 ? (s.total - s.done) / rate : 0;
    const int width = 30;
    const int filled = s.total ? width * s.done / s.total : width;
    std::fprintf(stderr, "\r[%.*s%*s] %d/%d trials  %.1f trials/s  ETA %.0f s ", filled,
                 "##############################", width - filled, "", s.done, s.total, rate, eta);
    std::fflush(stderr);
  };
  SweepSummary summary;
  if (!RunSweep(model.get(), spec, progress, &summary, &error)) {
    std::fprintf(stderr, "ssc sweep: %s\n", error.c_str());
    return 1;
  }
  if (bar) std::fprintf(stderr, "\n");
  if (!rank0) return summary.interrupted ? 130 : 0;
  std::printf("sweep: %d trials (%d already in %s, %d run) in %.1f s wall on %d rank(s) x %d "
              "threads (%.2f trials/s)\n",
              summary.total, summary.skipped, spec.out_csv.c_str(), summary.ran, summary.wall_s,
              summary.ranks, summary.threads,
              summary.wall_s > 0 ? summary.ran / summary.wall_s : 0.0);
  double busy = 0;
  for (double b : summary.rank_busy_s) busy += b;
  std::printf("load: %.1f trial-s busy, longest trial %.2f s; rank busy max/mean %.3f (",
              busy, summary.longest_trial_s, summary.balance_max_over_mean);
  for (size_t r = 0; r < summary.rank_busy_s.size(); ++r) {
    std::printf("%s%.1f", r ? " " : "", summary.rank_busy_s[r]);
  }
  std::printf(" s)\n");
  if (summary.interrupted) {
    std::fprintf(stderr, "ssc sweep: interrupted; %d finished rows kept in %s, re-run the same "
                         "command to resume\n", summary.ran, spec.out_csv.c_str());
    return 130;
  }
  if (!p.Flag("no-plot")) {
    const std::string png = (out / "success_maps.png").string();
    if (RunPlotScript("plot_success_maps.py", {spec.out_csv, png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
