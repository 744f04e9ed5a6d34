#include "compare/comparison.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <vector>

#include "robotlog/plain_log.h"
#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

std::string Mm(double m) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f mm", m * 1e3);
  return buf;
}

std::string Point(const std::array<double, 3>& p) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "(%.4f, %.4f, %.4f) m", p[0], p[1], p[2]);
  return buf;
}

// A replayed cup that is not where the log shows it: at most of the samples where the log reads
// the object (mean vacuum above a tenth of its 90th percentile: a seal, or an edge followed from
// the landing on; a grasp's last samples are not the level) the replay holds less than a quarter
// of it. Such a
// comparison measures the frames, not the twin: "" when the replay agrees, else the warning
// naming the options that place the path.
std::string ReplayDisagreement(const ReplayComparison& c, const CompareOptions& o,
                               const std::string& log_frame) {
  auto mean = [](const std::array<double, 4>& p) { return 0.25 * (p[0] + p[1] + p[2] + p[3]); };
  std::vector<double> means;
  means.reserve(c.log_pa.size());
  for (const auto& p : c.log_pa) means.push_back(mean(p));
  if (means.empty()) return "";
  const auto at =
      means.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(means.size() - 1));
  std::nth_element(means.begin(), at, means.end());
  const double level = 0.1 * *at;
  if (!(level > 0)) return "";
  int reading = 0, lost = 0;
  for (size_t i = 0; i < c.log_pa.size(); ++i) {
    const double log_mean = mean(c.log_pa[i]);
    if (log_mean < level) continue;
    ++reading;
    if (mean(c.sim_pa[i]) < 0.25 * log_mean) ++lost;
  }
  if (reading < 10 || lost * 2 <= reading) return "";
  const std::string frames =
      log_frame == "scene"
          ? "and that the plain CSV's poses are in the scene frame (--log-frame and "
            "--object-pose place lab logs only)"
          : "--log-frame (" + log_frame + " now) and --object-pose";
  char buf[640];
  std::snprintf(buf, sizeof(buf),
                "the replay disagrees with the log: at %d of the %d samples where the log reads "
                "the object (mean vacuum above %.0f Pa) the replayed cup holds less than a "
                "quarter of it, so the replayed path is likely off the object. Check --tcp-offset "
                "(%.1f mm now; the lab's tool %.1f mm), %s",
                lost, reading, level, o.processing.tcp_offset_m * 1e3, kToolCentreOffsetM * 1e3,
                frames.c_str());
  return buf;
}

// The plain reader refuses a log without vacuum (robotlog/plain_log.h); the same for the lab's:
// a pump that never ran or a sensor unplugged leaves nothing to compare.
bool LabLogHasVacuum(const LoadedLog& loaded, const std::string& path, std::string* error) {
  double peak_pa = 0, peak_t_s = 0;
  for (size_t i = 0; i < loaded.log.p_pa.size(); ++i) {
    for (double p : loaded.log.p_pa[i]) {
      if (p > peak_pa) {
        peak_pa = p;
        peak_t_s = loaded.log.t_s[i];
      }
    }
  }
  if (peak_pa >= kPeakVacuumMinPa) return true;
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%.1f Pa (t = %.2f s)", peak_pa, peak_t_s);
  *error = path + ": the logged vacuum never exceeds " + buf +
           " above the in-air offset: the pump off or the sensor unplugged? A trial on an "
           "object reads more than " +
           std::to_string(static_cast<int>(kPeakVacuumMinPa)) + " Pa; there is nothing to compare";
  return false;
}

// The object in a lab log's frame: from --object-pose, else from the log itself, whose top needs
// the twin's lip depth at the logged force (the loop scene, loaded into *loop for the closed loop
// to reuse).
bool PlaceLabObject(const CompareOptions& o, const LoadedLog& loaded, double approach_force_n,
                    ModelPtr* loop, ComparisonSetup* s, std::string* error) {
  if (!o.object_pose.empty()) {
    s->object.known = true;
    s->object.x_m = o.object_pose[0];
    s->object.y_m = o.object_pose[1];
    s->object.top_z_m = o.object_pose[2];
    s->object.yaw_rad = o.object_pose.size() > 3 ? o.object_pose[3] * M_PI / 180 : 0.0;
    s->object.source = "--object-pose";
    return true;
  }
  *loop = LoadModel(ResolveScenePath(o.loop_scene), error);
  if (!*loop || !TwinContactDepth(loop->get(), approach_force_n, &s->contact_depth_m, error)) {
    *error = "lip depth at the approach force: " + *error;
    return false;
  }
  s->object = DiskPoseFromLog(loaded, s->contact_depth_m);
  return true;
}

// Moves a lab log into the scene frame: its object onto the nearest scene object.
void MoveLabLogIntoScene(const std::vector<SceneObject>& objects, LogFrame frame,
                         ComparisonSetup* s, ProcessedLog* scene_log) {
  ObjectPose where = s->object;
  if (!where.known) {  // which object: the nearest to the log's first tool position
    where.x_m = scene_log->tcp_m.front()[0];
    where.y_m = scene_log->tcp_m.front()[1];
  }
  s->scene_object = *NearestSceneObject(objects, frame, where);
  s->X_scene_log = SceneFromLog(frame, s->object, s->scene_object);
  TransformProcessedLog(s->X_scene_log, scene_log);
}

