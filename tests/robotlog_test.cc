// Robot logs: round trips of every format, the processing steps, and each bad-log error.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "robotlog/robot_log.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("ssc_log_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// A small synthetic log: 2 s at 100 Hz; in air for 1 s (absolute = ambient), then a vacuum
// ramp; tool0 pointing down (tool z = world -z) moving along x.
RobotLog Synthetic() {
  RobotLog log;
  log.t0_ns = 1600000000000000000LL;
  const double q[4] = {0, M_SQRT1_2, -M_SQRT1_2, 0};
  for (int i = 0; i < 200; ++i) {
    const double t = i * 0.01;
    const double vac = t < 1 ? 0 : 1000 * (t - 1);
    log.pressure_abs.t_s.push_back(t);
    log.pressure_abs.rows.push_back({1, 101000 - vac, 101010 - 2 * vac, 101020 - vac, 101030});
    log.tool_pose.t_s.push_back(t + 0.005);
    log.tool_pose.rows.push_back({q[0], q[1], q[2], q[3], 0.5 + 0.01 * t, 0.1, 0.3});
  }
  return log;
}

TEST(RobotLogTest, TopicCsvRoundTripAndProcessing) {
  const fs::path dir = TempDir("csv");
  std::string error;
  ASSERT_TRUE(WriteRobotLogDir(dir.string(), Synthetic(), &error)) << error;
  RobotLog log;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogDir(dir.string(), &log, &e)) << e.ToString();
  ASSERT_EQ(log.pressure_abs.t_s.size(), 200u);
  EXPECT_NEAR(log.pressure_abs.rows[150][2], 101010 - 2 * 500, 1e-6);
  ProcessOptions o;
  o.moving_average = 1;
  ProcessedLog p;
  ASSERT_TRUE(ProcessRobotLog(log, o, &p, &e)) << e.ToString();
  // Gauge vacuum after subtracting the in-air offset (mean over the first second).
  EXPECT_NEAR(p.p_pa[150][0], 500, 1e-6);
  EXPECT_NEAR(p.p_pa[150][1], 1000, 1e-6);
  EXPECT_NEAR(p.p_pa[150][3], 0, 1e-6);
  // The TCP is 146 mm along tool0 z, which points down: 0.3 - 0.146.
  EXPECT_NEAR(p.tcp_m[150][2], 0.3 - 0.146, 1e-9);
  // Alignment: pose stamps are 5 ms late; the x ramp is interpolated exactly onto pressure time.
  EXPECT_NEAR(p.tcp_m[150][0], 0.5 + 0.01 * (1.50 - 0.005), 1e-9);
  // The host's moving average over 7 samples of a ramp lags it by 3 samples.
  o.moving_average = 7;
  ASSERT_TRUE(ProcessRobotLog(log, o, &p, &e));
  EXPECT_NEAR(p.p_pa[150][0], 1000 * (1.50 - 0.03 - 1), 1e-6);
  fs::remove_all(dir);
}

TEST(RobotLogTest, HeaderlessCsvIsRead) {
  std::vector<long long> t;
  std::vector<std::vector<double>> rows;
  LoadError e;
  ASSERT_TRUE(ParseTopicCsv("10,1,2\n20,3,4\n", "x.csv", {"a", "b"}, &t, &rows, &e)) << e.ToString();
  EXPECT_EQ(t[1], 20);
  EXPECT_EQ(rows[1][1], 4);
}

TEST(RobotLogTest, MatFileRoundTripThroughMatio) {
  const fs::path dir = TempDir("mat");
  std::string error;
  ASSERT_TRUE(WriteRobotLogMat((dir / "log.mat").string(), Synthetic(), &error)) << error;
  RobotLog log;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogMat((dir / "log.mat").string(), &log, &e)) << e.ToString();
  ASSERT_EQ(log.tool_pose.t_s.size(), 200u);
  EXPECT_NEAR(log.tool_pose.rows[10][4], 0.5 + 0.01 * 0.1, 1e-12);
  // Time stamps travel as doubles of nanoseconds: sub-microsecond rounding at epoch scale.
  EXPECT_NEAR(log.tool_pose.t_s[10] - log.pressure_abs.t_s[10], 0.005, 1e-6);
  fs::remove_all(dir);
}

