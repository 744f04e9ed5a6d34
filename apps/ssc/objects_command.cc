// ssc objects: write every test object's scenes and run the contour-following trial on each.
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "apps/ssc/trial_options.h"
#include "runtime/mujoco_model.h"
#include "objects/object_mjcf.h"
#include "studies/object_trials.h"

namespace ssc {

int RunObjectsCommand(int argc, char** argv) {
  cli::Command cmd(
      "objects",
      "Writes the scenes of the published test objects (disks and holes 2-14 mm, the 35 mm\n"
      "disk, corners every 15 deg, volute, semicircle and semi-square strips, variable fillet)\n"
      "and runs the contour-following trial on each; writes OUT/objects.csv (one row per\n"
      "object and seed), OUT/fillet_profile.csv and OUT/objects.png.");
  std::string names = "all", kind = "gantry", out_dir = "out/objects";
  long seeds = 1, threads = std::max(1u, std::thread::hardware_concurrency());
  std::uint64_t seed = 1;
  ContourLawParams law;
  law.step_mm = 0.5;
  bool write_only = false, no_plot = false;
  cmd.Text("objects", &names,
           "comma-separated object names (e.g. disk_d06,hole_d10,corner_a090) or all");
  cmd.Integer("seeds", &seeds, "trials per object (seeds base, base+1, ...)",
              NumberRange::Closed(1, 1000));
  cmd.Seed("seed", &seed, "base seed");
  cmd.Choice("scene-kind", &kind, "'gantry' (light, for tables) or 'arm' (the UR-10 scenes)",
             {"gantry", "arm"});
  AddLawOptions(&cmd, &law);
  cmd.Integer("threads", &threads, "worker threads", NumberRange::Closed(1, 256));
  cmd.OutputDir("out", &out_dir, "output directory (scenes in OUT/scenes)");
  cmd.Flag("write-only", &write_only, "only write the scenes");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Check([&law]() { return law.Validate(); });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  std::vector<ObjectSpec> specs;
  if (names == "all") {
    specs = AllObjects();
  } else {
    size_t start = 0;
    for (;;) {
      const size_t comma = names.find(',', start);
      const std::string name = names.substr(start, comma == std::string::npos ? std::string::npos
                                                                               : comma - start);
      ObjectSpec s = ObjectByName(name);
      if (s.name.empty()) {
        return cmd.Fail("--objects: unknown object '" + name + "' in '" + names +
                        "' (names: disk_d02..disk_d14, disk_r35, hole_d02..hole_d14, corner_aNNN "
                        "(1-359), volute, semicircle_strip, semisquare_strip, fillet)");
      }
      for (const ObjectSpec& earlier : specs) {
        if (earlier.name == s.name) return cmd.Fail("--objects: '" + name + "' is listed twice");
      }
      specs.push_back(s);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  const std::filesystem::path out = out_dir;
  const std::string scene_dir = (out / "scenes").string();
  std::string error;
  for (const ObjectSpec& s : specs) {
    if (!WriteObjectFiles(s, scene_dir, SourceDir(), &error)) {
      std::fprintf(stderr, "ssc objects: %s\n", error.c_str());
      return 1;
    }
  }
  std::printf("wrote %zu objects' scenes into %s\n", specs.size(), scene_dir.c_str());
  // Contours (for plots): one CSV per object, points in world metres.
  const std::string paths_dir = (out / "paths").string();
  std::filesystem::create_directories(paths_dir);
  for (const ObjectSpec& s : specs) {
    std::ofstream c(std::filesystem::path(paths_dir) / (s.name + "_contour.csv"));
    c << "x_m,y_m,closed\n";
    for (const Point2& q : s.outline) c << q[0] << ',' << q[1] << ',' << s.closed() << '\n';
  }
  if (write_only) return 0;

  struct Job {
    size_t object;
    std::uint64_t seed;
  };
  std::vector<Job> jobs;
  for (size_t i = 0; i < specs.size(); ++i) {
    for (long k = 0; k < seeds; ++k) jobs.push_back({i, static_cast<std::uint64_t>(seed + k)});
  }
  std::vector<ObjectTrialRow> rows(jobs.size());
  std::atomic<size_t> next{0};
  std::mutex print_mutex;
  auto worker = [&]() {
    for (size_t j = next++; j < jobs.size(); j = next++) {
      const ObjectSpec& spec = specs[jobs[j].object];
      const std::string scene = (std::filesystem::path(scene_dir) /
                                 (kind == "gantry" ? ObjectFileNames(spec.name).gantry_scene
                                                   : ObjectFileNames(spec.name).arm_scene)).string();
      std::string load_error;
      ModelPtr model = LoadModel(scene, &load_error);
      if (!model) {
        rows[j].object = spec.name;
        rows[j].kind = ObjectKindName(spec.kind);
        rows[j].seed = jobs[j].seed;
        rows[j].result.outcome = Outcome::kUnstable;
        rows[j].result.detail = load_error;
      } else {
        rows[j] = RunObjectTrial(model.get(), spec, law, jobs[j].seed, true);
        // The cup-centre path (follow phase), for the plots; the log itself is not kept.
        std::ofstream path(std::filesystem::path(paths_dir) /
                           (spec.name + "_s" + std::to_string(jobs[j].seed) + ".csv"));
        path << "x_m,y_m\n";
        for (const TrialLogRow& l : rows[j].result.log) {
          if (l.phase == TrialPhase::kFollow) path << l.tool_m[0] << ',' << l.tool_m[1] << '\n';
        }
        if (spec.kind != ObjectKind::kFillet) rows[j].result.log.clear();
      }
      std::lock_guard<std::mutex> lock(print_mutex);
      std::printf("  %-18s seed %-3llu %-11s end %.1f (%s) %.1f s wall\n", spec.name.c_str(),
                  static_cast<unsigned long long>(jobs[j].seed), OutcomeName(rows[j].result.outcome),
                  spec.closed() ? rows[j].end_swept_deg : rows[j].end_arc_mm,
                  spec.closed() ? "deg swept" : "mm along the edge",
                  rows[j].result.wall_time_s);
      std::fflush(stdout);
    }
  };
  std::vector<std::thread> pool;
  for (long t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();

  std::filesystem::create_directories(out);
  std::ofstream table(out / "objects.csv");
  table << ObjectTableHeader() << '\n';
  for (const ObjectTrialRow& r : rows) table << ObjectTableRow(r) << '\n';
  table.close();
  std::printf("wrote %s\n", (out / "objects.csv").c_str());
  for (const ObjectTrialRow& r : rows) {
    if (r.kind == "fillet" && !r.result.log.empty()) {
      std::ofstream(out / "fillet_profile.csv") << FilletProfileCsv(r);
      std::printf("fillet (seed %llu): %s at %.1f mm along the edge, fillet radius %.2f mm; "
                  "wrote %s\n", static_cast<unsigned long long>(r.seed), OutcomeName(r.result.outcome),
                  r.end_arc_mm, r.end_fillet_radius_mm, (out / "fillet_profile.csv").c_str());
      break;
    }
  }
  if (!no_plot) {
    const std::string png = (out / "objects.png").string();
    if (RunPlotScript("plot_objects.py", {(out / "objects.csv").string(), paths_dir, png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
