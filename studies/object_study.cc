#include "studies/object_study.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/output_file.h"
#include "common/strict_number.h"
#include "objects/object_mjcf.h"
#include "runtime/guarded_trial.h"
#include "runtime/mujoco_model.h"
#include "studies/jobs/job_runner.h"
#include "studies/object_trials.h"
#include "studies/sweep_io.h"

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

namespace {

std::string RowKey(const std::string& object, std::uint64_t seed) {
  return object + " seed " + std::to_string(seed);
}

// The options that define the table's rows: resuming with other ones would mix their rows. The
// object scenes are written from the code each run; they and every file they pull in (the tool
// and arm models, ...) stand for the compiled models: the files in the scenes folder as one hash,
// each other file under its own key, so that a refusal names the file that changed.
SweepManifest ObjectManifest(const ObjectStudySpec& spec, const std::string& scene_dir) {
  std::string names, scenes;
  std::map<std::string, std::string> pulled_in;
  const fs::path dir = fs::absolute(scene_dir).lexically_normal();
  for (const ObjectSpec& s : spec.objects) {
    names += (names.empty() ? "" : ",") + s.name;
    for (const auto& [path, hash] :
         SceneFileHashes((dir / ObjectSceneFile(s, spec.scene_kind, spec.law.step_mm)).string())) {
      const fs::path inside = fs::path(path).lexically_relative(dir);
      if (!inside.empty() && *inside.begin() != "..") {
        scenes += inside.string() + " " + hash + "\n";
      } else {
        pulled_in["file " + path] = hash;
      }
    }
  }
  char hash[32];
  std::snprintf(hash, sizeof(hash), "%016llx",
                static_cast<unsigned long long>(Fnv1a64(scenes.data(), scenes.size())));
  SweepManifest m = {{"csv_columns", ObjectTableHeader()},
                     {"objects", names},
                     {"seeds", std::to_string(spec.seeds)},
                     {"seed", std::to_string(spec.seed)},
                     {"scene_kind", ObjectSceneKindName(spec.scene_kind)},
                     {"scenes_hash", hash},
                     {"pref_pa", FormatNumber(spec.law.p_ref_pa)},
                     {"beta", FormatNumber(spec.law.beta)},
                     {"step_mm", FormatNumber(spec.law.step_mm)},
                     {"effects", FormatRobotEffects(spec.effects)},
                     {"stall_mm", FormatNumber(spec.stall.stall_mm)},
                     {"stall_window_s", FormatNumber(spec.stall.window_s)}};
  if (!spec.controller.IsPublished()) m["controller"] = spec.controller.Text();
  m.insert(pulled_in.begin(), pulled_in.end());
  return m;
}

// A row of an earlier run: its key when it can be one of this run's finished trials.
std::string CheckObjectRow(const ObjectStudySpec& spec, const std::vector<std::string_view>& f,
                           std::string* why) {
  // ObjectTableHeader(): object,kind,param,seed,outcome,...,tier (17),detail
  const std::string object(f[0]), seed_text(f[3]), outcome(f[4]), tier(f[16]);
  const ObjectSpec* spec_of = nullptr;
  for (const ObjectSpec& s : spec.objects) spec_of = s.name == object ? &s : spec_of;
  double seed = 0;
  std::string e;
  bool finished = false;
  for (Outcome o = Outcome::kSuccess; o <= Outcome::kControllerFault;
       o = static_cast<Outcome>(static_cast<int>(o) + 1)) {
    finished = finished || outcome == OutcomeName(o);
  }
  if (spec_of == nullptr) {
    *why = "object '" + object + "' is not one of this run's";
  } else if (!ParseNumber(seed_text,
                          NumberRange::Whole(static_cast<double>(spec.seed),
                                             static_cast<double>(spec.seed) + spec.seeds - 1),
                          &seed, &e)) {
    *why = "seed '" + seed_text + "' is not one of this run's (" + e + ")";
  } else if (!finished) {
    *why = "outcome '" + outcome + "' is not a finished trial's";
  } else if (tier != ObjectSceneKindName(ObjectTier(spec.scene_kind, *spec_of, spec.law.step_mm))) {
    *why = "tier '" + tier + "' is not the one this run gives " + object;
  } else {
    return RowKey(object, static_cast<std::uint64_t>(seed));
  }
  return "";
}

// The fillet's line from its table row (outcome, end_arc_mm, end_fillet_radius_mm).
std::string FilletLine(const std::string& row) {
  std::vector<std::string> f;
  std::stringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
  if (f.size() < 10) return "";
  return "fillet (seed " + f[3] + "): " + f[4] + " at " + f[7] +
         " mm along the edge, fillet radius " + f[9] + " mm";
}

struct ObjectJob {
  size_t object;
  std::uint64_t seed;
};

// One job: its table row, after a line for the progress report (and the fillet's line).
std::string RunObjectJob(const ObjectStudySpec& spec, const ObjectJob& job,
                         const std::string& scene_dir, const std::string& paths_dir,
                         const fs::path& fillet_profile) {
  const ObjectSpec& object = spec.objects[job.object];
  const ObjectSceneKind tier = ObjectTier(spec.scene_kind, object, spec.law.step_mm);
  const std::string scene =
      (fs::path(scene_dir) / ObjectSceneFile(object, tier, spec.law.step_mm)).string();
  std::string load_error;
  ModelPtr model = LoadModel(scene, &load_error);
  ObjectTrialRow row;
  if (!model) {
    row.object = object.name;
    row.kind = ObjectKindName(object.kind);
    row.seed = job.seed;
    row.result.outcome = Outcome::kUnstable;
    row.result.detail = load_error;
  } else {
    row = RunObjectTrial(model.get(), object, spec.law, spec.effects, job.seed, true,
                         spec.controller, spec.stall);
    // The cup-centre path (follow phase), for the plots; the log itself is not kept.
    // Plot inputs, each written whole; a failure is reported and the trial's row kept.
    OutputFile path(
        (fs::path(paths_dir) / (object.name + "_s" + std::to_string(job.seed) + ".csv")).string());
    path.stream() << "x_m,y_m\n";
    for (const TrialLogRow& l : row.result.log) {
      if (l.phase == TrialPhase::kFollow) {
        path.stream() << l.tool_m[0] << ',' << l.tool_m[1] << '\n';
      }
    }
    std::string write_error;
    if (!path.Commit(&write_error) ||
        (object.kind == ObjectKind::kFillet && job.seed == spec.seed &&
         !WriteWholeFile(fillet_profile.string(), FilletProfileCsv(row), &write_error))) {
      std::fprintf(stderr, "ssc objects: %s\n", write_error.c_str());
    }
  }
  if (row.result.interrupted) return "";  // not a finished trial: no row
  row.tier = ObjectSceneKindName(tier);
  char line[256];
  std::snprintf(line, sizeof(line), "  %-18s seed %-3llu %-11s end %.1f (%s) %.1f s wall",
                object.name.c_str(), static_cast<unsigned long long>(job.seed),
                OutcomeName(row.result.outcome),
                object.closed() ? row.end_swept_deg : row.end_arc_mm,
                object.closed() ? "deg swept" : "mm along the edge", row.result.wall_time_s);
  if (object.kind == ObjectKind::kFillet && job.seed == spec.seed && model) {
    char fillet[256];
    std::snprintf(fillet, sizeof(fillet),
                  "fillet (seed %llu): %s at %.1f mm along the edge, fillet radius %.2f mm",
                  static_cast<unsigned long long>(row.seed), OutcomeName(row.result.outcome),
                  row.end_arc_mm, row.end_fillet_radius_mm);
    return std::string(line) + '\n' + ObjectTableRow(row) + '\n' + fillet;
  }
  return std::string(line) + '\n' + ObjectTableRow(row);
}

// Opens the table for resuming; the rows it keeps fill `table_rows` (their trials are not run).
bool ResumeObjectTable(const ObjectStudySpec& spec, const std::vector<ObjectJob>& jobs,
                       const std::string& scene_dir, const fs::path& fillet_profile,
                       ResumableTable* table, std::vector<std::string>* table_rows,
                       ObjectStudySummary* summary, std::string* error) {
  auto check = [&spec](const std::vector<std::string_view>& f, std::string* why) {
    return CheckObjectRow(spec, f, why);
  };
  if (!table->Open(summary->table_csv, ObjectTableHeader(), ObjectManifest(spec, scene_dir), check,
                   "ssc objects", error)) {
    return false;
  }
  // Rows of an earlier run stand for their trials (their paths/ files were written with them).
  for (size_t j = 0; j < jobs.size(); ++j) {
    const ObjectSpec& object = spec.objects[jobs[j].object];
    (*table_rows)[j] = table->Kept(RowKey(object.name, jobs[j].seed));
    if ((*table_rows)[j].empty()) continue;
    ++summary->skipped;
    if (object.kind == ObjectKind::kFillet && jobs[j].seed == spec.seed &&
        fs::exists(fillet_profile)) {
      summary->fillet_line = FilletLine((*table_rows)[j]);
      summary->fillet_profile_csv = fillet_profile.string();
    }
  }
  return true;
}

}  // namespace

