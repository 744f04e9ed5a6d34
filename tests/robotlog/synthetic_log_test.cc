// A twin run written as a lab log with perturbations (offsets, clocks, delays) is recovered
// by processing.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

TEST(RobotLogTest, SyntheticLogWithPerturbationsRecoversTheRun) {
  // Sensor offsets (removed by the in-air offset), a faster pressure clock, a late pose stream
  // with dropped samples, a base frame away from the scene origin.
  const std::vector<TwinSample> run = TwinRun();
  LogPerturbation o;
  o.sensor_offset_pa = {30, -40, 50, 10};
  o.pressure_rate_hz = 160;
  o.pose_delay_s = 0.004;
  o.drop_fraction = 0.3;
  o.X_scene_base =
      Eigen::Translation3d(0.2, -0.1, 0.0) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  const RobotLog log = MakeRobotLog(run, o);
  ProcessOptions po;
  po.moving_average = 1;
  po.X_scene_base = o.X_scene_base;
  ProcessedLog p;
  LoadError e;
  ASSERT_TRUE(ProcessRobotLog(log, po, &p, &e)) << e.ToString();
  ASSERT_GT(p.t_s.size(), 300u);
  // The log starts with the 1 s in-air lead: run time = log time - 1 s.
  int checked = 0;
  for (size_t i = 0; i < p.t_s.size(); ++i) {
    const double t_run = p.t_s[i] - 1.0;
    if (t_run < 0.05 || t_run > 1.9) continue;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(p.p_pa[i][c], 100.0 * (c + 1) * t_run, 1e-6);
    // The pose is 4 ms late: the TCP read at t is the truth at t - 4 ms, interpolated along
    // chords of the circle (a few um off it where samples were dropped).
    const double a = 0.5 * (t_run - 0.004);
    EXPECT_NEAR(p.tcp_m[i][0], 0.6 + 0.03 * std::cos(a), 5e-6);
    EXPECT_NEAR(p.tcp_m[i][1], 0.1 + 0.03 * std::sin(a), 5e-6);
    EXPECT_NEAR(p.tcp_m[i][2], 0.005, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 250);
}

}  // namespace
}  // namespace ssc
