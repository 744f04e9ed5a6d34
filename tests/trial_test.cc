// Contour-following trials on the disk benchmark: controller outcomes of the published
// experiments, forced failures, and the control-callback dispatch.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include <unistd.h>

#include <gtest/gtest.h>

#include "runtime/control_dispatch.h"
#include "runtime/mujoco_model.h"
#include "studies/sweep.h"
#include "runtime/trial.h"

namespace ssc {
namespace {

// The light scene: the same cup and disk on a gantry (trajectories compared with the arm in
// docs/trials.md).
const mjModel* Scene() {
  static ModelPtr model = [] {
    std::string error;
    ModelPtr m = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
    EXPECT_TRUE(m) << error;
    return m;
  }();
  return model.get();
}

TrialResult Trial(double pref, double beta, double step, std::uint64_t seed = 1,
                  TrialConfig config = {}) {
  config.law.p_ref_pa = pref;
  config.law.beta = beta;
  config.law.step_mm = step;
  config.seed = seed;
  std::string error;
  TrialResult r = RunTrial(Scene(), config, false, &error);
  EXPECT_TRUE(error.empty()) << error;
  return r;
}

TEST(TrialTest, PilotControllerCompletesTheDisk) {
  const TrialResult r = Trial(70, 1.0, 2.5);
  EXPECT_EQ(r.outcome, Outcome::kSuccess) << r.detail;
  EXPECT_GT(r.swept_deg, 355);  // positive: counter-clockwise seen from above
}

TEST(TrialTest, BestControllerCompletesTheDiskAtAllThreeSteps) {
  const double published_speed_mm_s[3] = {10, 20, 30};
  const double steps[3] = {2.5, 5.0, 7.5};
  for (int i = 0; i < 3; ++i) {
    const TrialResult r = Trial(100, 2.0, steps[i]);
    EXPECT_EQ(r.outcome, Outcome::kSuccess) << "dL " << steps[i] << ": " << r.detail;
    EXPECT_GT(r.swept_deg, 0) << "travel must be counter-clockwise";
    // About 1, 2, 3 cm/s on the robot.
    EXPECT_NEAR(r.metrics.speed_mm_s, published_speed_mm_s[i], 0.2 * published_speed_mm_s[i]);
    // The cup centre rides inside the edge where the mean vacuum is P_ref (published -2.5 mm).
    EXPECT_NEAR(r.metrics.dr_mm, -2.5, 1.0);
  }
}

TEST(TrialTest, WithoutCorrectionTheCupDriftsOffTheEdge) {
  const TrialResult r = Trial(100, 0.0, 2.5);
  EXPECT_EQ(r.outcome, Outcome::kFailureOffEdge) << r.detail;
}

TEST(TrialTest, ObjectOnTheRightTravelsClockwise) {
  TrialConfig c;
  c.law.side = FollowSide::kObjectOnRight;
  c.timeout_s = 3;
  const TrialResult r = Trial(100, 2.0, 5.0, 1, c);
  EXPECT_LT(r.swept_deg, -20) << OutcomeName(r.outcome) << " " << r.detail;
}

TEST(TrialTest, StartingOffTheObjectIsFailureOne) {
  TrialConfig c;
  c.target.start = {0.65 + 0.050, 0.0};  // 15 mm beyond the edge: nothing under the cup
  c.target.goal.band_m = 0;  // under test: the pressure failure, not the band of following
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kFailureOffEdge) << r.detail;
}

TEST(TrialTest, PushedOntoTheSurfaceIsFailureTwo) {
  TrialConfig c;
  c.target.start = {0.65, 0.0};  // stay on the disk centre: the cup seals
  c.target.goal.band_m = 0;  // under test: the pressure failure, not the band of following
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kFailureGrasp) << r.detail;
}

TEST(TrialTest, StartingFarOffTheEdgeLosesIt) {
  TrialConfig c;  // the benchmark's goal: round the disk within the cup body radius of its edge
  c.target.start = {0.65 + 0.050, 0.0};  // 15 mm beyond the edge
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kLostEdge) << r.detail;
}

TEST(TrialTest, SameSeedSameTrajectory) {
  const TrialResult a = Trial(100, 2.0, 5.0, 7), b = Trial(100, 2.0, 5.0, 7);
  const TrialResult c = Trial(100, 2.0, 5.0, 8);
  EXPECT_EQ(a.metrics.s_mm, b.metrics.s_mm);
  EXPECT_EQ(a.metrics.sigma_r_mm, b.metrics.sigma_r_mm);
  EXPECT_NE(a.metrics.s_mm, c.metrics.s_mm);
}

