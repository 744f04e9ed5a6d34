// The lab's .mat files: the disk script's arguments and history round trip, a file made as
// SciPy's savemat makes it, and bad files named by variable, row and column.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

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

}  // namespace
}  // namespace ssc
