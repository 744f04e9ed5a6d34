// The UR-10 model: kinematics against the published DH numbers, and the position servos
// holding a Cartesian pose when still.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/dimensions.h"
#include "runtime/mujoco_model.h"
#include "runtime/trial.h"

namespace ssc {
namespace {

ModelPtr Load(const std::string& rel) {
  std::string error;
  ModelPtr m = LoadModel(SourceDir() + rel, &error);
  EXPECT_TRUE(m) << error;
  return m;
}

// Standard DH forward kinematics of the UR10 (ur10.md 1.1): tool0 position in the UR Base frame.
std::array<double, 3> DhTool0(const double q[6]) {
  const double d[6] = {0.1273, 0, 0, 0.163941, 0.1157, 0.0922};
  const double a[6] = {0, -0.612, -0.5723, 0, 0, 0};
  const double alpha[6] = {M_PI / 2, 0, 0, M_PI / 2, -M_PI / 2, 0};
  double T[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  for (int i = 0; i < 6; ++i) {
    const double ct = std::cos(q[i]), st = std::sin(q[i]);
    const double ca = std::cos(alpha[i]), sa = std::sin(alpha[i]);
    const double A[4][4] = {{ct, -st * ca, st * sa, a[i] * ct},
                            {st, ct * ca, -ct * sa, a[i] * st},
                            {0, sa, ca, d[i]},
                            {0, 0, 0, 1}};
    double R[4][4] = {};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) R[r][c] += T[r][k] * A[k][c];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) T[r][c] = R[r][c];
  }
  return {T[0][3], T[1][3], T[2][3]};
}

TEST(Ur10ModelTest, FlangeMatchesTheDhChainAtRandomPoses) {
  ModelPtr m = Load("/models/ur10.xml");
  ASSERT_TRUE(m);
  std::string error;
  DataPtr d = MakeData(m.get(), &error);
  const int tool0 = mj_name2id(m.get(), mjOBJ_SITE, "tool0");
  ASSERT_GE(tool0, 0);
  unsigned seed = 7;
  for (int trial = 0; trial < 20; ++trial) {
    double q[6];
    for (double& v : q) {
      seed = seed * 1103515245u + 12345u;
      v = ((seed >> 8) % 10000) / 10000.0 * 2 * M_PI - M_PI;
    }
    for (int i = 0; i < 6; ++i) d->qpos[i] = q[i];
    mj_kinematics(m.get(), d.get());
    const auto want = DhTool0(q);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(d->site_xpos[3 * tool0 + k], want[k], 1e-6);
  }
  // The published check pose (ur10.md 1.3): home -> tool0 (-0.16394, 0.68800, 0.64710).
  const double home[6] = {-M_PI / 2, -M_PI / 2, M_PI / 2, -M_PI / 2, -M_PI / 2, 0};
  for (int i = 0; i < 6; ++i) d->qpos[i] = home[i];
  mj_kinematics(m.get(), d.get());
  EXPECT_NEAR(d->site_xpos[3 * tool0 + 0], -0.16394, 1e-5);
  EXPECT_NEAR(d->site_xpos[3 * tool0 + 1], 0.68800, 1e-5);
  EXPECT_NEAR(d->site_xpos[3 * tool0 + 2], 0.64710, 1e-5);
}

TEST(Ur10ModelTest, ServosHoldTheToolWellUnderATenthOfAMillimetre) {
  ModelPtr m = Load("/scenes/disk_benchmark.xml");
  ASSERT_TRUE(m);
  std::string error;
  DataPtr d = MakeData(m.get(), &error);
  mj_resetDataKeyframe(m.get(), d.get(), 0);
  mj_forward(m.get(), d.get());
  const int site = mj_name2id(m.get(), mjOBJ_SITE, "ssc_tool_site");
  const double start[3] = {d->site_xpos[3 * site], d->site_xpos[3 * site + 1],
                           d->site_xpos[3 * site + 2]};
  double worst = 0;
  for (int i = 0; i < 1500; ++i) {  // 3 s, joint targets fixed at the keyframe
    mj_step(m.get(), d.get());
    if (i > 250) {
      const double* p = d->site_xpos + 3 * site;
      worst = std::max(worst, std::hypot(p[0] - start[0], p[1] - start[1], p[2] - start[2]));
    }
  }
  EXPECT_LT(worst, 0.05e-3) << "tool drift " << worst * 1e3 << " mm";
}

TEST(Ur10ModelTest, ToolCentreLiesTheStatedOffsetFromTheFlange) {
  // Robot logs give tool0; the twin's tool centre is kToolCentreOffsetM from it, along the tool
  // axis. The model (models/ssc_tool.xml attached at the flange) must agree with the constant.
  ModelPtr m = Load("/scenes/disk_benchmark.xml");
  ASSERT_TRUE(m);
  std::string error;
  DataPtr d = MakeData(m.get(), &error);
  mj_resetDataKeyframe(m.get(), d.get(), 0);
  mj_forward(m.get(), d.get());
  const int tool0 = mj_name2id(m.get(), mjOBJ_SITE, "tool0");
  const int tcp = mj_name2id(m.get(), mjOBJ_SITE, "ssc_tool_site");
  ASSERT_GE(tool0, 0);
  ASSERT_GE(tcp, 0);
  const double* a = d->site_xpos + 3 * tool0;
  const double* b = d->site_xpos + 3 * tcp;
  const double* z = d->site_xmat + 9 * tool0;  // tool0's z axis: column 2
  const double v[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  EXPECT_NEAR(std::hypot(v[0], v[1], v[2]), kToolCentreOffsetM, 1e-9);
  EXPECT_NEAR(v[0] * z[2] + v[1] * z[5] + v[2] * z[8], kToolCentreOffsetM, 1e-9);
}

TEST(Ur10ModelTest, ArmAndGantryScenesAgreeOnATrial) {
  // The light gantry scene stands in for the arm in sweeps: the same trial on both must agree
  // well inside the published trial-to-trial spread (sigma_r 1.4-1.9 mm).
  ModelPtr arm = Load("/scenes/disk_benchmark.xml");
  ModelPtr gantry = Load("/scenes/disk_benchmark_gantry.xml");
  ASSERT_TRUE(arm && gantry);
  TrialConfig c;
  c.law.step_mm = 5.0;
  std::string error;
  const TrialResult a = RunTrial(arm.get(), c, false, &error);
  const TrialResult g = RunTrial(gantry.get(), c, false, &error);
  ASSERT_EQ(a.outcome, Outcome::kSuccess) << a.detail;
  ASSERT_EQ(g.outcome, Outcome::kSuccess) << g.detail;
  EXPECT_NEAR(a.metrics.r_mean_mm, g.metrics.r_mean_mm, 0.3);
  EXPECT_NEAR(a.metrics.sigma_r_mm, g.metrics.sigma_r_mm, 0.3);
  EXPECT_NEAR(a.metrics.speed_mm_s, g.metrics.speed_mm_s, 1.0);
}

}  // namespace
}  // namespace ssc
