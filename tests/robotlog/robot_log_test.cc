// Processing and validating a raw log: logs that cannot be aligned and streams built in code
// are refused with a reason.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

TEST(RobotLogTest, ProcessingRefusesLogsItCannotAlign) {
  RobotLog log = StepLog();
  for (double& t : log.tool_pose.t_s) t += 100;  // a pose clock from another epoch
  ProcessedLog p;
  LoadError e;
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("do not overlap"), std::string::npos) << e.ToString();
  // A pose stream cut short: replaying its sliver would look like a whole comparison.
  for (double keep : {0.45, 0.55}) {
    log = StepLog();
    const size_t n = static_cast<size_t>(keep * static_cast<double>(log.tool_pose.size()));
    log.tool_pose.t_s.resize(n);
    log.tool_pose.rows.resize(n);
    if (!log.tool_pose.lines.empty()) log.tool_pose.lines.resize(n);
    const bool ok = ProcessRobotLog(log, ProcessOptions(), &p, &e);
    EXPECT_EQ(ok, keep > 0.5) << keep << ": " << e.ToString();
    if (!ok) {
      EXPECT_NE(e.message.find("less than half"), std::string::npos) << e.ToString();
    }
  }
  ProcessOptions o;
  o.trial_start_s = 50;
  EXPECT_FALSE(ProcessRobotLog(StepLog(), o, &p, &e));
  EXPECT_NE(e.message.find("no pressure sample in the in-air offset window"), std::string::npos);
  // A log built in code with a short row names the stream and its row.
  log = StepLog();
  log.pressure_abs.rows[7].pop_back();
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_EQ(e.ToString(), "pressure stream:8:1: row has 4 fields, the topic has 5");
  log = RobotLog();
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("empty stream"), std::string::npos);
  // Uniform clock and zero-order hold run on a good log.
  o = ProcessOptions();
  o.clock = ClockSource::kUniform;
  o.clock_rate_hz = 50;
  o.interpolation = Interpolation::kZeroOrderHold;
  ASSERT_TRUE(ProcessRobotLog(StepLog(), o, &p, &e)) << e.ToString();
  EXPECT_EQ(p.t_s.size(), 150u);  // [0, 2.99] s at 50 Hz
}

TEST(RobotLogTest, StreamsBuiltInCodeAreCheckedForTimeOrderAndUnits) {
  // No reader in front: ValidateRobotLog is the only check.
  ProcessedLog p;
  LoadError e;
  RobotLog log = StepLog();
  std::swap(log.pressure_abs.t_s[20], log.pressure_abs.t_s[21]);
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_EQ(e.ToString(), "pressure stream:22:1: non-finite, duplicate or non-monotonic time");
  log = StepLog();
  log.tool_pose.t_s[5] = log.tool_pose.t_s[4];
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_EQ(e.file, "tool pose stream");
  EXPECT_EQ(e.line, 6);
  log = StepLog();
  for (double& t : log.pressure_abs.t_s) t *= 1e-3;  // ms where s belong
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("faster than 10 kHz"), std::string::npos) << e.ToString();
  log = StepLog();
  for (double& t : log.tool_pose.t_s) t *= 1e3;  // ms where s belong
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("slower than 1 Hz"), std::string::npos) << e.ToString();
  log = StepLog();
  for (auto& row : log.pressure_abs.rows) row[2] *= 1e-3;  // kPa where Pa belong
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("not an absolute pressure"), std::string::npos) << e.ToString();
}

}  // namespace
}  // namespace ssc