TEST(RobotLogTest, PlainCsvRoundTrip) {
  const fs::path dir = TempDir("plain");
  ProcessedLog p, q;
  LoadError e;
  ProcessOptions o;
  RobotLog raw = Synthetic();
  ASSERT_TRUE(ProcessRobotLog(raw, o, &p, &e));
  std::string error;
  ASSERT_TRUE(WritePlainLog((dir / "plain.csv").string(), p, &error));
  ASSERT_TRUE(LoadPlainLog((dir / "plain.csv").string(), &q, &e)) << e.ToString();
  ASSERT_EQ(q.t_s.size(), p.t_s.size());
  EXPECT_NEAR(q.p_pa[120][1], p.p_pa[120][1], 1e-3);
  EXPECT_NEAR(q.tcp_m[120][0], p.tcp_m[120][0], 1e-8);
  fs::remove_all(dir);
}

// Each bad input: the error names the file, the line and the column.
struct BadCase {
  const char* text;
  int line, column;
  const char* words;
};

TEST(RobotLogTest, BadTopicCsvErrorsNameFileLineAndColumn) {
  const std::vector<std::string> fields = {"ch", "P1", "P2", "P3", "P4"};
  const BadCase cases[] = {
      {"t_ns,ch,P1,P2,P3,P4\n1,1,100000,100000,100000\n", 2, 6, "missing columns"},
      {"1,1,100000,abc,100000,100000\n", 1, 4, "not a number"},
      {"1,1,100000,100000,100000,100000\n2,1,1e5,nan,1e5,1e5\n", 2, 4, "non-finite"},
      {"5,1,1e5,1e5,1e5,1e5\n3,1,1e5,1e5,1e5,1e5\n", 2, 1, "non-monotonic"},
      {"5,1,1e5,1e5,1e5,1e5\n5,1,1e5,1e5,1e5,1e5\n", 2, 1, "duplicate"},
      {"t_ns,ch,P1,P2,P3,pressure4\n", 1, 6, "expected 'P4'"},
      {"t_ns,ch,P1,P2,P3,P4\n", 0, 0, "empty stream"},
      {"1.5,1,1e5,1e5,1e5,1e5\n2,1,1e5,1e5,1e5,1e5\n", 1, 1, "not an integer"},
  };
  for (const BadCase& c : cases) {
    std::vector<long long> t;
    std::vector<std::vector<double>> rows;
    LoadError e;
    EXPECT_FALSE(ParseTopicCsv(c.text, "pressure.csv", fields, &t, &rows, &e)) << c.text;
    EXPECT_EQ(e.file, "pressure.csv");
    EXPECT_EQ(e.line, c.line) << c.text << " -> " << e.ToString();
    EXPECT_EQ(e.column, c.column) << c.text << " -> " << e.ToString();
    EXPECT_NE(e.message.find(c.words), std::string::npos) << e.ToString();
  }
}

TEST(RobotLogTest, GaugeWhereAbsoluteExpectedAndMissingFiles) {
  const fs::path dir = TempDir("units");
  RobotLog log = Synthetic();
  for (auto& row : log.pressure_abs.rows) row[3] = 150;  // gauge-looking values in P3
  std::string error;
  ASSERT_TRUE(WriteRobotLogDir(dir.string(), log, &error));
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadRobotLogDir(dir.string(), &back, &e));
  EXPECT_NE(e.message.find("not an absolute pressure"), std::string::npos) << e.ToString();
  EXPECT_EQ(e.line, 2);    // first data row, after the header
  EXPECT_EQ(e.column, 5);  // t_ns, ch, P1, P2, P3
  fs::remove(dir / "tool_pose.csv");
  EXPECT_FALSE(LoadRobotLogDir(dir.string(), &back, &e));
  EXPECT_NE(e.ToString().find("tool_pose.csv"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadRobotLogMat((dir / "nothing.mat").string(), &back, &e));
  EXPECT_NE(e.ToString().find("nothing.mat"), std::string::npos);
  ProcessedLog p;
  std::ofstream(dir / "plain.csv") << "t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa\n"
                                    << "0,0,0,0,1,0,0,0,101000,0,0,0\n";
  EXPECT_FALSE(LoadPlainLog((dir / "plain.csv").string(), &p, &e));
  EXPECT_NE(e.message.find("absolute"), std::string::npos);
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 9);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ssc
