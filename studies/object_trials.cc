#include "studies/object_trials.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

#include "common/csv_cell.h"
#include "geometry/dimensions.h"
#include "runtime/guarded_trial.h"

namespace ssc {

bool ObjectSceneKindByName(const std::string& name, ObjectSceneKind* kind, std::string* error) {
  for (ObjectSceneKind k : {ObjectSceneKind::kGantry, ObjectSceneKind::kArm, ObjectSceneKind::kFlex,
                            ObjectSceneKind::kAuto}) {
    if (name == ObjectSceneKindName(k)) {
      *kind = k;
      return true;
    }
  }
  *error = "unknown scene kind '" + name + "' (valid: " + kObjectSceneKindNames + ")";
  return false;
}

const char* ObjectSceneKindName(ObjectSceneKind kind) {
  switch (kind) {
    case ObjectSceneKind::kArm:
      return "arm";
    case ObjectSceneKind::kFlex:
      return "flex";
    case ObjectSceneKind::kAuto:
      return "auto";
    case ObjectSceneKind::kGantry:
      break;
  }
  return "gantry";
}

bool FlexTierDisagrees(const ObjectSpec& spec, double step_mm) {
  // Measured with the real skirt, pressed to the preload where it lands, against the segment lip
  // on the same seeds (docs/flex_objects.md, "Which tier --scene-kind auto runs"). At the
  // published 0.5 mm every corner, the disks and holes, the volute, the semicircle strip and the
  // fillet end with the same outcomes. The semi-square strip does not: the skirt, 23 mm across,
  // stalls on top of its 18 mm half-square, where the segment lip's 11 mm throat goes on.
  if (spec.kind == ObjectKind::kSemisquareStrip) return true;
  // Past kCrimpFreeStepMm a step can drive the skirt's stretch over a concave corner's notch
  // into the far wall and fold it under the cup (the crimp, docs/flex_skirt.md): a failure the
  // segment lip cannot have.
  return spec.kind == ObjectKind::kCorner && spec.param > 180.0 && step_mm > kCrimpFreeStepMm;
}

ObjectSceneKind ObjectTier(ObjectSceneKind kind, const ObjectSpec& spec, double step_mm) {
  if (kind != ObjectSceneKind::kAuto) return kind;
  return FlexTierDisagrees(spec, step_mm) ? ObjectSceneKind::kFlex : ObjectSceneKind::kGantry;
}

std::string ObjectSceneFile(const ObjectSpec& spec, ObjectSceneKind kind, double step_mm) {
  const ObjectFiles files = ObjectFileNames(spec.name);
  switch (ObjectTier(kind, spec, step_mm)) {
    case ObjectSceneKind::kArm:
      return files.arm_scene;
    case ObjectSceneKind::kFlex:
      return files.flex_scene;
    case ObjectSceneKind::kGantry:
    case ObjectSceneKind::kAuto:  // resolved above
      break;
  }
  return files.gantry_scene;
}

ObjectSceneKind ObjectSceneKindOfTier(const RigTier& tier) {
  switch (tier.kind) {
    case RigKind::kArm:
      return ObjectSceneKind::kArm;
    case RigKind::kFlex:
      return ObjectSceneKind::kFlex;
    default:
      break;
  }
  return ObjectSceneKind::kGantry;
}

bool ObjectSceneKindOfScene(const std::string& scene, ObjectSceneKind* kind, std::string* error) {
  const RigTier* tier = RigTierOfScene(scene);
  if (tier == nullptr || *tier->probe == '\0') {
    *error = "scene '" + scene + "' is not a disk tier a test object can run in (" +
             RigDiskTierNames() + ": runtime/rig.h)";
    return false;
  }
  *kind = ObjectSceneKindOfTier(*tier);
  return true;
}

ObjectSceneTemplates RigObjectSceneTemplates() {
  return {RigObjectTemplate(RigKind::kArm).scene, RigObjectTemplate(RigKind::kGantry).scene,
          RigObjectTemplate(RigKind::kFlex).scene};
}

TrialConfig ObjectTrialConfig(const ObjectSpec& spec, TrialConfig base, const StallRule& stall) {
  TrialConfig c = std::move(base);
  const ContourLawParams& law = c.law;
  const ObjectTrialSetup& setup = spec.trial;
  TrialTarget& t = c.target;
  t = TrialTarget();  // the object's, not the disk's
  t.approach = setup.landing_xy_m;
  t.start = setup.start_xy_m;
  t.goal = setup.goal;
  const bool closed = setup.goal.kind == TrialGoal::Kind::kSweptAngle;
  // Radial metrics (r_mean, dr, sigma_r) only mean something round a disk.
  t.disk_radius_m = spec.kind == ObjectKind::kDisk ? 0.5e-3 * spec.param : 0.0;
  t.surface_top_z_m = setup.surface_top_z_m;
  t.edge = std::make_shared<const ContourPath>(spec.edge);
  // Expected speed: the realised fraction of each step per control period.
  const double smoothing_s = std::max(1e-3, c.servo.smoothing_s);
  const double speed_m_s =
      law.step_mm * 1e-3 * (1 - std::exp(-c.control_period_s / smoothing_s)) / c.control_period_s;
  const double path_m =
      closed ? spec.edge.Length() : std::max(0.01, setup.goal.goal_arc_m - setup.start_arc_m);
  c.timeout_s = std::min(3600.0, 30.0 + 2.5 * path_m / speed_m_s);
  // Held in place, its outcome is decided: the stall rule ends it (docs/objects.md, "Outcomes").
  c.thresholds.stall_mm = stall.stall_mm;
  c.thresholds.stall_window_s = stall.window_s;
  return c;
}

ObjectTrialRow RunObjectTrial(const mjModel* model, const ObjectSpec& spec,
                              const ContourLawParams& law, const RobotEffectsParams& effects,
                              std::uint64_t seed, bool keep_log, const ControllerChoice& controller,
                              const StallRule& stall) {
  ObjectTrialRow row;
  row.object = spec.name;
  row.kind = ObjectKindName(spec.kind);
  row.param = spec.param;
  row.seed = seed;
  TrialConfig base;
  base.law = law;
  base.seed = seed;
  base.effects = effects;
  base.controller = controller;
  row.result =
      RunGuardedTrial(model, ObjectTrialConfig(spec, base, stall), nullptr, nullptr, keep_log);
  const double steps = row.result.sim_time_s / model->opt.timestep;
  row.step_cost_us = steps > 0 ? row.result.wall_time_s / steps * 1e6 : 0;
  row.approach_compression_mm = (spec.trial.surface_top_z_m - row.result.hold_height_m) * 1e3;
  if (spec.closed()) {
    row.end_swept_deg = row.result.swept_deg;
  } else {
    row.end_arc_mm = row.result.end_arc_mm;
    if (spec.kind == ObjectKind::kFillet) {
      row.end_fillet_radius_mm = FilletRadius(row.result.end_arc_mm * 1e-3) * 1e3;
    }
  }
  return row;
}

std::string ObjectTableHeader() {
  return "object,kind,param,seed,outcome,contour_mean_mm,contour_max_mm,end_arc_mm,"
         "end_swept_deg,end_fillet_radius_mm,s_mm,follow_s,speed_mm_s,iterations,step_cost_us,"
         "approach_compression_mm,tier,detail";
}

std::string ObjectTableRow(const ObjectTrialRow& r) {
  // The numbers fit the buffer; the free-text detail goes after it, whole.
  char buf[512];
  std::snprintf(
      buf, sizeof(buf), "%s,%s,%g,%llu,%s,%.3f,%.3f,%.2f,%.2f,%.2f,%.1f,%.1f,%.2f,%d,%.1f,%.3f,%s,",
      r.object.c_str(), r.kind.c_str(), r.param, static_cast<unsigned long long>(r.seed),
      OutcomeName(r.result.outcome), r.result.metrics.contour_mean_mm,
      r.result.metrics.contour_max_mm, r.end_arc_mm, r.end_swept_deg, r.end_fillet_radius_mm,
      r.result.metrics.s_mm, r.result.follow_time_s, r.result.metrics.speed_mm_s,
      r.result.iterations, r.step_cost_us, r.approach_compression_mm, r.tier.c_str());
  return buf + CsvCell(r.result.detail);
}

std::string FilletProfileCsv(const ObjectTrialRow& row) {
  std::ostringstream os;
  os << "x_mm,fillet_radius_mm,pbar_pa,diff_pa,y_mm\n";
  for (const TrialLogRow& l : row.result.log) {
    if (!l.iteration || l.phase != TrialPhase::kFollow) continue;
    const double x = l.tool_m[0] - kWorkspaceX;  // along the edge from its sharp end
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%.2f,%.3f,%.2f,%.2f,%.3f\n", x * 1e3,
                  FilletRadius(std::max(0.0, x)) * 1e3, l.pbar_pa, std::hypot(l.dpx_pa, l.dpy_pa),
                  (l.tool_m[1] - kWorkspaceY) * 1e3);
    os << buf;
  }
  return os.str();
}

}  // namespace ssc
