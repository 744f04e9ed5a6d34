#include "runtime/rig.h"

#include <filesystem>
#include <system_error>

#include "common/tool_names.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"

namespace ssc {

const char* RigKindName(RigKind kind) {
  static constexpr const char* kNames[] = {"arm", "gantry", "flex", "replay", "probe"};
  return kNames[static_cast<int>(kind)];
}

const std::vector<RigTier>& RigTiers() {
  using K = RigKind;
  using U = RigUse;
  static const std::vector<RigTier> tiers = {
      {"arm", "disk_benchmark", K::kArm, 0.002, "probe", 1.0, true, U::kReference,
       "UR-10, 16-segment lip (the reference)"},
      {"gantry", "disk_benchmark_gantry", K::kGantry, 0.002, "probe", 1.0, true, U::kNone,
       "gantry, 16-segment lip"},
      {"light", "disk_benchmark_light", K::kGantry, 0.002, "probe", 1.0, false, U::kNone,
       "gantry, single-point lip contacts, rigid carrier"},
      {"fast", "disk_benchmark_fast", K::kGantry, 0.004, "probe", 1.0, false, U::kTrial,
       "the light tier at a 4 ms step"},
      {"flex", "disk_benchmark_flex", K::kFlex, 0.002, "probe_flex", 0.3, true, U::kNone,
       "gantry, the lip a flex skirt MuJoCo deforms"},
      {"replay", "disk_replay", K::kReplay, 0.002, "", 0, false, U::kReplay,
       "the cup on a mocap body replaying a robot log"},
      {"probe", "probe_edge", K::kProbe, 0.001, "", 0, false, U::kProbe,
       "the cup on a mocap body over a straight edge"},
      {"probe_flex", "probe_edge_flex", K::kProbe, 0.001, "", 0, false, U::kNone,
       "the flex-lip cup on a free body over a straight edge"},
  };
  return tiers;
}

const RigTier& RigTierFor(RigUse use) {
  if (use == RigUse::kNone) use = RigUse::kTrial;
  for (const RigTier& t : RigTiers()) {
    if (t.default_for == use) return t;
  }
  return RigTiers().front();  // unreachable: every use has a row (tests/runtime/rig_test.cc)
}

const char* DefaultScene() { return RigTierFor(RigUse::kTrial).scene; }

const RigTier* RigTierNamed(const std::string& name) {
  for (const RigTier& t : RigTiers()) {
    if (name == t.name) return &t;
  }
  return nullptr;
}

const RigTier* RigTierOfScene(const std::string& scene) {
  namespace fs = std::filesystem;
  for (const RigTier& t : RigTiers()) {
    if (scene == t.scene || scene == std::string(t.scene) + ".xml") return &t;
  }
  const fs::path path = ResolveScenePath(scene);
  std::error_code ec;
  for (const RigTier& t : RigTiers()) {
    const fs::path file = fs::path(ResourceDir()) / "scenes" / (std::string(t.scene) + ".xml");
    if (fs::equivalent(path, file, ec)) return &t;
  }
  return nullptr;
}

const RigTier& RigObjectTemplate(RigKind kind) {
  for (const RigTier& t : RigTiers()) {
    if (t.object_template && t.kind == kind) return t;
  }
  return RigTierFor(RigUse::kReference);  // unreachable for arm, gantry, flex (rig_test)
}

std::string RigDiskTierNames() {
  std::string names;
  for (const RigTier& t : RigTiers()) {
    if (*t.probe != '\0') names += (names.empty() ? "" : ", ") + std::string(t.name);
  }
  return names;
}

std::string RigBinding::BindSensors(const mjModel* m, mjData* d) {
  std::string why;
  const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m, d, &why);
  if (sensor == nullptr) return why;
  tool_site = sensor->site_id();
  pressure_instance = sensor->instance();
  pressure_adr = sensor->sensor_adr();
  max_press_m = sensor->config().lip_max_press_m;
  force_sensor = mj_name2id(m, mjOBJ_SENSOR, kToolForceSensorName);
  if (force_sensor < 0 || m->sensor_type[force_sensor] != mjSENS_FORCE) {
    return std::string("scene has no force sensor named '") + kToolForceSensorName +
           "' (the F/T transducer of models/ssc_tool.xml, attached with prefix \"" +
           kToolAttachPrefix + "\")";
  }
  force_adr = m->sensor_adr[force_sensor];
  torque_sensor = mj_name2id(m, mjOBJ_SENSOR, kToolTorqueSensorName);
  torque_adr = torque_sensor >= 0 ? m->sensor_adr[torque_sensor] : -1;
  return "";
}

std::string RigBinding::Bind(const mjModel* m, mjData* d) {
  if (std::string e = BindSensors(m, d); !e.empty()) return e;
  servo = MakeToolServo(m);
  if (!servo) return "scene has neither a gantry (gantry_x/y/z) nor a UR-10 to move the tool";
  return "";
}

void RigBinding::Reset(const mjModel* m, mjData* d, std::uint64_t seed) const {
  if (m->nkey > 0) {
    mj_resetDataKeyframe(m, d, 0);
  } else {
    mj_resetData(m, d);
  }
  SetChamberPressureRunSeed(m, d, pressure_instance, seed);
  mj_forward(m, d);
}

}  // namespace ssc
