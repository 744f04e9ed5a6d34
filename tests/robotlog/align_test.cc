// The processing steps on signals with a known answer: resampling, the in-air offset, the
// host's moving average, the tool centre point, the PWM scale.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

Stream Ramp(const std::vector<double>& t, double slope, double intercept) {
  Stream s;
  for (double ti : t) {
    s.t_s.push_back(ti);
    s.rows.push_back({intercept + slope * ti, -slope * ti});
  }
  return s;
}

TEST(RobotLogTest, LinearRampResampledExactly) {
  // Irregular source stamps, query times between, on and beyond them.
  const Stream ramp = Ramp({0.0, 0.013, 0.021, 0.04, 0.0555, 0.09}, 2.5, 1.0);
  const std::vector<double> t = {0.0, 0.005, 0.013, 0.02, 0.033, 0.06, 0.09};
  const auto lin = ResampleRows(ramp, t, Interpolation::kLinear);
  ASSERT_EQ(lin.size(), t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(lin[i][0], 1.0 + 2.5 * t[i], 1e-12) << t[i];
    EXPECT_NEAR(lin[i][1], -2.5 * t[i], 1e-12) << t[i];
  }
  // Zero-order hold: the latest sample at or before each time.
  const auto zoh = ResampleRows(ramp, {0.012, 0.013, 0.05, 1.0}, Interpolation::kZeroOrderHold);
  EXPECT_DOUBLE_EQ(zoh[0][0], 1.0);
  EXPECT_DOUBLE_EQ(zoh[1][0], 1.0 + 2.5 * 0.013);
  EXPECT_DOUBLE_EQ(zoh[2][0], 1.0 + 2.5 * 0.04);
  EXPECT_DOUBLE_EQ(zoh[3][0], 1.0 + 2.5 * 0.09);  // held after the end
  // Before the start: the first sample is held.
  EXPECT_DOUBLE_EQ(ResampleRows(ramp, {-1.0}, Interpolation::kLinear)[0][0], 1.0);

  // A uniform clock over [0, 0.09] at 100 Hz has 10 ticks; the ramp on it is exact too.
  const std::vector<double> clock = UniformClock(0.0, 0.09, 100.0);
  ASSERT_EQ(clock.size(), 10u);
  EXPECT_NEAR(clock.back(), 0.09, 1e-15);
  for (const auto& row : ResampleRows(ramp, clock, Interpolation::kLinear)) {
    EXPECT_NEAR(row[0] + row[1], 1.0, 1e-12);
  }
  EXPECT_TRUE(UniformClock(1.0, 0.0, 100.0).empty());
  EXPECT_TRUE(UniformClock(0.0, 1.0, 0.0).empty());
}

TEST(RobotLogTest, PoseOrientationIsSlerpedPositionInterpolated) {
  // Yaw 0 at t = 0, yaw 90 degrees at t = 1: at t = 0.25 yaw is 22.5 degrees (slerp), not the
  // normalised linear blend of the quaternions.
  Stream pose;
  pose.t_s = {0.0, 1.0};
  pose.rows = {{1, 0, 0, 0, 0, 0, 0}, {M_SQRT1_2, 0, 0, M_SQRT1_2, 1, 2, 3}};
  std::vector<Eigen::Quaterniond> q;
  const auto X = ResamplePose(pose, {0.25}, Interpolation::kLinear, &q);
  const Eigen::Vector3d x_axis = X[0].rotation().col(0);
  EXPECT_NEAR(std::atan2(x_axis.y(), x_axis.x()), M_PI / 8, 1e-12);
  EXPECT_NEAR(X[0].translation().x(), 0.25, 1e-12);
  EXPECT_NEAR(X[0].translation().z(), 0.75, 1e-12);
  EXPECT_NEAR(q[0].w(), std::cos(M_PI / 16), 1e-12);
  const auto held = ResamplePose(pose, {0.99}, Interpolation::kZeroOrderHold);
  EXPECT_NEAR(held[0].translation().y(), 0.0, 1e-15);
}

TEST(RobotLogTest, InAirOffsetIsSubtractedAsTheHostDid) {
  const RobotLog log = StepLog();
  std::array<double, 4> offset{};
  EXPECT_EQ(InAirOffset(log.pressure_abs, 0.0, 1.0, &offset), 100);
  EXPECT_DOUBLE_EQ(offset[3], 101100);
  EXPECT_EQ(InAirOffset(log.pressure_abs, 5.0, 6.0, &offset), 0);

  ProcessOptions o;
  o.moving_average = 1;
  ProcessedLog p;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(log, o, &p, &e)) << e.ToString();
  EXPECT_DOUBLE_EQ(p.offset_pa[1], 101020);
  ASSERT_EQ(p.t_s.size(), 300u);
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(p.p_pa[150][c], 0, 1e-9) << c;                     // in air: no vacuum
    EXPECT_NEAR(p.p_pa[250][c], c == 3 ? 2000 : 1000, 1e-9) << c;  // positive = vacuum
  }
  // A window that is not in air (the cup sealed at 40 kPa) is refused at its first sample.
  o.trial_start_s = 2.505;
  o.offset_window_s = 0.4;
  EXPECT_FALSE(ProcessRobotLog(StepLog(40e3), o, &p, &e));
  EXPECT_EQ(e.line, 212);  // t = 2.11 s, row 212
  EXPECT_EQ(e.column, 3);  // t, ch, P1
  EXPECT_NE(e.message.find("not an ambient pressure"), std::string::npos) << e.ToString();
  // A window just before the vacuum step is fine, and gives the same offsets.
  o.trial_start_s = 1.995;
  ASSERT_TRUE(ProcessRobotLog(log, o, &p, &e)) << e.ToString();
  EXPECT_DOUBLE_EQ(p.offset_pa[0], 101000);
}

