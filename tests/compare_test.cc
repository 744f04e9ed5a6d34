// The twin against a robot log made from a twin run: the replay must recover what was changed.
#include <cmath>
#include <filesystem>

#include <unistd.h>

#include <gtest/gtest.h>

#include "compare/log_replay.h"
#include "runtime/mujoco_model.h"
#include "geometry/dimensions.h"
#include "studies/tool_variants.h"

namespace ssc {
namespace {

struct Fixture {
  ModelPtr gantry, replay;
  TrialResult trial;
};

const Fixture& Shared() {
  static Fixture f = [] {
    Fixture x;
    std::string error;
    x.gantry = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
    x.replay = LoadModel(SourceDir() + "/scenes/disk_replay.xml", &error);
    TrialConfig c;
    c.law.step_mm = 7.5;
    x.trial = RunTrial(x.gantry.get(), c, true, &error);
    return x;
  }();
  return f;
}

ReplayComparison Replay(double scale, double offset_pa) {
  const Fixture& f = Shared();
  const RobotLog robot = RobotLogFromTrial(f.trial, kToolCentreOffsetM, scale, offset_pa);
  ProcessOptions o;
  o.moving_average = 1;  // the twin's log already carries the host-filtered values
  ProcessedLog log;
  LoadError e;
  EXPECT_TRUE(ProcessRobotLog(robot, o, &log, &e)) << e.ToString();
  ReplayComparison c;
  std::string error;
  EXPECT_TRUE(ReplayLog(f.replay.get(), log, kToolCentreOffsetM, &c, &error)) << error;
  return c;
}

TEST(CompareTest, ReplayOfAnUnchangedRunAgrees) {
  ASSERT_EQ(Shared().trial.outcome, Outcome::kSuccess);
  const ReplayComparison c = Replay(1.0, 0.0);
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(c.correlation[k], 0.95) << k;
    EXPECT_NEAR(c.mean_ratio[k], 1.0, 0.05) << k;
  }
  EXPECT_LT(std::fabs(c.pbar_bias_pa), 20.0);
  EXPECT_LT(c.direction_median_deg, 5.0);
  EXPECT_GT(c.direction_samples, 100);
}

TEST(CompareTest, ReplayRecoversAKnownScaleAndOffset) {
  // The "robot" reads 30 % more vacuum: the twin's mean is 1/1.3 of the log's.
  const ReplayComparison scaled = Replay(1.3, 0.0);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(scaled.mean_ratio[k], 1 / 1.3, 0.05) << k;
  // A constant 40 Pa sensor bias is removed by the in-air offset, as on the robot host.
  const ReplayComparison offset = Replay(1.0, 40.0);
  EXPECT_NEAR(offset.pbar_bias_pa, Replay(1.0, 0.0).pbar_bias_pa, 3.0);
}

TEST(CompareTest, ReplayExposesARobotWithAStrongerPump) {
  // The "robot": the twin with a 40 % stronger pump, logged with 8 Pa of extra noise. Replayed
  // in the default twin, the twin must read less vacuum than the log wherever the cup seals
  // (ratio of means 0.87, against 1.00 for an unchanged run), and still agree on direction.
  std::string error;
  ModelPtr strong = ToolModelVariant(SourceDir() + "/scenes/disk_benchmark_gantry.xml",
                                     {{"pump_free_flow_lpm", "18.06"}}, &error);
  ASSERT_TRUE(strong) << error;
  TrialConfig c;
  c.law.step_mm = 7.5;
  const TrialResult robot_run = RunTrial(strong.get(), c, true, &error);
  ProcessOptions o;
  o.moving_average = 1;
  ProcessedLog log;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(RobotLogFromTrial(robot_run, kToolCentreOffsetM, 1.0, 0.0, 101325.0, 8.0, 5), o,
                              &log, &e)) << e.ToString();
  ReplayComparison cmp;
  ASSERT_TRUE(ReplayLog(Shared().replay.get(), log, kToolCentreOffsetM, &cmp, &error)) << error;
  for (int k = 0; k < 4; ++k) EXPECT_LT(cmp.mean_ratio[k], 0.92) << k;  // unchanged: 1 +- 0.05
  EXPECT_LT(cmp.pbar_bias_pa, -20.0);
  EXPECT_LT(cmp.direction_median_deg, 10.0);
}

TEST(CompareTest, ClosedLoopFromTheLogsStartMatchesTheSameController) {
  const Fixture& f = Shared();
  const RobotLog robot = RobotLogFromTrial(f.trial, kToolCentreOffsetM, 1.0, 0.0);
  ProcessOptions o;
  o.moving_average = 1;
  ProcessedLog log;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(robot, o, &log, &e));
  TrialConfig c;
  c.law.step_mm = 7.5;
  c.seed = 9;  // another noise realisation of the same controller
  ClosedLoopComparison closed;
  std::string error;
  ASSERT_TRUE(CompareClosedLoop(f.gantry.get(), log, c, &closed, &error)) << error;
  EXPECT_EQ(closed.twin_outcome, "success");
  EXPECT_NEAR(closed.twin.dr_mm, closed.log.dr_mm, 0.5);
  EXPECT_LT(closed.path_distance_mean_mm, 1.5);
}

}  // namespace
}  // namespace ssc
