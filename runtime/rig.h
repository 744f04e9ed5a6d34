// The rig: which scene a trial runs in and how a loaded scene is bound to the trial's instruments.
//
// The tiers are the scenes under scenes/, named here and nowhere else: every command, the Python
// API, the Gym env and the SIL take a scene through this table (by tier scene name or a path),
// and the default when none is named is DefaultScene() for every entry point. What a tier is
// (arm, gantry, flex, replay, probe) comes from this table, never from a file's name.
//
// The binding (RigBinding) finds the tool site, the chamber pressure sensor, the F/T sensors and
// the servo that moves the tool in a compiled scene, and resets the scene to its keyframe with a
// seeded pressure sensor: the one home for what ContourTrial and the SIL plant both need.
#ifndef SSC_RUNTIME_RIG_H_
#define SSC_RUNTIME_RIG_H_

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/tool_servo.h"

namespace ssc {

// What a scene holds: the cup on the UR-10 arm, on a gantry, on a gantry with the flex skirt lip;
// the cup on a mocap body replaying a robot log; the cup on a mocap body over a straight edge.
enum class RigKind { kArm, kGantry, kFlex, kReplay, kProbe };
const char* RigKindName(RigKind kind);

// The entry points a tier is the default of when no scene is named.
enum class RigUse {
  kNone,
  kTrial,      // every trial command and API: trial, view, sweep, validate, calibrate, tune,
               // charts, stability, objects' disk, equivalence's candidate, compare's loop,
               // run_trial, SteppedTrial, SilPlant, the Gym env, the SIL runner
  kReference,  // the reference twin: equivalence's reference, the charts' arm rows
  kReplay,     // compare's replay of a robot log
  kProbe,      // ssc probe's straight edge
};

struct RigTier {
  const char* name;   // the tier's name (ssc charts --tiers)
  const char* scene;  // its scene: scenes/<scene>.xml
  RigKind kind;
  double timestep_s;      // the scene's time step (a test holds the file to it)
  const char* probe;      // disk tiers: the tier name of its straight-edge probe ("" otherwise)
  double probe_press_mm;  // the lip's press in that probe: what the tier's approach gives
  // Test objects' scenes of this kind are written from this scene (one per kind arm, gantry,
  // flex).
  bool object_template;
  RigUse default_for;
  const char* what;  // one line for tables and --help
};

// Every tier, disk tiers first (arm, gantry, light, fast, flex), then replay, probe, probe_flex.
const std::vector<RigTier>& RigTiers();
// The tier that is the default for `use` (kNone: the trial default).
const RigTier& RigTierFor(RigUse use);
// The scene every trial entry point runs when no scene is named (the fast tier:
// docs/scenes.md, no different from the arm by `ssc equivalence`).
const char* DefaultScene();
// The tier named `name` (tier name, not scene), or nullptr.
const RigTier* RigTierNamed(const std::string& name);
// The tier a scene argument is: a tier's scene name (with or without ".xml") or a path to a tier's
// file under the resource dir's scenes/. nullptr for any other scene (a user's MJCF, an object).
const RigTier* RigTierOfScene(const std::string& scene);
// The scene test objects of `kind` (arm, gantry or flex) are written from.
const RigTier& RigObjectTemplate(RigKind kind);
// "arm, gantry, light, fast, flex" (the disk tiers) for messages.
std::string RigDiskTierNames();

// A compiled scene bound to the trial's instruments. Bind fills every field or says what the
// scene lacks; the indices stay valid for the model's life.
struct RigBinding {
  int tool_site = -1;          // the lip plane's centre (the pressure sensor's site)
  int pressure_instance = -1;  // the ssc.chamber_pressure plugin instance
  int pressure_adr = -1;       // its four chamber vacuums in sensordata, Pa
  int force_sensor = -1;       // F/T force (kToolForceSensorName), N
  int force_adr = -1;
  int torque_sensor = -1;  // F/T torque (kToolTorqueSensorName); -1 when the scene has none
  int torque_adr = -1;     // its values in sensordata, N m; -1 when the scene has none
  double max_press_m = 0;  // the tool's deepest press below a surface (lip_max_press_mm)
  std::unique_ptr<ToolServo> servo;  // the gantry's or the arm's

  // "" when bound; else what the scene lacks (no pressure sensor, no F/T force sensor, nothing
  // that moves the tool).
  std::string Bind(const mjModel* m, mjData* d);
  // The sensors alone, for scenes that move the tool otherwise (a replay's mocap body).
  std::string BindSensors(const mjModel* m, mjData* d);
  // The seeded reset every run starts from: keyframe 0 (the model's defaults without one), the
  // pressure sensor's run seed `seed`, mj_forward. The servo is not bound here (Init after it).
  void Reset(const mjModel* m, mjData* d, std::uint64_t seed) const;
};

}  // namespace ssc

#endif  // SSC_RUNTIME_RIG_H_
