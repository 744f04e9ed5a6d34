// Contour-following trials on the test objects (the published primitive-geometry controller by
// default: P_ref 100 Pa, beta 2, dL 0.5 mm) and the table of their outcomes.
#ifndef SSC_STUDIES_OBJECT_TRIALS_H_
#define SSC_STUDIES_OBJECT_TRIALS_H_

#include <string>
#include <vector>

#include "objects/object_mjcf.h"
#include "objects/object_spec.h"
#include "runtime/rig.h"
#include "runtime/trial.h"

namespace ssc {

// The scene an object's trial runs in, picked by name in every command that runs objects
// (ssc objects/view --scene-kind, Python's scene): the light gantry with the 16-segment lip, the
// UR-10 with it, the gantry with the flex skirt lip (docs/pneumatics.md), or per object the
// tier its geometry needs (kAuto, ObjectTier).
enum class ObjectSceneKind { kGantry, kArm, kFlex, kAuto };
inline constexpr const char* kObjectSceneKindNames = "gantry, arm, flex, auto";
// False + *error naming the valid names for an unknown one.
bool ObjectSceneKindByName(const std::string& name, ObjectSceneKind* kind, std::string* error);
const char* ObjectSceneKindName(ObjectSceneKind kind);
// The longest law step at which the skirt was never seen to crimp at a concave corner (7.5 mm:
// 30 of 30 at the goal; at 10 mm it folds, docs/flex_skirt.md).
inline constexpr double kCrimpFreeStepMm = 7.5;
// Whether the flex skirt and the segment lip disagree on `spec` (its outcome, or where it is
// lost) when the law steps `step_mm`, from the measured evidence (docs/flex_objects.md, "Which
// tier --scene-kind auto runs").
bool FlexTierDisagrees(const ObjectSpec& spec, double step_mm);
// The tier an object runs in for `kind`: `kind` itself, except kAuto: the flex tier where the
// two tiers disagree at that step (FlexTierDisagrees), the gantry where they agree.
ObjectSceneKind ObjectTier(ObjectSceneKind kind, const ObjectSpec& spec, double step_mm);
// The object's scene file (no directory) of that kind (kAuto: ObjectTier's at `step_mm`).
std::string ObjectSceneFile(const ObjectSpec& spec, ObjectSceneKind kind, double step_mm);
// The object scene kind of a disk tier (runtime/rig.h: arm, gantry, light, fast, flex), from the
// rig's table.
ObjectSceneKind ObjectSceneKindOfTier(const RigTier& tier);
// The kind of the tier `scene` names (a tier's scene name or path); false + *error naming the
// disk tiers for any other scene.
bool ObjectSceneKindOfScene(const std::string& scene, ObjectSceneKind* kind, std::string* error);
// The scene templates objects' scenes are written from (WriteObjectFiles): the rig's.
ObjectSceneTemplates RigObjectSceneTemplates();

// The object trials' stall rule (TrialThresholds::stall_mm, stall_window_s; docs/objects.md,
// "Outcomes"): window 0 turns it off.
struct StallRule {
  double stall_mm = kObjectStallMm;
  double window_s = kObjectStallWindowS;
};

// Trial settings for an object: `base` (its law, seed, effects, loop and servo) with the target
// from the object's ObjectTrialSetup (landing and start points, goal) and exact edge (metrics,
// tracked arc position), a follow timeout from the edge length at the expected speed, and the
// stall rule.
TrialConfig ObjectTrialConfig(const ObjectSpec& spec, TrialConfig base,
                              const StallRule& stall = StallRule());

struct ObjectTrialRow {
  std::string object, kind;
  double param = 0;
  std::uint64_t seed = 0;
  TrialResult result;
  double end_arc_mm = -1;              // open contours: tracked arc position at the end, mm
  double end_swept_deg = 0;            // closed contours: swept angle at the end, deg (signed)
  double end_fillet_radius_mm = -1;    // fillet only: radius where tracking ended, mm
  double step_cost_us = 0;             // wall time per physics step of this trial
  double approach_compression_mm = 0;  // the lip plane below the top face after the approach
  std::string tier;                    // the scene kind it ran in (ObjectSceneKindName)
};

// Runs one object trial on `model` (a scene written by WriteObjectFiles) with `effects` (the
// robot effects; the twin's defaults are FittedRobotEffects()).
// `controller` decides while following (the published law by default).
ObjectTrialRow RunObjectTrial(const mjModel* model, const ObjectSpec& spec,
                              const ContourLawParams& law, const RobotEffectsParams& effects,
                              std::uint64_t seed, bool keep_log,
                              const ControllerChoice& controller = ControllerChoice(),
                              const StallRule& stall = StallRule());

std::string ObjectTableHeader();
std::string ObjectTableRow(const ObjectTrialRow& row);

// Along-edge profile of a logged fillet trial: x (mm from the sharp end), fillet radius (mm),
// mean P (Pa) and |(dPx, dPy)| (Pa) at every control iteration.
std::string FilletProfileCsv(const ObjectTrialRow& row);

}  // namespace ssc

#endif  // SSC_STUDIES_OBJECT_TRIALS_H_
