// Robot logs: the lab's formats exactly as its logger and MAT saver write them (both logger
// versions), the plain CSV, the processing steps on signals with a known answer, every bad-log
// case with the file, line and column it must name, and seeded perturbations of valid files.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "robotlog/robot_log.h"
#include "robotlog/synthetic_log.h"
#include "robotlog/text_cells.h"

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

// The disk benchmark script's arguments and a short edgeFollowing_history.
LabRunArgs DiskArgs() {
  LabRunArgs a;
  a.p_ref_pa = 100;
  a.beta = 2.0;
  a.d_lat_m = 0.0025;
  a.disk_radius_mm = 35;
  a.start_offset_m = 0.031;
  a.p_lims_pa = {100, 100};
  a.alpha_beta = {0.0, 2.0, 0.0, 2.0};
  a.success = 1;
  a.fz_set_n = {1.1, 1.2};
  for (int i = 0; i < 5; ++i) {
    HistoryRow h;
    h.t_s = 3.0 + 0.25 * i;
    h.x_m = -0.6 + 0.001 * i;
    h.y_m = 0.1;
    h.r_p = {0.6, 0.8};
    h.corr_p = {i % 2 ? 0.0 : -0.8, i % 2 ? 0.0 : 0.6};
    h.r_p_final = {0.28, 0.96};
    h.f_normal_n = -1.15;
    h.p_pa = {-50.0 - i, -150.0, -160.0, -40.0};
    a.history.push_back(h);
  }
  return a;
}

std::string ReadText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

std::string Line(const std::string& text, int n) {  // 1-based
  size_t at = 0;
  for (int i = 1; i < n; ++i) at = text.find('\n', at) + 1;
  return text.substr(at, text.find('\n', at) - at);
}

// What the logger writes (lab-logs.md): the first two lines of each topic file, per version.
TEST(RobotLogTest, TopicCsvFilesAreWrittenAsTheLabLoggerWritesThem) {
  TempDir dir("lab_csv");
  LogPerturbation o;
  o.t0_ns = 1726180212003000000LL;  // 2024-09-12 22:30:12 UTC
  const RobotLog log = MakeRobotLog(TwinRun(), o);
  std::vector<std::string> files;
  std::string error;
  ASSERT_TRUE(WriteTopicCsvRecording(dir / "newer", log, LoggerVersion::kNewer, &files, &error))
      << error;
  ASSERT_EQ(files.size(), 4u);
  const std::string stamp = "2024_0912_223012";
  const std::string p = ReadText(dir / ("newer/dataLog_" + stamp + "__SensorPacket.csv"));
  EXPECT_EQ(Line(p, 1),
            "ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],"
            "/SensorPacket.data[2],/SensorPacket.data[3]");
  // ns stamp, int ch, then the float32 tuple's text: ", " inside, "," outside.
  EXPECT_EQ(Line(p, 2), "1726180212003000000,4,101325.0, 101325.0, 101325.0, 101325.0");
  const std::string pose = ReadText(dir / ("newer/dataLog_" + stamp + "__endEffectorPose.csv"));
  EXPECT_EQ(Line(pose, 1),
            "ROStimestamp,/endEffectorPose.pose.orientation.w,/endEffectorPose.pose.orientation.x,"
            "/endEffectorPose.pose.orientation.y,/endEffectorPose.pose.orientation.z,"
            "/endEffectorPose.pose.position.x,/endEffectorPose.pose.position.y,"
            "/endEffectorPose.pose.position.z");
  EXPECT_EQ(Line(ReadText(dir / ("newer/dataLog_" + stamp + "__pwm.csv")), 2),
            "1726180212003000000,100");
  EXPECT_EQ(Line(ReadText(dir / ("newer/dataLog_" + stamp + "__netft_data.csv")), 1).substr(0, 45),
            "ROStimestamp,/netft_data.wrench.force.x,/netf");
  ASSERT_TRUE(WriteTopicCsvRecording(dir / "older", log, LoggerVersion::kOlder, &files, &error));
  const std::string q = ReadText(dir / ("older/dataLog_" + stamp + "__SensorPacket.csv"));
  EXPECT_EQ(Line(q, 1),
            "ROStimestamp,/SensorPacket.data,/SensorPacket.data,/SensorPacket.data,"
            "/SensorPacket.data");
  EXPECT_EQ(Line(q, 2), "1726180212003000000,101325.0, 101325.0, 101325.0, 101325.0");
  // Python's float text.
  EXPECT_EQ(text::PyFloat(101339.671875), "101339.671875");
  EXPECT_EQ(text::PyFloat(1e-5), "1e-05");
  EXPECT_EQ(text::PyFloat(0.0001), "0.0001");
  EXPECT_EQ(text::PyFloat(-0.63), "-0.63");
  EXPECT_EQ(text::PyFloat(1e16), "1e+16");
  EXPECT_EQ(text::PyFloat(123.0), "123.0");
}

