// The plain CSV log: a round trip, and bad files named by line and column.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

TEST(RobotLogTest, PlainCsvRoundTrip) {
  TempDir dir("plain");
  ProcessedLog p;
  LoadError e;
  ProcessOptions o;
  o.moving_average = 1;
  ASSERT_TRUE(ProcessRobotLog(MakeRobotLog(TwinRun(), LogPerturbation()), o, &p, &e))
      << e.ToString();
  ASSERT_FALSE(p.ft.empty());
  ASSERT_FALSE(p.pwm_pct.empty());
  std::string error;
  ASSERT_TRUE(WritePlainLog(dir / "plain.csv", p, &error)) << error;
  EXPECT_TRUE(StartsWith(dir / "plain.csv",
                         "t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,fx_n,fy_n,fz_n,"
                         "tx_nm,ty_nm,tz_nm,pwm_pct\n"));
  ProcessedLog q;
  ASSERT_TRUE(LoadPlainLog(dir / "plain.csv", &q, &e)) << e.ToString();
  EXPECT_EQ(q.t_s, p.t_s);
  EXPECT_EQ(q.tcp_m, p.tcp_m);
  EXPECT_EQ(q.quat, p.quat);
  EXPECT_EQ(q.p_pa, p.p_pa);
  EXPECT_EQ(q.ft, p.ft);
  EXPECT_EQ(q.pwm_pct, p.pwm_pct);

  // Columns in another order, without the optional ones.
  std::string reordered = "p4_pa,p3_pa,p2_pa,p1_pa,qz,qy,qx,qw,z_m,y_m,x_m,t_s\n";
  for (int i = 0; i < 100; ++i) {
    reordered += "400,3,2,1,0,0,0,1,0.3,0.2,0.1," + std::to_string(0.01 * i) + "\n";
  }
  WriteText(dir / "reordered.csv", reordered);
  ASSERT_TRUE(LoadPlainLog(dir / "reordered.csv", &q, &e)) << e.ToString();
  EXPECT_EQ(q.p_pa[0], (std::array<double, 4>{1, 2, 3, 400}));
  EXPECT_EQ(q.tcp_m[0], (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_TRUE(q.ft.empty());
}

TEST(RobotLogTest, BadPlainLogsNameLineAndColumn) {
  TempDir dir("bad_plain");
  const std::string h = "t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa\n";
  const std::string ok_row = "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n";
  // 100 rows at 100 Hz reaching 400 Pa, with `time_scale` applied to the times.
  auto rows = [](double time_scale, const std::string& p4) {
    std::string s;
    for (int i = 0; i < 100; ++i) {
      s += std::to_string(0.01 * i * time_scale) + ",0.1,0.2,0.3,1,0,0,0,10,20,30," + p4 + "\n";
    }
    return s;
  };
  const BadCase cases[] = {
      {h + ok_row + "0.01,0.1,0.2,0.3,1,0,0,0,101325,20,30,40\n", 3, 9, "absolute pressure"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,-900,-9000\n", 2, 12, "vacuum written negative"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_kpa,p2_pa,p3_pa,p4_pa\n" + ok_row, 1, 9, "unknown column"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,p1_pa,p2_pa,p3_pa,p4_pa\n" + ok_row, 1, 12, "missing column 'qz'"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,x_m\n", 1, 13, "appears twice"},
      {h.substr(0, h.size() - 1) + ",fx_n\n", 1, 14, "missing column 'fy_n'"},
      {ok_row, 1, 1, "header row"},
      {h + ok_row + "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n", 3, 1, "duplicate time"},
      {h + "0.5,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n" + ok_row, 3, 1, "non-monotonic time"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,30\n", 2, 12, "missing column"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40,50\n", 2, 13, "unexpected extra column"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,nan,40\n", 2, 11, "non-finite"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,2O,30,40\n", 2, 10, "'2O' is not a number (p2_pa)"},
      {h + "0,100,0.2,0.3,1,0,0,0,10,20,30,40\n", 2, 2, "millimetres"},
      {h + "0,0.1,0.2,0.3,0.9,0,0,0,10,20,30,40\n", 2, 5, "not a unit quaternion"},
      {h + "1.7e18,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n", 2, 1, "nanoseconds"},
      // Times in milliseconds under t_s: 10 "s" apart.
      {h + rows(1000, "400"), 3, 1, "ms read as s"},
      // kPa under _pa: the largest vacuum 0.4.
      {h + rows(1, "0.4"), 2, 9, "kPa under a _pa column"},
      {h, 0, 0, "empty log"},
  };
  for (const BadCase& c : cases) {
    WriteText(dir / "plain.csv", c.text);
    ProcessedLog p;
    LoadError e;
    EXPECT_FALSE(LoadPlainLog(dir / "plain.csv", &p, &e)) << c.text;
    EXPECT_EQ(e.file, dir / "plain.csv");
    ExpectError(e, c.line, c.column, c.words);
  }
  ProcessedLog p;
  LoadError e;
  WriteText(dir / "plain.csv", h + rows(1, "400"));
  EXPECT_TRUE(LoadPlainLog(dir / "plain.csv", &p, &e)) << e.ToString();
  EXPECT_FALSE(LoadPlainLog(dir / "missing.csv", &p, &e));
  EXPECT_NE(e.ToString().find("missing.csv: no such file"), std::string::npos);
  EXPECT_FALSE(LoadPlainLog(dir.str(), &p, &e));
  EXPECT_NE(e.message.find("is a directory"), std::string::npos);
}

}  // namespace
}  // namespace ssc
