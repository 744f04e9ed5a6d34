// Robot logs: round trips of every format (per-topic CSV with and without a header, .mat through
// matio, plain CSV), the processing steps on signals with a known answer, and every bad-log case
// with the file, line and column it must name.
#include <matio.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "robotlog/robot_log.h"
#include "robotlog/synthetic_log.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

// tool0 pointing down at the table (tool z = scene -z), tool x = scene -y: the project's
// orientation (180 degrees about (1, -1, 0)).
constexpr double kDown[4] = {0, M_SQRT1_2, -M_SQRT1_2, 0};

// A fresh directory per test, removed at the end.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(fs::temp_directory_path() /
              ("ssc_robotlog_" + tag + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool StartsWith(const std::string& path, const std::string& prefix) {
  std::ifstream f(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  return text.compare(0, prefix.size(), prefix) == 0;
}

// A twin run: 2 s at 100 Hz, the TCP on a 30 mm circle 5 mm above the table, vacuum rising
// linearly per chamber, a growing normal force.
std::vector<TwinSample> TwinRun() {
  std::vector<TwinSample> run;
  for (int i = 0; i < 200; ++i) {
    TwinSample s;
    s.t_s = 0.01 * i;
    const double a = 0.5 * s.t_s;
    s.tcp_m = {0.6 + 0.03 * std::cos(a), 0.1 + 0.03 * std::sin(a), 0.005};
    s.quat = {kDown[0], kDown[1], kDown[2], kDown[3]};
    for (int c = 0; c < 4; ++c) s.p_pa[c] = 100.0 * (c + 1) * s.t_s;
    s.ft = {0.1, -0.2, 1.5 * s.t_s, 0.01, 0.02, -0.03};
    s.pwm_pct = 100;
    run.push_back(s);
  }
  return run;
}

void ExpectSameStream(const Stream& a, const Stream& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a.t_s[i], b.t_s[i], 1e-9) << what << " row " << i;  // stamps are whole ns
    ASSERT_EQ(a.rows[i].size(), b.rows[i].size()) << what;
    for (size_t k = 0; k < a.rows[i].size(); ++k) {
      EXPECT_EQ(a.rows[i][k], b.rows[i][k]) << what << " row " << i << " field " << k;
    }
  }
}

void ExpectSameLog(const RobotLog& a, const RobotLog& b) {
  EXPECT_EQ(a.t0_ns, b.t0_ns);
  ExpectSameStream(a.pressure_abs, b.pressure_abs, "pressure");
  ExpectSameStream(a.tool_pose, b.tool_pose, "pose");
  ExpectSameStream(a.ft, b.ft, "ft");
  ExpectSameStream(a.pwm, b.pwm, "pwm");
}

// ---------------------------------------------------------------------------------------------
// Round trips.

TEST(RobotLogTest, TopicCsvRoundTripWithHeader) {
  TempDir dir("csv_header");
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  std::string error;
  ASSERT_TRUE(WriteTopicCsvLogs(dir.str(), log, TopicCsvWriteOptions(), &error)) << error;
  EXPECT_TRUE(StartsWith(dir / "pressure.csv", "t_ns,ch,P1,P2,P3,P4\n"));
  EXPECT_TRUE(StartsWith(dir / "tool_pose.csv", "t_ns,orientation.w,orientation.x,"));
  RobotLog back;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogDir(dir.str(), &back, &e)) << e.ToString();
  ExpectSameLog(log, back);
  EXPECT_EQ(back.pressure_abs.source, dir / "pressure.csv");
  EXPECT_EQ(back.pressure_abs.lines.front(), 2);  // after the header
}

TEST(RobotLogTest, TopicCsvRoundTripWithoutHeader) {
  TempDir dir("csv_bare");
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  TopicCsvWriteOptions options;
  options.header = false;
  std::string error;
  ASSERT_TRUE(WriteTopicCsvLogs(dir.str(), log, options, &error)) << error;
  EXPECT_TRUE(StartsWith(dir / "pressure.csv", "1700000000000000000,1,101325,"));
  RobotLog back;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogDir(dir.str(), &back, &e)) << e.ToString();
  ExpectSameLog(log, back);
  EXPECT_EQ(back.pressure_abs.lines.front(), 1);
}