bool RunObjectStudy(const ObjectStudySpec& spec,
                    const std::function<void(const std::string&)>& progress,
                    ObjectStudySummary* summary, std::string* error) {
  const fs::path out = spec.out_dir;
  const std::string scene_dir = (out / "scenes").string();
  for (const ObjectSpec& s : spec.objects) {
    if (!WriteObjectFiles(s, scene_dir, SourceDir(), RigObjectSceneTemplates(), error))
      return false;
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

  std::vector<ObjectJob> jobs;
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
    // A flex step costs about 46 segment steps (docs/flex_cost.md): the flex trials start first.
    const double tier_weight =
        ObjectTier(spec.scene_kind, object, spec.law.step_mm) == ObjectSceneKind::kFlex ? 46.0
                                                                                        : 1.0;
    return tier_weight * ObjectTrialConfig(object, base).timeout_s;
  };
  set.run = [&](size_t j) {
    return RunObjectJob(spec, jobs[j], scene_dir, summary->paths_dir, fillet_profile);
  };
  std::vector<std::string> table_rows(jobs.size());
  const bool writer = JobRunnerRank() == 0;
  summary->table_csv = (out / "objects.csv").string();
  ResumableTable table;
  if (writer && !ResumeObjectTable(spec, jobs, scene_dir, fillet_profile, &table, &table_rows,
                                   summary, error)) {
    return false;
  }
  set.skip = [&](size_t j) { return !table_rows[j].empty(); };
  JobRunnerOptions options;
  options.threads = spec.threads;
  std::string write_error;
  ScopedTrialErrorGuard guard;  // a MuJoCo error ends its trial as unstable, not the study
  const JobRunStats stats = RunJobs(set, options, [&](size_t j, const std::string& result) {
    if (result.empty()) return;  // interrupted: no row
    const size_t a = result.find('\n'), b = result.find('\n', a + 1);
    table_rows[j] = result.substr(a + 1, b == std::string::npos ? b : b - a - 1);
    if (write_error.empty()) table.Append(table_rows[j], &write_error);
    if (b != std::string::npos) {
      summary->fillet_line = result.substr(b + 1);
      summary->fillet_profile_csv = fillet_profile.string();
    }
    if (progress) progress(result.substr(0, a));
  });
  if (!writer) return true;
  summary->trials = static_cast<int>(jobs.size());
  summary->interrupted = stats.interrupted;
  if (!write_error.empty()) {
    *error = write_error;
    return false;
  }
  std::vector<std::string> rows;
  for (const std::string& r : table_rows) {
    if (!r.empty()) rows.push_back(r);
  }
  summary->finished = static_cast<int>(rows.size());
  // Interrupted, the table holds the finished rows as they came; complete, the study's order.
  return summary->interrupted || table.Rewrite(rows, error);
}

}  // namespace ssc
