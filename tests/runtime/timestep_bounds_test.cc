// Time-step bounds from the stability study: a zero or negative step is an error (a trial would
// never reach its timeout), a step above the tested limit loads with a warning naming the limit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "runtime/mujoco_model.h"
#include "runtime/trial.h"

namespace ssc {
namespace {

// The gantry scene with another time step, in the temp folder: its parts and models named by
// absolute path.
std::string SceneWithTimestep(const std::string& dt) {
  std::ifstream in(SourceDir() + "/scenes/disk_benchmark_gantry.xml");
  std::stringstream buf;
  buf << in.rdbuf();
  std::string xml =
      std::regex_replace(buf.str(), std::regex(R"(timestep="[^"]*")"), "timestep=\"" + dt + "\"");
  xml = std::regex_replace(xml, std::regex(R"(file="parts/)"),
                           "file=\"" + SourceDir() + "/scenes/parts/");
  xml = std::regex_replace(xml, std::regex(R"(file="\.\./models/)"),
                           "file=\"" + SourceDir() + "/models/");
  const std::string path = (std::filesystem::temp_directory_path() /
                            (".timestep_test_" + std::to_string(::getpid()) + ".xml"))
                               .string();
  std::ofstream(path) << xml;
  return path;
}

TEST(TimestepBoundsTest, CheckNamesTheLimit) {
  std::string warning;
  EXPECT_EQ(CheckTimestep(0.002, &warning), "");
  EXPECT_EQ(warning, "");
  EXPECT_EQ(CheckTimestep(kLargestTestedTimestepS, &warning), "");
  EXPECT_EQ(warning, "");
  EXPECT_EQ(CheckTimestep(0.010, &warning), "");
  EXPECT_NE(warning.find("8 ms"), std::string::npos) << warning;
  for (double bad : {0.0, -0.001, std::nan("")}) {
    EXPECT_NE(CheckTimestep(bad, nullptr).find("must be > 0"), std::string::npos) << bad;
  }
  // Tiny steps would run for hours (1e-9 s: 10^10 steps for a 10 s trial): refused at the edge.
  EXPECT_EQ(CheckTimestep(kSmallestTimestepS, nullptr), "");
  for (double tiny : {kSmallestTimestepS * 0.99, 1e-9}) {
    EXPECT_NE(CheckTimestep(tiny, nullptr).find("below 0.05 ms"), std::string::npos) << tiny;
  }
}

TEST(TimestepBoundsTest, TinyStepSceneFailsToLoadInsteadOfRunningForHours) {
  const std::string path = SceneWithTimestep("1e-9");
  std::string error;
  ModelPtr m = LoadModel(path, &error);
  std::filesystem::remove(path);
  EXPECT_FALSE(m);
  EXPECT_NE(error.find("below 0.05 ms"), std::string::npos) << error;
}

TEST(TimestepBoundsTest, ZeroStepSceneFailsToLoadInsteadOfHanging) {
  const std::string path = SceneWithTimestep("0");
  std::string error;
  ModelPtr m = LoadModel(path, &error);
  std::filesystem::remove(path);
  EXPECT_FALSE(m);
  EXPECT_NE(error.find("time step"), std::string::npos) << error;
  EXPECT_NE(error.find(".timestep_test_"), std::string::npos) << "names the file: " << error;
}

TEST(TimestepBoundsTest, ATrialRefusesAModelWhoseStepWasSetToZero) {
  std::string error;
  ModelPtr m = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
  ASSERT_TRUE(m) << error;
  m->opt.timestep = 0;
  TrialConfig config;
  const TrialResult r = RunTrial(m.get(), config, false, &error);
  EXPECT_NE(error.find("time step"), std::string::npos) << error;
  EXPECT_LT(r.sim_time_s, 1e-9);
}

}  // namespace
}  // namespace ssc