void ExpectSameAsWritten(const RobotLog& log, const RobotLog& back) {
  EXPECT_EQ(back.t0_ns, log.t0_ns);
  ASSERT_EQ(back.pressure_abs.size(), log.pressure_abs.size());
  for (size_t i = 0; i < log.pressure_abs.size(); ++i) {
    EXPECT_NEAR(back.pressure_abs.t_s[i], log.pressure_abs.t_s[i], 1e-9);
    for (int c = 1; c <= 4; ++c) {  // float32 on the wire
      EXPECT_EQ(back.pressure_abs.rows[i][c],
                static_cast<double>(static_cast<float>(log.pressure_abs.rows[i][c])));
    }
    EXPECT_EQ(back.pressure_abs.rows[i][0], 4);
  }
  ExpectSameStream(log.tool_pose, back.tool_pose, "pose");
  ExpectSameStream(log.ft, back.ft, "ft");
  ExpectSameStream(log.pwm, back.pwm, "pwm");
}

TEST(RobotLogTest, TopicCsvRecordingReadsFromItsFolderOrAnyOfItsFiles) {
  TempDir dir("lab_read");
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  for (LoggerVersion version : {LoggerVersion::kNewer, LoggerVersion::kOlder}) {
    const std::string folder = dir / (version == LoggerVersion::kNewer ? "n" : "o");
    std::vector<std::string> files;
    std::string error;
    ASSERT_TRUE(WriteTopicCsvRecording(folder, log, version, &files, &error)) << error;
    // An unused topic beside them is skipped.
    WriteText(folder + "/" + TopicFileName(RecordingStamp(log.t0_ns), "/sync"),
              "ROStimestamp,/sync.data\n1700000000000000000,1\n");
    RobotLog back;
    LoadError e;
    ASSERT_TRUE(LoadTopicCsvRecording(folder, &back, &e)) << e.ToString();
    ExpectSameAsWritten(log, back);
    EXPECT_EQ(back.pressure_abs.lines.front(), 2);  // after the header
    for (const std::string& file : files) {
      ASSERT_TRUE(LoadTopicCsvRecording(file, &back, &e)) << file << ": " << e.ToString();
      ExpectSameAsWritten(log, back);
    }
    TopicTable table;
    ASSERT_TRUE(ReadTopicCsv(files[0], &table, &e)) << e.ToString();
    EXPECT_EQ(table.header.version, version);
    EXPECT_EQ(table.header.has_ch, version == LoggerVersion::kNewer);
  }
  // Two recordings in one folder: give a file.
  LogPerturbation later;
  later.t0_ns += 3600LL * 1000000000LL;
  std::string error;
  ASSERT_TRUE(WriteTopicCsvRecording(dir / "n", MakeRobotLog(TwinRun(), later),
                                     LoggerVersion::kNewer, nullptr, &error));
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadTopicCsvRecording(dir / "n", &back, &e));
  EXPECT_NE(e.message.find("holds 2 recordings"), std::string::npos) << e.ToString();
  EXPECT_NE(e.message.find("give one of its files"), std::string::npos) << e.ToString();
}

TEST(RobotLogTest, MatRoundTripWithTheScriptsArgumentsAndHistory) {
  TempDir dir("mat");
  RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  log.args = DiskArgs();
  for (LoggerVersion version : {LoggerVersion::kNewer, LoggerVersion::kOlder}) {
    for (MatVersion mat_version : {MatVersion::kMat5, MatVersion::kMat73}) {
      const std::string path = dir / DiskBenchmarkMatName(RecordingStamp(log.t0_ns), log.args);
      std::string error;
      ASSERT_TRUE(WriteRobotLogMat(path, log, &error, version, mat_version)) << error;
      RobotLog back;
      LoadError e;
      ASSERT_TRUE(LoadRobotLogMat(path, &back, &e)) << e.ToString();
      EXPECT_EQ(back.tool_pose.variable, "endEffectorPose_data");
      EXPECT_EQ(back.ft.variable, "netftdata_data");
      // Stamps travel as doubles of ns: 256 ns resolution at 1.7e18 ns.
      ASSERT_EQ(back.pressure_abs.size(), log.pressure_abs.size());
      for (size_t i = 0; i < log.pressure_abs.size(); ++i) {
        EXPECT_NEAR(back.pressure_abs.t_s[i], log.pressure_abs.t_s[i], 300e-9);
        EXPECT_EQ(back.pressure_abs.rows[i][2],
                  static_cast<double>(static_cast<float>(log.pressure_abs.rows[i][2])));
      }
      EXPECT_EQ(back.tool_pose.rows, log.tool_pose.rows);
      EXPECT_EQ(back.ft.rows, log.ft.rows);
      EXPECT_EQ(back.pwm.rows, log.pwm.rows);
      const LabRunArgs& a = back.args;
      EXPECT_EQ(a.p_ref_pa, 100);
      EXPECT_EQ(a.d_lat_m, 0.0025);
      EXPECT_EQ(a.disk_radius_mm, 35);
      EXPECT_EQ(a.start_offset_m, 0.031);
      EXPECT_EQ(a.fz_set_n, (std::vector<double>{1.1, 1.2}));
      EXPECT_EQ(a.success, 1);
      ASSERT_EQ(a.history.size(), 5u);
      EXPECT_EQ(a.history[3].t_s, 3.75);
      EXPECT_EQ(a.history[2].corr_p, (std::array<double, 2>{-0.8, 0.6}));
      EXPECT_EQ(a.history[1].p_pa[0], -51.0);
      EXPECT_EQ(a.history[4].f_normal_n, -1.15);
    }
  }
  EXPECT_EQ(DiskBenchmarkMatName("2024_0912_153012", DiskArgs()),
            "DataLog_2024_0912_153012_seb_testEdgeFollowing_refP_100_beta_2.0_step_0.0025_"
            "deleteMe.mat");
}