TEST(RobotLogTest, TopicCsvAcceptsExportHeadersLineEndingsAndBom) {
  // rostopic-style names, the authors' 0-based chamber numbers, CRLF, a BOM, blank lines.
  const std::string text =
      "\xEF\xBB\xBF%time,field.ch,field.p0,field.p1,field.p2,field.p3\r\n"
      "100,0,101000,101001,101002,101003\r\n\r\n"
      "200,1,+1.01e5,101001.5,101002,101003\r\n";
  TopicTable table;
  LoadError e;
  ASSERT_TRUE(ParseTopicCsv(text, "p.csv", GetStreamSpec(StreamId::kPressure), &table, &e))
      << e.ToString();
  EXPECT_TRUE(table.had_header);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.t_ns[1], 200);
  EXPECT_EQ(table.rows[1][1], 101000);
  EXPECT_EQ(table.rows[1][2], 101001.5);
  EXPECT_EQ(table.lines[1], 4);
  ASSERT_TRUE(ParseTopicCsv("stamp,data\n5,255\n", "pwm.csv", GetStreamSpec(StreamId::kPwm),
                            &table, &e)) << e.ToString();
  ASSERT_TRUE(ParseTopicCsv("t_ns,pose.orientation.w,pose.orientation.x,pose.orientation.y,"
                            "pose.orientation.z,pose.position.x,pose.position.y,pose.position.z\n"
                            "1,1,0,0,0,0.1,0.2,0.3\n",
                            "pose.csv", GetStreamSpec(StreamId::kPose), &table, &e))
      << e.ToString();
  EXPECT_EQ(table.rows[0][6], 0.3);
}

TEST(RobotLogTest, MatRoundTripThroughMatioV5AndV73) {
  TempDir dir("mat");
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  for (MatVersion version : {MatVersion::kMat5, MatVersion::kMat73}) {
    const std::string path = dir / (version == MatVersion::kMat5 ? "v5.mat" : "v73.mat");
    std::string error;
    ASSERT_TRUE(WriteRobotLogMat(path, log, &error, version)) << error;
    RobotLog back;
    LoadError e;
    ASSERT_TRUE(LoadRobotLogMat(path, &back, &e)) << e.ToString();
    EXPECT_EQ(back.tool_pose.variable, "pose");
    // Stamps travel as doubles of ns: 256 ns resolution at 1.7e18 ns.
    ASSERT_EQ(back.pressure_abs.size(), log.pressure_abs.size());
    for (size_t i = 0; i < log.pressure_abs.size(); ++i) {
      EXPECT_NEAR(back.pressure_abs.t_s[i], log.pressure_abs.t_s[i], 300e-9);
      EXPECT_EQ(back.pressure_abs.rows[i], log.pressure_abs.rows[i]);
    }
    EXPECT_EQ(back.tool_pose.rows, log.tool_pose.rows);
    EXPECT_EQ(back.ft.rows, log.ft.rows);
    EXPECT_EQ(back.pwm.rows, log.pwm.rows);
  }
}

// A .mat file made with matio's own API as a MATLAB user would: double matrices, F/T in single,
// PWM as uint8, the pose under its other name, an unrelated variable alongside.
void MatWrite(mat_t* mat, const char* name, matio_classes cls, matio_types type, size_t rows,
              size_t cols, void* data) {
  size_t dims[2] = {rows, cols};
  matvar_t* v = Mat_VarCreate(name, cls, type, 2, dims, data, 0);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(Mat_VarWrite(mat, v, MAT_COMPRESSION_ZLIB), 0);
  Mat_VarFree(v);
}