TEST(TrialTest, InvalidConfigIsRejectedWithTheField) {
  TrialConfig c;
  c.law.p_ref_pa = 1e6;
  std::string error;
  mjData* d = mj_makeData(Scene());
  auto trial = ContourTrial::Create(Scene(), d, c, false, &error);
  EXPECT_FALSE(trial);
  EXPECT_NE(error.find("pref_pa"), std::string::npos) << error;
  mj_deleteData(d);
}

std::vector<std::string> SortedRows(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::string> rows;
  std::string line;
  while (std::getline(f, line)) rows.push_back(line);
  std::sort(rows.begin(), rows.end());
  return rows;
}

TEST(SweepTest, ParallelSweepGivesTheSameRowsAsSerialAndResumes) {
  const auto dir = std::filesystem::temp_directory_path() / ("ssc_sweep_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  SweepSpec spec;
  spec.scene_name = "disk_benchmark_gantry";
  spec.base.timeout_s = 4;  // short trials: this tests the machinery, not the outcomes
  spec.pref_pa = {70, 100};
  spec.beta = {1.0, 2.0};
  spec.step_mm = {7.5};
  spec.repeats = 1;
  spec.seed = 3;
  SweepSummary summary;
  std::string error;
  spec.threads = 1;
  spec.out_csv = (dir / "serial.csv").string();
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  EXPECT_EQ(summary.ran, 4);
  spec.threads = 2;
  spec.out_csv = (dir / "parallel.csv").string();
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  const auto serial = SortedRows((dir / "serial.csv").string());
  EXPECT_EQ(serial.size(), 5u);  // header + 4
  EXPECT_EQ(serial, SortedRows((dir / "parallel.csv").string()));
  // Re-running resumes: nothing left to run, no duplicate rows.
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  EXPECT_EQ(summary.ran, 0);
  EXPECT_EQ(summary.skipped, 4);
  EXPECT_EQ(SortedRows((dir / "parallel.csv").string()).size(), 5u);
  std::filesystem::remove_all(dir);
}

// Counts calls per mjData.
class Counter : public ControlCallback {
 public:
  void Control(const mjModel*, mjData* d) override {
    ++calls;
    last = d;
  }
  int calls = 0;
  const mjData* last = nullptr;
};

TEST(ControlDispatchTest, EachDataReachesItsOwnControllerAcrossThreads) {
  const mjModel* m = Scene();
  mjData* a = mj_makeData(m);
  mjData* b = mj_makeData(m);
  mjData* none = mj_makeData(m);
  Counter ca, cb;
  {
    ScopedControl ra(a, &ca), rb(b, &cb);
    ASSERT_TRUE(ra.ok() && rb.ok());
    std::thread ta([&] { for (int i = 0; i < 200; ++i) mj_step(m, a); });
    std::thread tb([&] { for (int i = 0; i < 300; ++i) mj_step(m, b); });
    ta.join();
    tb.join();
    for (int i = 0; i < 50; ++i) mj_step(m, none);
  }
  EXPECT_EQ(ca.calls, 200);
  EXPECT_EQ(cb.calls, 300);
  EXPECT_EQ(ca.last, a);
  EXPECT_EQ(cb.last, b);
  mj_step(m, a);  // unregistered now
  EXPECT_EQ(ca.calls, 200);
  mj_deleteData(a);
  mj_deleteData(b);
  mj_deleteData(none);
}

}  // namespace
}  // namespace ssc

namespace ssc {
namespace {

TEST(TrialEndsTest, TimeoutWhenTheFollowPhaseRunsOutOfTime) {
  TrialConfig c;
  c.timeout_s = 1.0;
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kTimeout) << r.detail;
}

TEST(TrialEndsTest, DivergingSimulationIsUnstableNotAControllerResult) {
  // A copy of the scene with a time step far beyond what the lip springs tolerate.
  mjModel* m = mj_copyModel(nullptr, Scene());
  m->opt.timestep = 0.2;
  m->opt.integrator = mjINT_EULER;
  std::string error;
  const TrialResult r = RunTrial(m, TrialConfig{}, false, &error);
  EXPECT_EQ(r.outcome, Outcome::kUnstable) << r.detail;
  mj_deleteModel(m);
}

}  // namespace
}  // namespace ssc
