// The rig: its table of tiers against the scene files, and the binding every trial and the SIL
// plant take their instruments from.
#include "runtime/rig.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

ModelPtr LoadTier(const RigTier& t) {
  std::string error;
  ModelPtr m = LoadModel(ResolveScenePath(t.scene), &error);
  EXPECT_TRUE(m) << t.name << ": " << error;
  return m;
}

// What the compiled scene holds, as the table's kind says it.
RigKind KindOfModel(const mjModel* m) {
  const int probe = mj_name2id(m, mjOBJ_BODY, "probe");
  if (probe >= 0 && m->body_mocapid[probe] >= 0) {
    return mj_name2id(m, mjOBJ_GEOM, "plate") >= 0 ? RigKind::kProbe : RigKind::kReplay;
  }
  if (mj_name2id(m, mjOBJ_JOINT, "gantry_x") >= 0) {
    return m->nflex > 0 ? RigKind::kFlex : RigKind::kGantry;
  }
  return RigKind::kArm;
}

TEST(RigTest, EveryTierIsItsSceneFile) {
  for (const RigTier& t : RigTiers()) {
    ModelPtr m = LoadTier(t);
    if (!m) continue;
    EXPECT_DOUBLE_EQ(m->opt.timestep, t.timestep_s) << t.name;
    // The flex probe rides a free body (MuJoCo refuses a flex under a mocap body).
    if (t.kind != RigKind::kProbe || m->nflex == 0) {
      EXPECT_STREQ(RigKindName(KindOfModel(m.get())), RigKindName(t.kind)) << t.name;
    }
    if (*t.probe != '\0') {
      const RigTier* probe = RigTierNamed(t.probe);
      ASSERT_NE(probe, nullptr) << t.name;
      EXPECT_EQ(probe->kind, RigKind::kProbe) << t.name;
      EXPECT_GT(t.probe_press_mm, 0) << t.name;
    }
  }
}

TEST(RigTest, EveryUseAndObjectKindHasOneTier) {
  for (RigUse use : {RigUse::kTrial, RigUse::kReference, RigUse::kReplay, RigUse::kProbe}) {
    int rows = 0;
    for (const RigTier& t : RigTiers()) rows += t.default_for == use ? 1 : 0;
    EXPECT_EQ(rows, 1) << static_cast<int>(use);
    EXPECT_EQ(RigTierFor(use).default_for, use);
  }
  EXPECT_STREQ(DefaultScene(), "disk_benchmark_fast");
  EXPECT_EQ(RigTierFor(RigUse::kReference).kind, RigKind::kArm);
  for (RigKind kind : {RigKind::kArm, RigKind::kGantry, RigKind::kFlex}) {
    int rows = 0;
    for (const RigTier& t : RigTiers()) rows += t.object_template && t.kind == kind ? 1 : 0;
    EXPECT_EQ(rows, 1) << RigKindName(kind);
    EXPECT_EQ(RigObjectTemplate(kind).kind, kind);
  }
  std::set<std::string> names, scenes;
  for (const RigTier& t : RigTiers()) {
    EXPECT_TRUE(names.insert(t.name).second) << t.name;
    EXPECT_TRUE(scenes.insert(t.scene).second) << t.scene;
  }
  EXPECT_EQ(RigDiskTierNames(), "arm, gantry, light, fast, flex");
}

TEST(RigTest, SceneArgumentsFindTheirTier) {
  for (const RigTier& t : RigTiers()) {
    EXPECT_EQ(RigTierOfScene(t.scene), &t);
    EXPECT_EQ(RigTierOfScene(std::string(t.scene) + ".xml"), &t);
    EXPECT_EQ(RigTierOfScene(ResolveScenePath(t.scene)), &t) << ResolveScenePath(t.scene);
    EXPECT_EQ(RigTierNamed(t.name), &t);
  }
  // A scene that is no tier (another file, a name found nowhere), whatever its name says.
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("disk_benchmark_flex_" + std::to_string(::getpid()) + ".xml");
  std::filesystem::copy_file(ResolveScenePath("disk_benchmark_flex"), copy,
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(RigTierOfScene(copy.string()), nullptr);
  std::filesystem::remove(copy);
  EXPECT_EQ(RigTierOfScene("disk_benchmark_fastest"), nullptr);
  EXPECT_EQ(RigTierNamed("disk_benchmark_fast"), nullptr);  // a scene, not a tier name
}

TEST(RigTest, BindingFindsTheInstrumentsAndResetsSeeded) {
  const RigTier& tier = RigTierFor(RigUse::kTrial);
  ModelPtr m = LoadTier(tier);
  ASSERT_TRUE(m);
  std::string error;
  DataPtr d = MakeData(m.get(), &error);
  ASSERT_TRUE(d) << error;
  RigBinding rig;
  ASSERT_EQ(rig.Bind(m.get(), d.get()), "");
  EXPECT_GE(rig.tool_site, 0);
  EXPECT_GE(rig.pressure_adr, 0);
  EXPECT_EQ(m->sensor_type[rig.force_sensor], mjSENS_FORCE);
  EXPECT_GE(rig.torque_adr, 0);
  ASSERT_TRUE(rig.servo);
  EXPECT_TRUE(rig.servo->Init(m.get(), d.get(), rig.tool_site, &error)) << error;
  // The reset puts the keyframe back whatever ran before.
  rig.Reset(m.get(), d.get(), 3);
  const std::vector<double> start(d->qpos, d->qpos + m->nq);
  for (int i = 0; i < m->nu; ++i) d->ctrl[i] = 0.01;
  for (int i = 0; i < 50; ++i) mj_step(m.get(), d.get());
  EXPECT_NE(std::vector<double>(d->qpos, d->qpos + m->nq), start);
  rig.Reset(m.get(), d.get(), 3);
  EXPECT_EQ(std::vector<double>(d->qpos, d->qpos + m->nq), start);
  EXPECT_EQ(d->time, 0);
  // A scene without the tool's instruments says what it lacks.
  ModelPtr bare = LoadTier(*RigTierNamed("probe"));
  ASSERT_TRUE(bare);
  DataPtr bare_d = MakeData(bare.get(), &error);
  RigBinding none;
  EXPECT_EQ(none.BindSensors(bare.get(), bare_d.get()), "");
  EXPECT_FALSE(none.servo);
}

}  // namespace
}  // namespace ssc