TEST(RobotLogTest, MatFileWrittenWithMatioApiReadsBack) {
  TempDir dir("mat_api");
  const std::string path = dir / "merged.mat";
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  ASSERT_NE(mat, nullptr);
  // ROS sim time near 1 s: stamps exact even in single precision (multiples of 64 ns).
  const double t0 = 1e9;
  // Column-major, 3 samples 10 ms apart.
  double pressure[3 * 6] = {t0, t0 + 1e7, t0 + 2e7, 0,      1,      2,      101000, 100900,
                            100800, 101100, 101000, 100900, 101200, 101100, 101000, 101300,
                            101200, 101100};
  double pose[3 * 8] = {t0 + 5e6, t0 + 1.5e7, t0 + 2.5e7, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                        0.5, 0.6, 0.7, 0.1, 0.1, 0.1, 0.3, 0.3, 0.3};
  float ft[2 * 7] = {1e9f, 1.01e9f, 1, 2, 3, 4, 5, 6, 0.5f, 0.25f, 0, 0, 0, 0};
  uint8_t pwm[2 * 2] = {0, 1, 255, 255};  // t = 0 and 1 ns: refused later as not-ns spacing
  char note[] = "a note";
  MatWrite(mat, "pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, 6, pressure);
  MatWrite(mat, "tool_pose", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, 8, pose);
  MatWrite(mat, "ft", MAT_C_SINGLE, MAT_T_SINGLE, 2, 7, ft);
  MatWrite(mat, "note", MAT_C_CHAR, MAT_T_UINT8, 1, 6, note);
  Mat_Close(mat);

  RobotLog log;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogMat(path, &log, &e)) << e.ToString();
  EXPECT_EQ(log.t0_ns, 1000000000);
  ASSERT_EQ(log.pressure_abs.size(), 3u);
  EXPECT_EQ(log.pressure_abs.rows[1], (std::vector<double>{1, 100900, 101000, 101100, 101200}));
  EXPECT_EQ(log.tool_pose.variable, "tool_pose");
  EXPECT_EQ(log.tool_pose.rows[2][4], 0.7);
  EXPECT_NEAR(log.tool_pose.t_s[0] - log.pressure_abs.t_s[0], 0.005, 1e-6);
  EXPECT_EQ(log.ft.rows[0][0], 1);
  EXPECT_NEAR(log.ft.t_s[1], 0.01, 1e-12);
  EXPECT_EQ(log.ft.rows[1], (std::vector<double>{2, 4, 6, 0.25, 0, 0}));  // from single

  // A uint8 PWM with time stamps 1 ns apart: read, then refused by the spacing check.
  mat = Mat_Open(path.c_str(), MAT_ACC_RDWR);
  ASSERT_NE(mat, nullptr);
  MatWrite(mat, "pwm", MAT_C_UINT8, MAT_T_UINT8, 2, 2, pwm);
  Mat_Close(mat);
  EXPECT_FALSE(LoadRobotLogMat(path, &log, &e));
  EXPECT_EQ(e.file, path);
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 1);
  EXPECT_NE(e.message.find("variable 'pwm'"), std::string::npos) << e.ToString();
  EXPECT_NE(e.message.find("not nanoseconds"), std::string::npos) << e.ToString();
}

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
  WriteText(dir / "reordered.csv",
            "p4_pa,p3_pa,p2_pa,p1_pa,qz,qy,qx,qw,z_m,y_m,x_m,t_s\n"
            "4,3,2,1,0,0,0,1,0.3,0.2,0.1,0.5\n");
  ASSERT_TRUE(LoadPlainLog(dir / "reordered.csv", &q, &e)) << e.ToString();
  EXPECT_EQ(q.p_pa[0], (std::array<double, 4>{1, 2, 3, 4}));
  EXPECT_EQ(q.tcp_m[0], (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_TRUE(q.ft.empty());
}

// ---------------------------------------------------------------------------------------------
// Processing steps on known signals.

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

// A raw log by hand: pressure at 100 Hz for 3 s, in air for the first second (sensor offsets
// differ per chamber), then vacuum steps to 1000 Pa at t = 2 s in every chamber.
RobotLog StepLog(double step_pa = 1000) {
  RobotLog log;
  log.t0_ns = 1000;
  const double ambient[4] = {101000, 101020, 100980, 101100};
  for (int i = 0; i < 300; ++i) {
    const double t = 0.01 * i;
    const double vac = t >= 2.0 - 1e-9 ? step_pa : 0;
    log.pressure_abs.t_s.push_back(t);
    log.pressure_abs.rows.push_back(
        {1, ambient[0] - vac, ambient[1] - vac, ambient[2] - vac, ambient[3] - 2 * vac});
    log.tool_pose.t_s.push_back(t);
    log.tool_pose.rows.push_back({kDown[0], kDown[1], kDown[2], kDown[3], 0.5, 0.1, 0.2});
  }
  return log;
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
    EXPECT_NEAR(p.p_pa[150][c], 0, 1e-9) << c;                       // in air: no vacuum
    EXPECT_NEAR(p.p_pa[250][c], c == 3 ? 2000 : 1000, 1e-9) << c;    // positive = vacuum
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

// ---------------------------------------------------------------------------------------------
// Bad logs: each error names the file, the line and the column.

struct BadCase {
  StreamId stream;
  const char* text;
  int line, column;
  const char* words;
};

TEST(RobotLogTest, BadTopicCsvErrorsNameFileLineAndColumn) {
  const BadCase cases[] = {
      {StreamId::kPressure, "t_ns,ch,P1,P2,P3,P4\n1,1,1e5,1e5,1e5\n", 2, 6,
       "missing column 'P4'"},
      {StreamId::kPressure, "t_ns,ch,P1,P2,P3\n", 1, 6, "header is missing column 'P4'"},
      {StreamId::kPressure, "1,1,1e5,1e5,1e5,1e5,7\n", 1, 7, "unexpected extra column"},
      {StreamId::kPressure, "t_ns,ch,P1,P2,P3,P4,P5\n", 1, 7, "unexpected extra column"},
      {StreamId::kPressure, "1,1,100000,abc,100000,100000\n", 1, 4, "not a number (P2)"},
      {StreamId::kPressure, "1,1,100000,,100000,100000\n", 1, 4, "empty cell (P2)"},
      {StreamId::kPressure, "1,1,1e5,1e5,1e5,1e5\n2,1,1e5,nan,1e5,1e5\n", 2, 4, "non-finite"},
      {StreamId::kPressure, "1,1,1e5,1e5,1e5,-inf\n", 1, 6, "non-finite"},
      {StreamId::kPressure, "1,1,1e5,1e999,1e5,1e5\n", 1, 4, "non-finite"},
      {StreamId::kPressure, "5,1,1e5,1e5,1e5,1e5\n3,1,1e5,1e5,1e5,1e5\n", 2, 1, "non-monotonic"},
      {StreamId::kPressure, "5,1,1e5,1e5,1e5,1e5\n\n5,1,1e5,1e5,1e5,1e5\n", 3, 1, "duplicate"},
      {StreamId::kPressure, "1.5,1,1e5,1e5,1e5,1e5\n", 1, 1,
       "not an integer number of nanoseconds"},
      {StreamId::kPressure, "-5,1,1e5,1e5,1e5,1e5\n", 1, 1, "negative time stamp"},
      {StreamId::kPressure, "x1,1,1e5,1e5,1e5,1e5\n", 1, 1, "not a time-stamp column"},
      {StreamId::kPressure, "t_s,ch,P1,P2,P3,P4\n", 1, 1, "reads as seconds"},
      {StreamId::kPressure, "t_ns,ch,P1,P2,P3,pressure4\n", 1, 6, "expected 'P4'"},
      {StreamId::kPressure, "t_ns,ch,P1,P2,P3,P4\n\n", 0, 0, "empty stream"},
      {StreamId::kPressure, "", 0, 0, "empty stream"},
      {StreamId::kPose, "t_ns,orientation.w,orientation.x,orientation.y,orientation.z,"
                        "position.x,position.y,position.z\n1,1,0,0,0,0.1,0.2\n",
       2, 8, "missing column 'position.z'"},
      {StreamId::kFt, "1,0,0,0,0,0,0\n2,0,0,0,0,0\n", 2, 7, "missing column 'torque.z'"},
      {StreamId::kPwm, "1,50\n2,\xff\xfe\n", 2, 2, "'\\xFF\\xFE' is not a number"},
  };
  for (const BadCase& c : cases) {
    TopicTable table;
    LoadError e;
    EXPECT_FALSE(ParseTopicCsv(c.text, "some.csv", GetStreamSpec(c.stream), &table, &e))
        << c.text;
    EXPECT_EQ(e.file, "some.csv");
    EXPECT_EQ(e.line, c.line) << c.text << " -> " << e.ToString();
    EXPECT_EQ(e.column, c.column) << c.text << " -> " << e.ToString();
    EXPECT_NE(e.message.find(c.words), std::string::npos) << c.text << " -> " << e.ToString();
  }
  // ToString puts it together as compilers do.
  const LoadError e{"dir/pressure.csv", 12, 4, "'abc' is not a number (P2)"};
  EXPECT_EQ(e.ToString(), "dir/pressure.csv:12:4: 'abc' is not a number (P2)");
  EXPECT_EQ((LoadError{"x.mat", 0, 0, "no such file"}).ToString(), "x.mat: no such file");
}

// A directory log with one topic file replaced, loaded: the error must name that file.
LoadError LoadWith(const TempDir& dir, const std::string& file, const std::string& text) {
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  std::string error;
  EXPECT_TRUE(WriteRobotLogDir(dir.str(), log, &error)) << error;
  if (!file.empty()) WriteText(dir / file, text);
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadRobotLogDir(dir.str(), &back, &e)) << file;
  EXPECT_EQ(e.file, file.empty() ? e.file : dir / file) << e.ToString();
  return e;
}

void ExpectError(const LoadError& e, int line, int column, const std::string& words) {
  EXPECT_EQ(e.line, line) << e.ToString();
  EXPECT_EQ(e.column, column) << e.ToString();
  EXPECT_NE(e.message.find(words), std::string::npos) << e.ToString();
}

TEST(RobotLogTest, BadUnitsAndFilesInATopicDirectory) {
  TempDir dir("bad_dir");
  const std::string ph = "t_ns,ch,P1,P2,P3,P4\n";
  // Gauge vacuum where raw absolute pressure belongs (P3 on the second row).
  ExpectError(LoadWith(dir, "pressure.csv",
                       ph + "1000000000,1,101000,101000,101000,101000\n"
                            "1010000000,1,101000,101000,12.5,101000\n"
                            "1020000000,1,101000,101000,101000,101000\n"),
              3, 5, "not an absolute pressure");
  // Absolute pressure in kPa: refused as well (too small for Pa).
  ExpectError(LoadWith(dir, "pressure.csv", "1000000000,1,101,101,101,101\n"
                                            "1010000000,1,101,101,101,101\n"),
              1, 3, "gauge vacuum or another unit");
  ExpectError(LoadWith(dir, "pressure.csv", "1000000000,1,1e6,1e5,1e5,1e5\n"), 1, 3,
              "above the sensor's absolute range");
  // Stamps in microseconds: spacing of 10 ns per 10 ms sample.
  ExpectError(LoadWith(dir, "pressure.csv", ph + "1000,1,1e5,1e5,1e5,1e5\n"
                                                 "1010,1,1e5,1e5,1e5,1e5\n"
                                                 "1020,1,1e5,1e5,1e5,1e5\n"),
              3, 1, "not nanoseconds");
  const std::string pose_h =
      "t_ns,orientation.w,orientation.x,orientation.y,orientation.z,position.x,position.y,"
      "position.z\n";
  // Pose in millimetres.
  ExpectError(LoadWith(dir, "tool_pose.csv",
                       pose_h + "1700000000000000000,1,0,0,0,600,100,5\n"),
              2, 6, "millimetres");
  // A quaternion that is not unit.
  ExpectError(LoadWith(dir, "tool_pose.csv",
                       pose_h + "1700000000000000000,1,0,0,0,0.6,0.1,0.2\n"
                                "1700000000010000000,0.5,0,0,0,0.6,0.1,0.2\n"),
              3, 2, "not a unit quaternion");
  ExpectError(LoadWith(dir, "pwm.csv", "1700000000000000000,300\n"), 1, 2, "outside 0..255");
  // An optional stream that is present must not be empty.
  ExpectError(LoadWith(dir, "ft.csv", "t_ns,force.x,force.y,force.z,torque.x,torque.y,torque.z\n"),
              0, 0, "empty stream");
  // A required file missing, a directory that does not exist, two files for one topic.
  std::string error;
  ASSERT_TRUE(WriteRobotLogDir(dir.str(), MakeRobotLog(TwinRun(), LogPerturbation()), &error));
  fs::remove(dir / "tool_pose.csv");
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadRobotLogDir(dir.str(), &back, &e));
  EXPECT_EQ(e.file, dir / "tool_pose.csv");
  EXPECT_NE(e.message.find("no such file"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadRobotLogDir(dir / "nowhere", &back, &e));
  EXPECT_EQ(e.file, dir / "nowhere");
  EXPECT_NE(e.message.find("no such directory"), std::string::npos);
  WriteText(dir / "tool_pose.csv", "1,1,0,0,0,0,0,0\n");
  WriteText(dir / "pose.csv", "1,1,0,0,0,0,0,0\n");
  EXPECT_FALSE(LoadRobotLogDir(dir.str(), &back, &e));
  EXPECT_NE(e.message.find("two files for one topic"), std::string::npos) << e.ToString();
  TopicTable table;
  EXPECT_FALSE(ReadTopicCsv(dir / "none.csv", GetStreamSpec(StreamId::kFt), &table, &e));
  EXPECT_EQ(e.ToString(), dir / "none.csv" + ": no such file");
}

TEST(RobotLogTest, BadPlainLogsNameLineAndColumn) {
  TempDir dir("bad_plain");
  const std::string h = "t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa\n";
  const std::string ok_row = "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n";
  struct Case {
    std::string text;
    int line, column;
    const char* words;
  } cases[] = {
      {h + ok_row + "0.01,0.1,0.2,0.3,1,0,0,0,101325,20,30,40\n", 3, 9, "absolute pressure"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,-900,-9000\n", 2, 12, "vacuum written negative"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_kpa,p2_pa,p3_pa,p4_pa\n" + ok_row, 1, 9, "unknown column"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,p1_pa,p2_pa,p3_pa,p4_pa\n" + ok_row, 1, 12,
       "missing column 'qz'"},
      {"t_s,x_m,y_m,z_m,qw,qx,qy,qz,p1_pa,p2_pa,p3_pa,p4_pa,x_m\n", 1, 13, "appears twice"},
      {h.substr(0, h.size() - 1) + ",fx_n\n", 1, 14, "missing column 'fy_n'"},
      {ok_row, 1, 1, "header row"},
      {h + ok_row + "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n", 3, 1, "duplicate time"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,30\n", 2, 12, "missing column"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,30,40,50\n", 2, 13, "unexpected extra column"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,20,nan,40\n", 2, 11, "non-finite"},
      {h + "0,0.1,0.2,0.3,1,0,0,0,10,2O,30,40\n", 2, 10, "'2O' is not a number (p2_pa)"},
      {h + "0,100,0.2,0.3,1,0,0,0,10,20,30,40\n", 2, 2, "millimetres"},
      {h + "0,0.1,0.2,0.3,0.9,0,0,0,10,20,30,40\n", 2, 5, "not a unit quaternion"},
      {h + "1.7e18,0.1,0.2,0.3,1,0,0,0,10,20,30,40\n", 2, 1, "nanoseconds"},
      {h, 0, 0, "empty log"},
  };
  for (const Case& c : cases) {
    WriteText(dir / "plain.csv", c.text);
    ProcessedLog p;
    LoadError e;
    EXPECT_FALSE(LoadPlainLog(dir / "plain.csv", &p, &e)) << c.text;
    EXPECT_EQ(e.file, dir / "plain.csv");
    ExpectError(e, c.line, c.column, c.words);
  }
  ProcessedLog p;
  LoadError e;
  EXPECT_FALSE(LoadPlainLog(dir / "missing.csv", &p, &e));
  EXPECT_NE(e.ToString().find("missing.csv: no such file"), std::string::npos);
  EXPECT_FALSE(LoadPlainLog(dir.str(), &p, &e));
  EXPECT_NE(e.message.find("is a directory"), std::string::npos);
}

TEST(RobotLogTest, BadMatFilesNameVariableRowAndColumn) {
  TempDir dir("bad_mat");
  const std::string path = dir / "bad.mat";
  // Starts from a good file each time and replaces one variable.
  auto check = [&](const char* name, matio_classes cls, matio_types type, size_t rows,
                   size_t cols, void* data, int line, int column, const std::string& words) {
    std::string error;
    ASSERT_TRUE(WriteRobotLogMat(path, MakeRobotLog(TwinRun(), LogPerturbation()), &error));
    mat_t* mat = Mat_Open(path.c_str(), MAT_ACC_RDWR);
    ASSERT_NE(mat, nullptr);
    Mat_VarDelete(mat, name);
    if (data) MatWrite(mat, name, cls, type, rows, cols, data);
    Mat_Close(mat);
    RobotLog log;
    LoadError e;
    EXPECT_FALSE(LoadRobotLogMat(path, &log, &e)) << words;
    EXPECT_EQ(e.file, path);
    ExpectError(e, line, column, words);
  };
  check("pose", MAT_C_DOUBLE, MAT_T_DOUBLE, 0, 0, nullptr, 0, 0, "'pose' is missing");
  double transposed[6 * 2] = {0};
  check("pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 6, 2, transposed, 0, 0, "transpose it");
  char text[] = "abcdef";
  check("pressure", MAT_C_CHAR, MAT_T_UINT8, 1, 6, text, 0, 0, "real numeric matrix");
  const double t0 = 1.6e18;
  double nan_cell[2 * 6] = {t0, t0 + 1e7, 1, 1, 1e5, 1e5, 1e5, NAN, 1e5, 1e5, 1e5, 1e5};
  check("pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, nan_cell, 2, 4, "non-finite");
  double backwards[2 * 6] = {t0, t0 - 1e7, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5};
  check("pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, backwards, 2, 1, "non-monotonic");
  double seconds[2 * 6] = {1.7e9 + 0.5, 1.7e9 + 0.51, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5,
                           1e5, 1e5};
  check("pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, seconds, 1, 1, "integer number of ns");
  double gauge[2 * 6] = {t0, t0 + 1e7, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 250, 1e5, 1e5};
  check("pressure", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, gauge, 2, 5, "not an absolute pressure");
  double empty_ft[1] = {0};
  check("ft", MAT_C_DOUBLE, MAT_T_DOUBLE, 0, 7, empty_ft, 0, 0, "empty stream");

  RobotLog log;
  LoadError e;
  WriteText(dir / "text.mat", "this is not a MATLAB file\n");
  EXPECT_FALSE(LoadRobotLogMat(dir / "text.mat", &log, &e));
  EXPECT_NE(e.message.find("not a MATLAB file"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadRobotLogMat(dir / "nothing.mat", &log, &e));
  EXPECT_EQ(e.ToString(), dir / "nothing.mat" + ": no such file");
}

TEST(RobotLogTest, ProcessingRefusesLogsItCannotAlign) {
  RobotLog log = StepLog();
  for (double& t : log.tool_pose.t_s) t += 100;  // a pose clock from another epoch
  ProcessedLog p;
  LoadError e;
  EXPECT_FALSE(ProcessRobotLog(log, ProcessOptions(), &p, &e));
  EXPECT_NE(e.message.find("do not overlap"), std::string::npos) << e.ToString();
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

TEST(RobotLogTest, RandomBytesNeverCrashTheReaders) {
  // A deterministic slice of what the fuzz target does, so every test run covers it.
  std::mt19937 rng(7);
  const std::string alphabet = "0123456789,,,\n\n.-+eEnaif \r\"t_P\xff";
  for (int i = 0; i < 2000; ++i) {
    std::string text(rng() % 200, ' ');
    for (char& c : text) c = alphabet[rng() % alphabet.size()];
    TopicTable table;
    ProcessedLog plain;
    LoadError e;
    for (const StreamSpec& spec : AllStreamSpecs()) {
      if (!ParseTopicCsv(text, "r.csv", spec, &table, &e)) {
        EXPECT_FALSE(e.message.empty());
      }
    }
    if (!ParsePlainLog(text, "r.csv", &plain, &e)) {
      EXPECT_FALSE(e.message.empty());
    }
  }
}

}  // namespace
}  // namespace ssc