TEST(RobotLogTest, HostMovingAverageOfSevenSamples) {
  ProcessOptions o;  // 7 samples by default
  ProcessedLog p;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(StepLog(), o, &p, &e)) << e.ToString();
  // The step at sample 200 shows as k/7 of its height k samples later, full after 7.
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(p.p_pa[200 + k][0], 1000.0 * std::min(k + 1, 7) / 7, 1e-9) << k;
  }
  // At the start the host averaged what it had.
  const std::vector<std::array<double, 4>> x = {{7, 0, 0, 0}, {14, 0, 0, 0}, {21, 0, 0, 0}};
  EXPECT_DOUBLE_EQ(MovingAverage(x, 7)[1][0], 10.5);
  EXPECT_DOUBLE_EQ(MovingAverage(x, 2)[2][0], 17.5);
  EXPECT_EQ(MovingAverage(x, 1), x);
}

TEST(RobotLogTest, ToolCentrePointIs146MmAlongTool0Z) {
  // Tool z pointing down: the TCP lies 146 mm below tool0.
  RobotLog log = StepLog();
  ProcessedLog p;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(log, ProcessOptions(), &p, &e)) << e.ToString();
  EXPECT_NEAR(p.tcp_m[0][0], 0.5, 1e-12);
  EXPECT_NEAR(p.tcp_m[0][1], 0.1, 1e-12);
  EXPECT_NEAR(p.tcp_m[0][2], 0.2 - 0.146, 1e-12);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(p.quat[0][k], kDown[k], 1e-15);

  // Tool0 turned +90 degrees about the base y axis: tool z = base +x.
  const double h = M_SQRT1_2;
  const Eigen::Isometry3d X = PoseFromRow({h, 0, h, 0, 0.4, -0.2, 0.6});
  const Eigen::Vector3d tcp = TcpFromTool0(X, 0.146);
  EXPECT_NEAR(tcp.x(), 0.4 + 0.146, 1e-12);
  EXPECT_NEAR(tcp.y(), -0.2, 1e-12);
  EXPECT_NEAR(tcp.z(), 0.6, 1e-12);

  // Base -> scene: the base 1 m along scene x and turned 90 degrees about z (4x4 hook).
  ProcessOptions o;
  o.X_scene_base = IsometryFromRowMajor({0, -1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  ASSERT_TRUE(ProcessRobotLog(log, o, &p, &e)) << e.ToString();
  EXPECT_NEAR(p.tcp_m[0][0], 1.0 - 0.1, 1e-12);  // base y -> scene -x
  EXPECT_NEAR(p.tcp_m[0][1], 0.5, 1e-12);        // base x -> scene y
  EXPECT_NEAR(p.tcp_m[0][2], 0.2 - 0.146, 1e-12);
  const Eigen::Quaterniond q(p.quat[0][0], p.quat[0][1], p.quat[0][2], p.quat[0][3]);
  EXPECT_NEAR((q * Eigen::Vector3d::UnitZ()).z(), -1.0, 1e-12);  // still pointing down
}

TEST(RobotLogTest, PwmScaleIsDetected) {
  Stream s;
  s.t_s = {0, 1};
  s.rows = {{0}, {1.0}};
  EXPECT_EQ(DetectPwmScale(s), PwmScale::kFraction);
  s.rows = {{0}, {100}};
  EXPECT_EQ(DetectPwmScale(s), PwmScale::kPercent);
  s.rows = {{0}, {255}};
  EXPECT_EQ(DetectPwmScale(s), PwmScale::kByte);
  EXPECT_DOUBLE_EQ(PwmPercent(255, PwmScale::kByte), 100);
  EXPECT_DOUBLE_EQ(PwmPercent(0.5, PwmScale::kFraction), 50);
  EXPECT_DOUBLE_EQ(PwmPercent(40, PwmScale::kPercent), 40);
  // Through the pipeline: a byte-scaled log reads back as 100 %.
  LogPerturbation o;
  o.pwm_scale = PwmScale::kByte;
  ProcessedLog p;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(MakeRobotLog(TwinRun(), o), ProcessOptions(), &p, &e));
  EXPECT_DOUBLE_EQ(p.pwm_pct.back(), 100);
}

}  // namespace
}  // namespace ssc