// The error for a cup that never comes within reach: the closest approach and the frames in use.
std::string OutOfReachError(const CompareOptions& o, const ComparisonSetup& s, bool lab) {
  std::string error = o.log_path + ": the cup never comes within reach (" + Mm(kCupReachM) +
                      ") of any object of " + o.scene + ": closest approach " +
                      Mm(s.reach.closest_m) + " to '" + s.reach.object +
                      "' at t = " + std::to_string(s.reach.t_s) + " s, tool centre at " +
                      Point(s.reach.tcp_m) + " in the scene frame. Frames: ";
  if (!lab) return error + "a plain CSV is taken as already in the scene frame; move it there.";
  return error + "log poses in " + LogFrameName(o.frame) +
         (s.object.known ? ", object pose from " + s.object.source
                         : ", no object pose (the base frame at the scene origin)") +
         ". Give the object's pose in the log's frame with --object-pose x,y,z[,yaw], "
         "or the frame with --log-frame base_link|base.";
}

// The twin's controller from the log's start on the loop scene's disk nearest to the replay's
// object (loop: the loop scene if already loaded).
bool RunClosedLoop(const CompareOptions& o, ModelPtr loop, const ProcessedLog& scene_log,
                   const LabRunArgs& args, TrialConfig loop_config, CompareResult* r,
                   std::string* error) {
  if (!loop) loop = LoadModel(ResolveScenePath(o.loop_scene), error);
  if (!loop) return false;
  const std::vector<SceneObject> loop_objects = FindSceneObjects(loop.get());
  if (loop_objects.empty()) {
    *error = o.loop_scene + ": no disk for the closed loop";
    return false;
  }
  ObjectPose at;
  at.x_m = r->setup.scene_object.x_m;
  at.y_m = r->setup.scene_object.y_m;
  const SceneObject& disk = *NearestSceneObject(loop_objects, LogFrame::kUrBase, at);
  loop_config.target.surface_top_z_m = disk.top_z_m;
  const double start_t =
      r->history.ran ? args.history.front().t_s + r->history.time_offset_s : -1.0;
  if (!CompareClosedLoop(loop.get(), scene_log, disk, start_t, loop_config, &r->closed, error)) {
    *error = "closed loop: " + *error;
    return false;
  }
  return true;
}

}  // namespace

bool RunComparison(const CompareOptions& o, CompareResult* r, std::string* error) {
  *r = CompareResult();
  LoadedLog loaded;
  LoadError load_error;
  if (!LoadLog(o.log_path, o.processing, &loaded, &load_error)) {
    *error = load_error.ToString();
    return false;
  }
  r->log_warnings = loaded.raw.warnings;
  const bool lab = loaded.format != LogFormat::kPlain;
  if (lab && !LabLogHasVacuum(loaded, o.log_path, error)) return false;
  ModelPtr model = LoadModel(ResolveScenePath(o.scene), error);
  if (!model) return false;
  const std::vector<SceneObject> objects = FindSceneObjects(model.get());
  if (objects.empty()) {
    *error = o.scene + ": the replay scene has no object the cup could touch";
    return false;
  }
  ComparisonSetup& s = r->setup;
  s.log_path = o.log_path;
  s.format = LogFormatName(loaded.format);
  s.log_frame = lab ? LogFrameName(o.frame) : "scene";
  const LabRunArgs& args = loaded.raw.args;
  std::string params;
  TrialConfig loop_config = ConfigFromArgs(args, o.loop_config, &params);
  if (o.override_law) {
    loop_config.law = o.loop_config.law;
    params = "the command line's P_ref, beta, dL; " + params;
  }
  ModelPtr loop;
  if (lab && !PlaceLabObject(o, loaded, loop_config.approach_force_n, &loop, &s, error)) {
    return false;
  }
  // A plain log is needed once, in the scene frame: moved, not copied (a 1M-row log is ~100 MB).
  ProcessedLog scene_log = lab ? loaded.log : std::move(loaded.log);
  if (lab) {
    MoveLabLogIntoScene(objects, o.frame, &s, &scene_log);
  } else {
    s.scene_object = objects.front();
  }
  s.reach = ClosestApproach(model.get(), objects, scene_log);
  if (!(s.reach.closest_m <= kCupReachM)) {
    *error = OutOfReachError(o, s, lab);
    return false;
  }
  // Without the closed loop nothing needs the scene-frame log after the replay: its series move
  // into the result.
  const bool replayed =
      o.closed_loop ? ReplayLog(model.get(), scene_log, o.processing.tcp_offset_m,
                                o.loop_config.effects.lip, &r->replay, error, o.progress)
                    : ReplayLogConsuming(model.get(), &scene_log, o.processing.tcp_offset_m,
                                         o.loop_config.effects.lip, &r->replay, error, o.progress);
  if (!replayed) return false;
  if (std::string w = ReplayDisagreement(r->replay, o, s.log_frame); !w.empty()) {
    r->log_warnings.push_back(w);
  }
  if (!args.history.empty()) {
    std::string why;
    if (!CompareHistory(args, loaded.log, r->replay, loop_config.law, &r->history, &why)) {
      r->history_warning = why;
    }
  }
  if (o.closed_loop) {
    if (!RunClosedLoop(o, std::move(loop), scene_log, args, loop_config, r, error)) return false;
    r->closed.parameters = params;
    r->closed.controller = loop_config.controller.Text();
  }
  return WriteComparisonReport(o.out_dir, s, r->replay, &r->history,
                               o.closed_loop ? &r->closed : nullptr, error);
}

}  // namespace ssc
