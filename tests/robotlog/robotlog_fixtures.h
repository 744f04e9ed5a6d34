// Shared fixtures of the robot-log tests (tests/robotlog/*_test.cc): a scratch directory, a
// twin run and the disk script's arguments to write as the lab would, a raw log by hand, and the
// checks every bad-log case makes (file, line, column, words).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "robotlog/robot_log.h"
#include "robotlog/synthetic_log.h"
#include "robotlog/text_cells.h"

namespace ssc {

namespace fs = std::filesystem;

// tool0 pointing down at the table (tool z = scene -z), tool x = scene -y: the project's
// orientation (180 degrees about (1, -1, 0)).
inline constexpr double kDown[4] = {0, M_SQRT1_2, -M_SQRT1_2, 0};

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

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline bool StartsWith(const std::string& path, const std::string& prefix) {
  std::ifstream f(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  return text.compare(0, prefix.size(), prefix) == 0;
}

// A twin run: 2 s at 100 Hz, the TCP on a 30 mm circle 5 mm above the table, vacuum rising
// linearly per chamber, a growing normal force.
inline std::vector<TwinSample> TwinRun() {
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

inline void ExpectSameStream(const Stream& a, const Stream& b, const char* what) {
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
inline LabRunArgs DiskArgs() {
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

inline std::string ReadText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

inline std::string Line(const std::string& text, int n) {  // 1-based
  size_t at = 0;
  for (int i = 1; i < n; ++i) at = text.find('\n', at) + 1;
  return text.substr(at, text.find('\n', at) - at);
}

// A raw log by hand: pressure at 100 Hz for 3 s, in air for the first second (sensor offsets
// differ per chamber), then vacuum steps to 1000 Pa at t = 2 s in every chamber.
inline RobotLog StepLog(double step_pa = 1000) {
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

inline constexpr char kPressureHeader[] =
    "ROStimestamp,/SensorPacket.ch,/SensorPacket.data[0],/SensorPacket.data[1],"
    "/SensorPacket.data[2],/SensorPacket.data[3]\n";

struct BadCase {
  std::string text;
  int line, column;
  const char* words;
};

// A recording with one topic file's text replaced, loaded: the error must name that file.
struct Recording {
  std::string folder, pressure, pose, ft, pwm;
};
inline Recording WriteRecording(const TempDir& dir) {
  const RobotLog log = MakeRobotLog(TwinRun(), LogPerturbation());
  std::string error;
  fs::remove_all(dir.str());
  EXPECT_TRUE(WriteTopicCsvRecording(dir.str(), log, LoggerVersion::kNewer, nullptr, &error));
  const std::string stamp = RecordingStamp(log.t0_ns);
  return {dir.str(), dir / TopicFileName(stamp, "/SensorPacket"),
          dir / TopicFileName(stamp, "/endEffectorPose"), dir / TopicFileName(stamp, "/netft_data"),
          dir / TopicFileName(stamp, "/pwm")};
}

inline LoadError LoadWith(const TempDir& dir, std::string Recording::*file,
                          const std::string& text) {
  const Recording r = WriteRecording(dir);
  WriteText(r.*file, text);
  RobotLog back;
  LoadError e;
  EXPECT_FALSE(LoadTopicCsvRecording(r.folder, &back, &e));
  EXPECT_EQ(e.file, r.*file) << e.ToString();
  return e;
}

inline void ExpectError(const LoadError& e, int line, int column, const std::string& words) {
  EXPECT_EQ(e.line, line) << e.ToString();
  EXPECT_EQ(e.column, column) << e.ToString();
  EXPECT_NE(e.message.find(words), std::string::npos) << e.ToString();
}

// n pressure rows from t0 every dt_ns, all at `value` Pa.
inline std::string PressureRows(long long t0, long long dt_ns, int n, const std::string& value) {
  std::string s = kPressureHeader;
  for (int i = 0; i < n; ++i) {
    s += std::to_string(t0 + dt_ns * i) + ",4," + value + ", " + value + ", " + value + ", " +
         value + "\n";
  }
  return s;
}

}  // namespace ssc
