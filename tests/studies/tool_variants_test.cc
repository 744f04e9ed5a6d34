#include "studies/tool_variants.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"

namespace ssc {
namespace {

TEST(ToolVariantsTest, LipSegmentCountChangesKeepTheTotalStiffnessAndTheRing) {
  std::string error;
  const auto tool = ToolModelVariants::Read(SourceDir() + "/models/ssc_tool.xml", &error);
  ASSERT_TRUE(tool) << error;
  const std::string base = tool->ToolXml({}, &error);
  ASSERT_FALSE(base.empty()) << error;
  for (int n : {8, 32}) {
    ModelPtr m = tool->Compile({{}, n}, &error);
    ASSERT_TRUE(m) << error;
    DataPtr d = MakeData(m.get(), &error);
    const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m.get(), d.get());
    ASSERT_NE(sensor, nullptr);
    EXPECT_EQ(sensor->num_lip_segments(), n);
    double stiffness = 0;
    for (int j = 0; j < m->njnt; ++j) stiffness += m->jnt_stiffness[j];
    EXPECT_NEAR(stiffness, 1500.0, 1e-6);  // N/m over the whole lip
    // Each chamber gets the same share of the lip.
    int per_chamber[4] = {0, 0, 0, 0};
    for (const LipSegmentState& s : sensor->last_sample().lip) ++per_chamber[s.chamber];
    for (int c = 0; c < 4; ++c) EXPECT_EQ(per_chamber[c], n / 4);
  }
  EXPECT_TRUE(ToolWithLipSegments(base, 10, &error).empty());
  EXPECT_NE(error.find("multiple of 4"), std::string::npos);
}

// An optimiser evaluation touches no disk: the scene's files are read once, then removed, and
// every variant still compiles, each with its own config.
TEST(ToolVariantsTest, VariantsCompileInMemoryWithTheirConfig) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ssc_variants_" + std::to_string(::getpid()));
  fs::create_directories(dir / "models");
  // The scene with the parts it includes (scenes/parts/).
  fs::copy(SourceDir() + "/scenes", dir / "scenes", fs::copy_options::recursive);
  fs::copy_file(SourceDir() + "/models/ur10.xml", dir / "models" / "ur10.xml");
  fs::copy_file(SourceDir() + "/models/ssc_tool.xml", dir / "models" / "ssc_tool.xml");
  std::string error;
  const auto variants =
      ToolModelVariants::Read((dir / "scenes" / "disk_benchmark.xml").string(), &error);
  ModelPtr from_file = LoadModel((dir / "scenes" / "disk_benchmark.xml").string(), &error);
  fs::remove_all(dir);
  ASSERT_TRUE(variants) << error;
  ASSERT_TRUE(from_file) << error;
  for (const char* noise : {"0", "3.5", "12"}) {
    ModelPtr m = variants->Compile({{{"noise_pa", noise}, {"lag_ms", "7"}}, 0}, &error);
    ASSERT_TRUE(m) << error;
    ASSERT_EQ(m->nplugin, 1);
    EXPECT_STREQ(mj_getPluginConfig(m.get(), 0, "noise_pa"), noise);
    EXPECT_STREQ(mj_getPluginConfig(m.get(), 0, "lag_ms"), "7");
    // The whole scene (arm, tool, disk), as loaded from its files.
    EXPECT_EQ(m->nbody, from_file->nbody);
    EXPECT_EQ(m->nu, from_file->nu);
    EXPECT_EQ(m->ngeom, from_file->ngeom);
  }
  // A value the plugin refuses fails the compile with the plugin's message.
  EXPECT_FALSE(variants->Compile({{{"noise_pa", "-1"}}, 0}, &error));
  EXPECT_NE(error.find("noise_pa"), std::string::npos) << error;
  // A scene without the pressure plugin is refused when read.
  error.clear();
  const fs::path bare = fs::temp_directory_path() / ("ssc_bare_" + std::to_string(::getpid()));
  std::ofstream(bare.string()) << "<mujoco><worldbody/></mujoco>";
  EXPECT_FALSE(ToolModelVariants::Read(bare.string(), &error));
  fs::remove(bare);
  EXPECT_NE(error.find("ssc.chamber_pressure"), std::string::npos) << error;
}

// The light scene leaves the lip carrier's joints and their locks out (<custom> ssc_remove_joints),
// from its file and as in-memory variants; a variant that switches the lip shear on is refused
// with the plugin's message; a name the model lacks is an error naming it.
TEST(ToolVariantsTest, LightSceneLeavesTheListedJointsOut) {
  std::string error;
  ModelPtr gantry = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
  ModelPtr light = LoadModel(SourceDir() + "/scenes/disk_benchmark_light.xml", &error);
  ASSERT_TRUE(gantry && light) << error;
  EXPECT_EQ(light->nv, gantry->nv - 4);
  EXPECT_EQ(light->neq, gantry->neq - 4);
  for (const char* j :
       {"ssc_flex_tilt_x", "ssc_flex_tilt_y", "ssc_flex_shear_x", "ssc_flex_shear_y"}) {
    EXPECT_GE(mj_name2id(gantry.get(), mjOBJ_JOINT, j), 0) << j;
    EXPECT_EQ(mj_name2id(light.get(), mjOBJ_JOINT, j), -1) << j;
  }
  const auto variants =
      ToolModelVariants::Read(SourceDir() + "/scenes/disk_benchmark_light.xml", &error);
  ASSERT_TRUE(variants) << error;
  ModelPtr variant = variants->Compile({{{"noise_pa", "3"}}, 0}, &error);
  ASSERT_TRUE(variant) << error;
  EXPECT_EQ(variant->nv, light->nv);
  EXPECT_FALSE(variants->Compile({{{"lip_shear_n_per_mm", "1"}}, 0}, &error));
  EXPECT_NE(error.find("lip_shear_n_per_mm"), std::string::npos) << error;

  ModelTexts texts;
  texts.main_xml =
      "<mujoco><custom><text name=\"ssc_remove_joints\" data=\"a nope\"/></custom>"
      "<worldbody><body><joint name=\"a\"/><geom size=\"0.1\"/></body></worldbody></mujoco>";
  error.clear();
  EXPECT_FALSE(LoadModelFromTexts(texts, "t", &error));
  EXPECT_NE(error.find("'nope'"), std::string::npos) << error;
}

}  // namespace
}  // namespace ssc
