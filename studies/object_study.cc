#include "studies/object_study.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/output_file.h"
#include "objects/object_mjcf.h"
#include "runtime/mujoco_model.h"
#include "studies/job_runner.h"
#include "studies/object_trials.h"

namespace ssc {
namespace fs = std::filesystem;

bool ObjectsByNames(const std::string& names, std::vector<ObjectSpec>* objects,
                    std::string* error) {
  if (names == "all") {
    *objects = AllObjects();
    return true;
  }
  size_t start = 0;
  for (;;) {
    const size_t comma = names.find(',', start);
    const std::string name =
        names.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    ObjectSpec s = ObjectByName(name);
    if (s.name.empty()) {
      *error = "unknown object '" + name + "' in '" + names +
               "' (names: disk_d02..disk_d14, disk_r35, hole_d02..hole_d14, corner_aNNN "
               "(1-359), volute, semicircle_strip, semisquare_strip, fillet)";
      return false;
    }
    for (const ObjectSpec& earlier : *objects) {
      if (earlier.name == s.name) {
        *error = "'" + name + "' is listed twice";
        return false;
      }
    }
    objects->push_back(s);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

bool RunObjectStudy(const ObjectStudySpec& spec,
                    const std::function<void(const std::string&)>& progress,
                    ObjectStudySummary* summary, std::string* error) {
  const fs::path out = spec.out_dir;
  const std::string scene_dir = (out / "scenes").string();
  for (const ObjectSpec& s : spec.objects) {
    if (!WriteObjectFiles(s, scene_dir, SourceDir(), error)) return false;
  }
  // Contours (for plots): one CSV per object, points in world metres.
  summary->paths_dir = (out / "paths").string();
  fs::create_directories(summary->paths_dir);
  for (const ObjectSpec& s : spec.objects) {
    OutputFile c((fs::path(summary->paths_dir) / (s.name + "_contour.csv")).string());
    c.stream() << "x_m,y_m,closed\n";
    for (const Point2& q : s.outline) {
      c.stream() << q[0] << ',' << q[1] << ',' << s.closed() << '\n';
    }
    if (!c.Commit(error)) return false;
  }
  if (spec.write_only) return true;

  struct Job {
    size_t object;
    std::uint64_t seed;
  };
  std::vector<Job> jobs;
  for (size_t i = 0; i < spec.objects.size(); ++i) {
    for (int k = 0; k < spec.seeds; ++k) jobs.push_back({i, spec.seed + k});
  }
  const fs::path fillet_profile = out / "fillet_profile.csv";
  JobSet set;
  set.count = jobs.size();
  set.cost = [&](size_t j) {  // the follow timeout grows with the edge to follow
    TrialConfig base;
    base.law = spec.law;
    const ObjectSpec& object = spec.objects[jobs[j].object];
    // A flex step costs about 14 segment steps (docs/objects.md): the flex trials start first.
    const double tier_weight =
        ObjectTier(spec.scene_kind, object) == ObjectSceneKind::kFlex ? 14.0 : 1.0;
    return tier_weight * ObjectTrialConfig(object, base).timeout_s;
  };
  // One job: its table row, after a line for the progress report.
  set.run = [&](size_t j) {
    const ObjectSpec& object = spec.objects[jobs[j].object];
    const std::string scene =
        (fs::path(scene_dir) / ObjectSceneFile(object, spec.scene_kind)).string();
    std::string load_error;
    ModelPtr model = LoadModel(scene, &load_error);
    ObjectTrialRow row;
    if (!model) {
      row.object = object.name;
      row.kind = ObjectKindName(object.kind);
      row.seed = jobs[j].seed;
      row.result.outcome = Outcome::kUnstable;
      row.result.detail = load_error;
    } else {
      row = RunObjectTrial(model.get(), object, spec.law, spec.effects, jobs[j].seed, true,
                           spec.controller);
      // The cup-centre path (follow phase), for the plots; the log itself is not kept.
      // Plot inputs, each written whole; a failure is reported and the trial's row kept.
      OutputFile path((fs::path(summary->paths_dir) /
                       (object.name + "_s" + std::to_string(jobs[j].seed) + ".csv"))
                          .string());
      path.stream() << "x_m,y_m\n";
      for (const TrialLogRow& l : row.result.log) {
        if (l.phase == TrialPhase::kFollow) {
          path.stream() << l.tool_m[0] << ',' << l.tool_m[1] << '\n';
        }
      }
      std::string write_error;
      if (!path.Commit(&write_error) ||
          (object.kind == ObjectKind::kFillet && jobs[j].seed == spec.seed &&
           !WriteWholeFile(fillet_profile.string(), FilletProfileCsv(row), &write_error))) {
        std::fprintf(stderr, "ssc objects: %s\n", write_error.c_str());
      }
    }
    row.tier = ObjectSceneKindName(ObjectTier(spec.scene_kind, object));
    char line[256];
    std::snprintf(line, sizeof(line), "  %-18s seed %-3llu %-11s end %.1f (%s) %.1f s wall",
                  object.name.c_str(), static_cast<unsigned long long>(jobs[j].seed),
                  OutcomeName(row.result.outcome),
                  object.closed() ? row.end_swept_deg : row.end_arc_mm,
                  object.closed() ? "deg swept" : "mm along the edge", row.result.wall_time_s);
    if (object.kind == ObjectKind::kFillet && jobs[j].seed == spec.seed && model) {
      char fillet[256];
      std::snprintf(fillet, sizeof(fillet),
                    "fillet (seed %llu): %s at %.1f mm along the edge, fillet radius %.2f mm",
                    static_cast<unsigned long long>(row.seed), OutcomeName(row.result.outcome),
                    row.end_arc_mm, row.end_fillet_radius_mm);
      return std::string(line) + '\n' + ObjectTableRow(row) + '\n' + fillet;
    }
    return std::string(line) + '\n' + ObjectTableRow(row);
  };
  std::vector<std::string> table_rows(jobs.size());
  JobRunnerOptions options;
  options.threads = spec.threads;
  const JobRunStats stats = RunJobs(set, options, [&](size_t j, const std::string& result) {
    const size_t a = result.find('\n'), b = result.find('\n', a + 1);
    table_rows[j] = result.substr(a + 1, b == std::string::npos ? b : b - a - 1);
    if (b != std::string::npos) {
      summary->fillet_line = result.substr(b + 1);
      summary->fillet_profile_csv = fillet_profile.string();
    }
    if (progress) progress(result.substr(0, a));
  });
  if (JobRunnerRank() != 0) return true;
  summary->trials = static_cast<int>(jobs.size());
  summary->interrupted = stats.interrupted;
  summary->table_csv = (out / "objects.csv").string();
  OutputFile table(summary->table_csv);
  table.stream() << ObjectTableHeader() << '\n';
  for (const std::string& r : table_rows) {
    if (r.empty()) continue;  // not run: interrupted
    table.stream() << r << '\n';
    ++summary->finished;
  }
  return table.Commit(error);
}

}  // namespace ssc