// A .mat made with matio's own API as SciPy's savemat makes it from pandas tables: char matrices
// of names (space-padded; the older logger's repeated names as pandas renames them), double
// data, an int64 single-row pwm_data, int64 and double arguments.
void MatWrite(mat_t* mat, const char* name, matio_classes cls, matio_types type, size_t rows,
              size_t cols, void* data) {
  size_t dims[2] = {rows, cols};
  matvar_t* v = Mat_VarCreate(name, cls, type, 2, dims, data, 0);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(Mat_VarWrite(mat, v, MAT_COMPRESSION_ZLIB), 0);
  Mat_VarFree(v);
}

void MatNames(mat_t* mat, const char* name, const std::vector<std::string>& rows) {
  size_t len = 0;
  for (const std::string& r : rows) len = std::max(len, r.size());
  std::vector<char> data(rows.size() * len, ' ');
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) data[c * rows.size() + r] = rows[r][c];
  }
  MatWrite(mat, name, MAT_C_CHAR, MAT_T_UINT8, rows.size(), len, data.data());
}

TEST(RobotLogTest, MatAsSavematWritesItReadsBack) {
  TempDir dir("mat_api");
  const std::string path = dir / "DataLog_2024_0912_153012_x.mat";
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  ASSERT_NE(mat, nullptr);
  const double t0 = 1.7e18;
  // Column-major: 60 samples at 100 Hz (older logger: no ch; pandas' data, data.1, ...).
  const size_t n = 60;
  std::vector<double> pressure(n * 5), pose(n * 8);
  for (size_t i = 0; i < n; ++i) {
    pressure[i] = pose[i] = t0 + 1e7 * static_cast<double>(i);
    for (size_t c = 1; c < 5; ++c) pressure[c * n + i] = 101000 - 10.0 * static_cast<double>(c);
    pose[1 * n + i] = 1;  // w
    pose[5 * n + i] = -0.63;
    pose[6 * n + i] = 0.097;
    pose[7 * n + i] = 0.2;
  }
  MatNames(mat, "SensorPacket_columnName",
           {"ROStimestamp", "/SensorPacket.data", "/SensorPacket.data.1", "/SensorPacket.data.2",
            "/SensorPacket.data.3"});
  MatWrite(mat, "SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, n, 5, pressure.data());
  MatNames(mat, "endEffectorPose_columnName",
           {"ROStimestamp", "/endEffectorPose.pose.orientation.w",
            "/endEffectorPose.pose.orientation.x", "/endEffectorPose.pose.orientation.y",
            "/endEffectorPose.pose.orientation.z", "/endEffectorPose.pose.position.x",
            "/endEffectorPose.pose.position.y", "/endEffectorPose.pose.position.z"});
  MatWrite(mat, "endEffectorPose_data", MAT_C_DOUBLE, MAT_T_DOUBLE, n, 8, pose.data());
  int64_t pwm[2] = {1700000000000000123LL, 100};  // one row: published once
  MatNames(mat, "pwm_columnName", {"ROStimestamp", "/pwm.data"});
  MatWrite(mat, "pwm_data", MAT_C_INT64, MAT_T_INT64, 1, 2, pwm);
  int64_t pref = 150, radius = 35;
  double d_lat = 0.005, beta = 1.5;
  MatWrite(mat, "Pref", MAT_C_INT64, MAT_T_INT64, 1, 1, &pref);
  MatWrite(mat, "diskRadius", MAT_C_INT64, MAT_T_INT64, 1, 1, &radius);
  MatWrite(mat, "d_lat", MAT_C_DOUBLE, MAT_T_DOUBLE, 1, 1, &d_lat);
  MatWrite(mat, "beta", MAT_C_DOUBLE, MAT_T_DOUBLE, 1, 1, &beta);
  double history[2 * 14] = {0.5, 0.75, -0.6, -0.6, 0.1,  0.1,  1,  1,  0,  0,  0,  0,   0,   0,
                            1,   1,    0,    0,    -1.1, -1.2, -5, -6, -7, -8, -9, -10, -11, -12};
  MatWrite(mat, "edgeFollowing_history", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 14, history);
  char note[] = "a note";
  MatWrite(mat, "note", MAT_C_CHAR, MAT_T_UINT8, 1, 6, note);
  Mat_Close(mat);

  RobotLog log;
  LoadError e;
  ASSERT_TRUE(LoadRobotLogMat(path, &log, &e)) << e.ToString();
  EXPECT_EQ(log.t0_ns, 1700000000000000000LL);
  ASSERT_EQ(log.pressure_abs.size(), n);
  EXPECT_EQ(log.pressure_abs.rows[1], (std::vector<double>{4, 100990, 100980, 100970, 100960}));
  EXPECT_EQ(log.tool_pose.rows[2][4], -0.63);
  ASSERT_EQ(log.pwm.size(), 1u);
  EXPECT_NEAR(log.pwm.t_s[0], 123e-9, 1e-12);  // int64 stamps stay exact
  EXPECT_EQ(log.pwm.rows[0][0], 100);
  EXPECT_EQ(log.args.p_ref_pa, 150);
  EXPECT_EQ(log.args.beta, 1.5);
  EXPECT_EQ(log.args.d_lat_m, 0.005);
  ASSERT_EQ(log.args.history.size(), 2u);
  EXPECT_EQ(log.args.history[1].r_p, (std::array<double, 2>{1, 0}));
  EXPECT_EQ(log.args.history[1].f_normal_n, -1.2);
  EXPECT_EQ(log.args.history[0].p_pa, (std::array<double, 4>{-5, -7, -9, -11}));
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

const char kPressureHeader[] =
    "ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],"
    "/SensorPacket.data[2],/SensorPacket.data[3]\n";

struct BadCase {
  std::string text;
  int line, column;
  const char* words;
};

TEST(RobotLogTest, BadTopicCsvErrorsNameFileLineAndColumn) {
  const std::string h = kPressureHeader;
  const std::string ok = "1700000000000000000,4,1e5, 1e5, 1e5, 1e5\n";
  const BadCase cases[] = {
      {h + "1700000000000000000,4,1e5, 1e5, 1e5\n", 2, 6, "missing column"},
      {h + "1700000000000000000,4,1e5, 1e5, 1e5, 1e5, 7\n", 2, 7, "unexpected extra column"},
      {h + "1700000000000000000,4,1e5, abc, 1e5, 1e5\n", 2, 4, "not a number (P2)"},
      {h + "1700000000000000000,4,1e5, , 1e5, 1e5\n", 2, 4, "empty cell (P2)"},
      {h + ok + "1700000000010000000,4,1e5, nan, 1e5, 1e5\n", 3, 4, "non-finite"},
      {h + "1700000000000000000,4,1e5, 1e999, 1e5, 1e5\n", 2, 4, "non-finite"},
      {h + "1700000000010000000,4,1e5, 1e5, 1e5, 1e5\n" + ok, 3, 1, "non-monotonic"},
      {h + ok + "\n" + ok, 4, 1, "duplicate"},
      {h + "1700000000.5,4,1e5, 1e5, 1e5, 1e5\n", 2, 1, "not an integer number of nanoseconds"},
      {h + "-5,4,1e5, 1e5, 1e5, 1e5\n", 2, 1, "negative time stamp"},
      {ok, 1, 1, "no header line"},
      {"t_ns,ch,P1,P2,P3,P4\n" + ok, 1, 1, "not the logger's time column 'ROStimestamp'"},
      {"ROStimestamp,ch,data[0]\n", 1, 2, "expected <topic>.<field>"},
      {"ROStimestamp,/SensorPacket.ch,/endEffectorPose.pose.position.x\n", 1, 3, "one topic"},
      {"ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],"
       "/SensorPacket.data[2],/SensorPacket.pressure4\n",
       1, 6, "unknown field 'pressure4'"},
      {"ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],"
       "/SensorPacket.data[2]\n",
       1, 6, "missing field 'data[3]'"},
      {"ROStimestamp,/SensorPacket.data,/SensorPacket.data,/SensorPacket.data,"
       "/SensorPacket.data,/SensorPacket.data\n",
       1, 6, "more 'data' columns than the 4 chambers"},
      {"ROStimestamp,/SensorPacket.data,/SensorPacket.data[1],/SensorPacket.data[2],"
       "/SensorPacket.data[3]\n",
       1, 0, "mixes indexed"},
      {"ROStimestamp,/SensorPacket.ch,/SensorPacket.ch,/SensorPacket.data[0],"
       "/SensorPacket.data[1],/SensorPacket.data[2],/SensorPacket.data[3]\n",
       1, 3, "appears twice"},
      {h + "\n", 0, 0, "empty stream"},
      {"", 0, 0, "empty file"},
      {"ROStimestamp,/pwm.data\n1700000000000000000,50\n1700000000100000000,\xff\xfe\n", 3, 2,
       "'\\xFF\\xFE' is not a number"},
  };
  for (const BadCase& c : cases) {
    TopicTable table;
    LoadError e;
    EXPECT_FALSE(ParseTopicCsv(c.text, "some.csv", &table, &e)) << c.text;
    EXPECT_EQ(e.file, "some.csv");
    EXPECT_EQ(e.line, c.line) << c.text << " -> " << e.ToString();
    EXPECT_EQ(e.column, c.column) << c.text << " -> " << e.ToString();
    EXPECT_NE(e.message.find(c.words), std::string::npos) << c.text << " -> " << e.ToString();
  }
  // ToString puts it together as compilers do.
  const LoadError e{"dir/x.csv", 12, 4, "'abc' is not a number (P2)"};
  EXPECT_EQ(e.ToString(), "dir/x.csv:12:4: 'abc' is not a number (P2)");
  EXPECT_EQ((LoadError{"x.mat", 0, 0, "no such file"}).ToString(), "x.mat: no such file");
}

// A recording with one topic file's text replaced, loaded: the error must name that file.
struct Recording {
  std::string folder, pressure, pose, ft, pwm;
};
Recording WriteRecording(const TempDir& dir) {
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  std::string error;
  fs::remove_all(dir.str());
  EXPECT_TRUE(WriteTopicCsvRecording(dir.str(), log, LoggerVersion::kNewer, nullptr, &error));
  const std::string stamp = RecordingStamp(log.t0_ns);
  return {dir.str(), dir / TopicFileName(stamp, "/SensorPacket"),
          dir / TopicFileName(stamp, "/endEffectorPose"), dir / TopicFileName(stamp, "/netft_data"),
          dir / TopicFileName(stamp, "/pwm")};
}

LoadError LoadWith(const TempDir& dir, std::string Recording::*file, const std::string& text) {
  const Recording r = WriteRecording(dir);
  WriteText(r.*file, text);
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadTopicCsvRecording(r.folder, &back, &e));
  EXPECT_EQ(e.file, r.*file) << e.ToString();
  return e;
}

void ExpectError(const LoadError& e, int line, int column, const std::string& words) {
  EXPECT_EQ(e.line, line) << e.ToString();
  EXPECT_EQ(e.column, column) << e.ToString();
  EXPECT_NE(e.message.find(words), std::string::npos) << e.ToString();
}

// n pressure rows from t0 every dt_ns, all at `value` Pa.
std::string PressureRows(long long t0, long long dt_ns, int n, const std::string& value) {
  std::string s = kPressureHeader;
  for (int i = 0; i < n; ++i) {
    s += std::to_string(t0 + dt_ns * i) + ",4," + value + ", " + value + ", " + value + ", " +
         value + "\n";
  }
  return s;
}

TEST(RobotLogTest, BadUnitsAndFilesInARecording) {
  TempDir dir("bad_dir");
  const long long t0 = 1700000000000000000LL;
  // Gauge vacuum where raw absolute pressure belongs (P3 on the second row).
  ExpectError(LoadWith(dir, &Recording::pressure,
                       std::string(kPressureHeader) +
                           "1700000000000000000,4,101000, 101000, 101000, 101000\n"
                           "1700000000010000000,4,101000, 101000, 12.5, 101000\n"),
              3, 5, "not an absolute pressure");
  // Absolute pressure in kPa: refused as well (too small for Pa).
  ExpectError(LoadWith(dir, &Recording::pressure, PressureRows(t0, 10000000, 100, "101.3")), 2, 3,
              "gauge vacuum or another unit");
  ExpectError(LoadWith(dir, &Recording::pressure, PressureRows(t0, 10000000, 100, "1e6")), 2, 3,
              "above the sensor's absolute range");
  // Stamps in microseconds at 50 Hz read as ns: 20 us apart.
  ExpectError(LoadWith(dir, &Recording::pressure, PressureRows(t0, 20000, 3000, "1e5")), 3, 1,
              "us read as ns");
  // Spacing right (1 ms) but the recording lasts 0.3 s.
  ExpectError(LoadWith(dir, &Recording::pressure, PressureRows(t0, 1000000, 300, "1e5")), 301, 1,
              "shorter than 0.5 s");
  // Stamps in microseconds since the epoch (1970), right spacing.
  ExpectError(
      LoadWith(dir, &Recording::pressure, PressureRows(1700000000000000LL, 10000000, 100, "1e5")),
      2, 1, "not ROS time in ns");
  const std::string pose_h =
      "ROStimestamp,/endEffectorPose.pose.orientation.w,/endEffectorPose.pose.orientation.x,"
      "/endEffectorPose.pose.orientation.y,/endEffectorPose.pose.orientation.z,"
      "/endEffectorPose.pose.position.x,/endEffectorPose.pose.position.y,"
      "/endEffectorPose.pose.position.z\n";
  // Pose in millimetres.
  ExpectError(LoadWith(dir, &Recording::pose, pose_h + "1700000000000000000,1,0,0,0,600,100,5\n"),
              2, 6, "millimetres");
  // A quaternion that is not unit.
  ExpectError(LoadWith(dir, &Recording::pose,
                       pose_h + "1700000000000000000,1,0,0,0,0.6,0.1,0.2\n"
                                "1700000000010000000,0.5,0,0,0,0.6,0.1,0.2\n"),
              3, 2, "not a unit quaternion");
  ExpectError(LoadWith(dir, &Recording::pwm, "ROStimestamp,/pwm.data\n1700000000000000000,300\n"),
              2, 2, "outside 0..255");
  // An optional stream that is present must not be empty.
  ExpectError(LoadWith(dir, &Recording::ft,
                       "ROStimestamp,/netft_data.wrench.force.x,/netft_data.wrench.force.y,"
                       "/netft_data.wrench.force.z,/netft_data.wrench.torque.x,"
                       "/netft_data.wrench.torque.y,/netft_data.wrench.torque.z\n"),
              0, 0, "empty stream");
  // A required topic missing; a folder that does not exist; two files of one topic.
  Recording r = WriteRecording(dir);
  fs::remove(r.pose);
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadTopicCsvRecording(r.pressure, &back, &e));
  EXPECT_EQ(e.file, r.pressure);
  EXPECT_NE(e.message.find("no file of topic /endEffectorPose"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadTopicCsvRecording(dir / "nowhere", &back, &e));
  EXPECT_NE(e.message.find("no such file or folder"), std::string::npos);
  r = WriteRecording(dir);
  fs::copy_file(r.pose, r.ft, fs::copy_options::overwrite_existing);
  EXPECT_FALSE(LoadTopicCsvRecording(r.folder, &back, &e));
  EXPECT_NE(e.message.find("a second file of topic /endEffectorPose"), std::string::npos)
      << e.ToString();
  TopicTable table;
  EXPECT_FALSE(ReadTopicCsv(dir / "none.csv", &table, &e));
  EXPECT_EQ(e.ToString(), dir / "none.csv" + ": no such file");
}

// What a logger stopped mid-row or an unfinished copy leaves, and inputs that are not files.
TEST(RobotLogTest, CutFilesAndNonRegularFilesAreTrimmedWithAWarningOrRefused) {
  TempDir dir("cut");
  {  // A topic file whose last row lost its line end and part of its last number: dropped, said.
    const Recording r = WriteRecording(dir);
    RobotLog whole, cut;
    LoadError e;
    ASSERT_TRUE(LoadTopicCsvRecording(r.folder, &whole, &e)) << e.ToString();
    EXPECT_TRUE(whole.warnings.empty());
    std::ifstream in(r.pressure, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_EQ(text.back(), '\n');
    WriteText(r.pressure, text.substr(0, text.size() - 4));
    ASSERT_TRUE(LoadTopicCsvRecording(r.folder, &cut, &e)) << e.ToString();
    EXPECT_EQ(cut.pressure_abs.size() + 1, whole.pressure_abs.size());
    ASSERT_EQ(cut.warnings.size(), 1u);
    EXPECT_NE(cut.warnings[0].find("no line end"), std::string::npos) << cut.warnings[0];
    EXPECT_NE(cut.warnings[0].find(r.pressure), std::string::npos) << cut.warnings[0];
  }
  {  // A .mat cut anywhere (level 5, plain and compressed) is refused, not read in part.
    RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
    log.args = DiskArgs();
    const std::string path = dir / "whole.mat", cut_path = dir / "cut.mat";
    std::string error;
    ASSERT_TRUE(WriteRobotLogMat(path, log, &error)) << error;
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    RobotLog back;
    LoadError e;
    ASSERT_TRUE(LoadRobotLogMat(path, &back, &e)) << e.ToString();
    for (size_t keep : {bytes.size() - 1, bytes.size() * 2 / 3, bytes.size() / 2, size_t{300}}) {
      WriteText(cut_path, bytes.substr(0, keep));
      EXPECT_FALSE(LoadRobotLogMat(cut_path, &back, &e)) << keep;
      EXPECT_NE(e.message.find("cut short"), std::string::npos) << keep << ": " << e.ToString();
    }
  }
  // A FIFO would block the reader for ever, a directory is no file: refused before opening.
  const std::string fifo = dir / "pipe.csv", fifo_mat = dir / "pipe.mat";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo(fifo_mat.c_str(), 0600), 0);
  ProcessedLog p;
  RobotLog log;
  TopicTable table;
  LoadError e;
  EXPECT_FALSE(LoadPlainLog(fifo, &p, &e));
  EXPECT_NE(e.message.find("not a regular file"), std::string::npos) << e.ToString();
  EXPECT_FALSE(ReadTopicCsv(fifo, &table, &e));
  EXPECT_NE(e.message.find("not a regular file"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadRobotLogMat(fifo_mat, &log, &e));
  EXPECT_NE(e.message.find("not a regular file"), std::string::npos) << e.ToString();
  EXPECT_FALSE(LoadRobotLogMat(dir.str(), &log, &e));
  EXPECT_NE(e.message.find("is a directory"), std::string::npos) << e.ToString();
}

// A line without an end: refused after kMaxLineBytes, never read whole.
TEST(RobotLogTest, ALongLineIsRefusedWithoutReadingItWhole) {
  TempDir dir("long_line");
  const std::string path = dir / "one_line.csv";
  {
    std::ofstream f(path, std::ios::binary);
    f << "ROStimestamp,/SensorPacket.ch";
    const std::string chunk(4096, '1');
    for (int i = 0; i < 256; ++i) f << ',' << chunk;  // 1 MB, no newline
  }
  TopicTable table;
  LoadError e;
  EXPECT_FALSE(ReadTopicCsv(path, &table, &e));
  ExpectError(e, 1, 0, "line longer than 64 KiB");
  ProcessedLog p;
  EXPECT_FALSE(LoadPlainLog(path, &p, &e));
  ExpectError(e, 1, 0, "line longer than 64 KiB");
  RobotLog log;
  EXPECT_FALSE(LoadTopicCsvRecording(path, &log, &e));
  ExpectError(e, 1, 0, "line longer than 64 KiB");
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

TEST(RobotLogTest, BadMatFilesNameVariableRowAndColumn) {
  TempDir dir("bad_mat");
  const std::string path = dir / "bad.mat";
  // Starts from a good file each time and replaces one variable.
  auto check = [&](const char* name, matio_classes cls, matio_types type, size_t rows, size_t cols,
                   void* data, int line, int column, const std::string& words) {
    std::string error;
    RobotLog good = MakeRobotLog(TwinRun(), LogPerturbation());
    good.args = DiskArgs();
    ASSERT_TRUE(WriteRobotLogMat(path, good, &error));
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
  check("endEffectorPose_columnName", MAT_C_DOUBLE, MAT_T_DOUBLE, 0, 0, nullptr, 0, 0,
        "no variable holds topic /endEffectorPose");
  check("endEffectorPose_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 0, 0, nullptr, 0, 0,
        "'endEffectorPose_data': missing");
  double transposed[6 * 2] = {0};
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 6, 2, transposed, 0, 0, "expected N x 6");
  char text[] = "abcdef";
  check("SensorPacket_data", MAT_C_CHAR, MAT_T_UINT8, 1, 6, text, 0, 0, "real numeric matrix");
  const double t0 = 1.6e18;
  double nan_cell[2 * 6] = {t0, t0 + 1e7, 1, 1, 1e5, 1e5, 1e5, NAN, 1e5, 1e5, 1e5, 1e5};
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, nan_cell, 2, 4, "non-finite");
  double backwards[2 * 6] = {t0, t0 - 1e7, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5};
  // The .mat reader's own check (the stream check behind it says "non-monotonic time").
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, backwards, 2, 1,
        "non-monotonic time stamp");
  double seconds[2 * 6] = {1.7e9 + 0.5, 1.7e9 + 0.51, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5, 1e5};
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, seconds, 1, 1,
        "integer number of ns");
  double gauge[2 * 6] = {t0, t0 + 1e7, 1, 1, 1e5, 1e5, 1e5, 1e5, 1e5, 250, 1e5, 1e5};
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 6, gauge, 2, 5,
        "not an absolute pressure");
  // Stamps in us at 50 Hz stored as ns: 20 us apart over 0.06 s.
  std::vector<double> us(3000 * 6, 1e5);
  for (size_t i = 0; i < 3000; ++i) {
    us[i] = 1.7e18 + 20000.0 * static_cast<double>(i);
    us[3000 + i] = 4;
  }
  check("SensorPacket_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 3000, 6, us.data(), 2, 1, "us read as ns");
  double empty_ft[1] = {0};
  check("netftdata_data", MAT_C_DOUBLE, MAT_T_DOUBLE, 0, 7, empty_ft, 0, 0, "empty stream");
  double bad_history[2 * 14] = {1, 0.5};  // time goes back on row 2
  check("edgeFollowing_history", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, 14, bad_history, 2, 1,
        "does not increase");
  double bad_d_lat[2] = {1, 2};
  check("d_lat", MAT_C_DOUBLE, MAT_T_DOUBLE, 1, 2, bad_d_lat, 0, 0, "'d_lat': expected 1");

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

// Seeded perturbations of valid files (rows swapped, duplicated or dropped, a cell's character
// changed, a value scaled by 1000, a cell removed or added, the file cut short): every input
// either loads with the invariants holding or is refused with a located message, and enough of
// them reach the row-level checks and get through (unlike random bytes, which stop at the header).
std::string Perturb(const std::string& text, std::mt19937* rng) {
  std::vector<std::string> lines;
  for (size_t at = 0; at < text.size();) {
    const size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  auto pick = [&](size_t lo, size_t hi) { return lo + (*rng)() % (hi - lo); };
  const size_t n = lines.size();
  const size_t i = pick(1, n - 1);
  switch ((*rng)() % 8) {
    case 0:
      std::swap(lines[i], lines[i + 1]);
      break;
    case 1:
      lines.insert(lines.begin() + static_cast<long>(i), lines[i]);
      break;
    case 2:
      lines.erase(lines.begin() + static_cast<long>(i));
      break;
    case 3: {  // one character of a row changed
      const std::string alphabet = "0123456789.-e+ ,xn";
      std::string& l = lines[i];
      l[pick(0, l.size())] = alphabet[(*rng)() % alphabet.size()];
      break;
    }
    case 4: {  // one cell scaled by 1000 (a unit slip)
      std::string& l = lines[i];
      const size_t comma = l.find(',', pick(0, l.size()));
      if (comma != std::string::npos) l.insert(comma, "000");
      break;
    }
    case 5: {  // one cell removed
      std::string& l = lines[i];
      const size_t comma = l.rfind(',');
      if (comma != std::string::npos) l.erase(comma);
      break;
    }
    case 6:
      lines[i] += ",1";
      break;
    default:
      lines.resize(i);
      break;
  }
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

TEST(RobotLogTest, SeededPerturbationsOfValidLogsReachTheRowChecks) {
  TempDir dir("perturb");
  const RobotLog good = MakeRobotLog(TwinRun(), LogPerturbation());
  std::vector<std::string> files;
  std::string error;
  ASSERT_TRUE(WriteTopicCsvRecording(dir / "n", good, LoggerVersion::kNewer, &files, &error));
  ASSERT_TRUE(WriteTopicCsvRecording(dir / "o", good, LoggerVersion::kOlder, &files, &error));
  ProcessedLog processed;
  LoadError e;
  ProcessOptions po;
  po.moving_average = 1;
  ASSERT_TRUE(ProcessRobotLog(good, po, &processed, &e));
  ASSERT_TRUE(WritePlainLog(dir / "plain.csv", processed, &error));
  std::mt19937 rng(20261123);
  int row_level = 0, accepted = 0, total = 0;
  for (int round = 0; round < 300; ++round) {
    for (const std::string& file : files) {
      const std::string text = Perturb(ReadText(file), &rng);
      const int n_lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
      TopicTable table;
      ++total;
      if (!ParseTopicCsv(text, file, &table, &e)) {
        EXPECT_FALSE(e.message.empty());
        EXPECT_LE(e.line, n_lines) << e.ToString();
        row_level += e.line >= 2;
        continue;
      }
      // Accepted at parse level: the rows must hold what the checks promise.
      for (size_t k = 1; k < table.t_ns.size(); ++k) ASSERT_GT(table.t_ns[k], table.t_ns[k - 1]);
      for (const auto& row : table.rows) {
        ASSERT_EQ(row.size(), table.header.topic->size());
        for (double v : row) ASSERT_TRUE(std::isfinite(v));
      }
      // Then through the unit checks, in place of its stream in the good log.
      RobotLog log = good;
      Stream* streams[] = {&log.pressure_abs, &log.tool_pose, &log.ft, &log.pwm};
      Stream& s = *streams[static_cast<size_t>(table.header.topic->id)];
      s = Stream();
      for (size_t k = 0; k < table.t_ns.size(); ++k) {
        s.t_s.push_back(static_cast<double>(table.t_ns[k] - log.t0_ns) * 1e-9);
      }
      s.rows = table.rows;
      s.lines = table.lines;
      if (!ValidateRobotLog(log, &e)) {
        row_level += e.line >= 2;
        continue;
      }
      ++accepted;
      for (const auto& row : log.pressure_abs.rows) {
        for (int c = 1; c <= 4; ++c) {
          ASSERT_GE(row[c], kAbsolutePressureMinPa);
          ASSERT_LE(row[c], kAbsolutePressureMaxPa);
        }
      }
      for (const auto& row : log.tool_pose.rows) {
        ASSERT_NEAR(
            std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2] + row[3] * row[3]), 1.0,
            kQuaternionNormTolerance);
        for (int k = 4; k < 7; ++k) ASSERT_LE(std::fabs(row[k]), kPositionMaxM);
      }
    }
    const std::string text = Perturb(ReadText(dir / "plain.csv"), &rng);
    ProcessedLog p;
    ++total;
    if (!ParsePlainLog(text, "plain.csv", &p, &e)) {
      EXPECT_FALSE(e.message.empty());
      row_level += e.line >= 2;
      continue;
    }
    ++accepted;
    for (size_t k = 1; k < p.t_s.size(); ++k) ASSERT_GT(p.t_s[k], p.t_s[k - 1]);
    for (const auto& row : p.p_pa) {
      for (double v : row) ASSERT_TRUE(v >= kGaugeVacuumMinPa && v <= kGaugeVacuumMaxPa);
    }
  }
  // Measured: about half reach a row check and a third pass (seed 20261123).
  EXPECT_GT(row_level, total / 4) << row_level << " of " << total;
  EXPECT_GT(accepted, total / 10) << accepted << " of " << total;
  std::printf("perturbations: %d inputs, %d refused at a row, %d accepted\n", total, row_level,
              accepted);
}

TEST(RobotLogTest, RandomBytesNeverCrashTheReaders) {
  // A deterministic slice of what the fuzz target does, so every test run covers it.
  std::mt19937 rng(7);
  const std::string alphabet = "0123456789,,,\n\n.-+eEnaif \r\"t_P\xff/[]ROStimestamp";
  for (int i = 0; i < 2000; ++i) {
    std::string text(rng() % 200, ' ');
    for (char& c : text) c = alphabet[rng() % alphabet.size()];
    TopicTable table;
    ProcessedLog plain;
    LoadError e;
    if (!ParseTopicCsv(text, "r.csv", &table, &e)) {
      EXPECT_FALSE(e.message.empty());
    }
    if (!ParsePlainLog(text, "r.csv", &plain, &e)) {
      EXPECT_FALSE(e.message.empty());
    }
  }
}

}  // namespace
}  // namespace ssc
