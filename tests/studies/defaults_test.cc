// One home per fact: docs/defaults.md is generated from the code's tables, and the scene files'
// literal disk matches geometry/dimensions.h.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "geometry/dimensions.h"
#include "runtime/mujoco_model.h"
#include "studies/defaults_doc.h"
#include "studies/success_map_fit.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

TEST(DefaultsTest, DocsAreGeneratedFromTheTables) {
  std::ifstream in(SourceDir() + "/docs/defaults.md");
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_EQ(doc.str(), DefaultsMarkdown())
      << "docs/defaults.md is stale: build/bin/ssc_defaults_doc > docs/defaults.md";
}

TEST(DefaultsTest, EveryFittedEffectKeyIsAFitParameterWithTheTablesRange) {
  for (const EffectKey& k : EffectKeys()) {
    const DynamicParameter* found = nullptr;
    for (const DynamicParameter& p : DynamicParameters())
      if (std::string(p.key) == k.key) found = &p;
    if (k.fit_max > k.fit_min) {
      ASSERT_NE(found, nullptr) << k.key;
      EXPECT_EQ(found->min, k.fit_min) << k.key;
      EXPECT_EQ(found->max, k.fit_max) << k.key;
      EXPECT_GE(k.fit_min, k.min) << k.key << ": the fit searches outside the valid range";
      EXPECT_LE(k.fit_max, k.max) << k.key << ": the fit searches outside the valid range";
    } else {
      EXPECT_EQ(found, nullptr) << k.key << " has no fit range";
    }
  }
}

// The scenes keep the disk as literal MJCF; it must be the benchmark disk of dimensions.h.
TEST(DefaultsTest, ScenesHoldTheBenchmarkDisk) {
  struct Scene {
    const char* file;
    double centre_x_m;  // the probe scene keeps its disk away from the plate's edge
  };
  const Scene scenes[] = {{"disk_benchmark.xml", kWorkspaceX},
                          {"disk_benchmark_gantry.xml", kWorkspaceX},
                          {"disk_benchmark_light.xml", kWorkspaceX},
                          {"disk_replay.xml", kWorkspaceX},
                          {"probe_edge.xml", 0.15}};
  for (const Scene& s : scenes) {
    std::string error;
    ModelPtr m = LoadModel(SourceDir() + "/scenes/" + s.file, &error);
    ASSERT_TRUE(m) << error;
    const int disk = mj_name2id(m.get(), mjOBJ_GEOM, "disk");
    ASSERT_GE(disk, 0) << s.file;
    EXPECT_EQ(m->geom_type[disk], mjGEOM_CYLINDER) << s.file;
    EXPECT_DOUBLE_EQ(m->geom_size[3 * disk], kBenchmarkDiskRadiusM) << s.file;
    EXPECT_NEAR(m->geom_pos[3 * disk], s.centre_x_m, 1e-12) << s.file;
    EXPECT_NEAR(m->geom_pos[3 * disk + 1], kWorkspaceY, 1e-12) << s.file;
  }
}

}  // namespace
}  // namespace ssc
