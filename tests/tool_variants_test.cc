#include "studies/tool_variants.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "runtime/mujoco_model.h"
#include "plugin/chamber_pressure_sensor.h"

namespace ssc {
namespace {

TEST(ToolVariantsTest, LipSegmentCountChangesKeepTheTotalStiffnessAndTheRing) {
  std::string error;
  const std::string base = ToolModelWithConfig("", &error);
  ASSERT_FALSE(base.empty()) << error;
  for (int n : {8, 32}) {
    const std::string xml = ToolWithLipSegments(base, n, &error);
    ASSERT_FALSE(xml.empty()) << error;
    const auto path = std::filesystem::temp_directory_path() /
                      ("ssc_tool_" + std::to_string(n) + "_" + std::to_string(::getpid()) + ".xml");
    std::ofstream(path) << xml;
    ModelPtr m = LoadModel(path.string(), &error);
    std::filesystem::remove(path);
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

}  // namespace
}  // namespace ssc
