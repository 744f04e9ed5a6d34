// The lab logger's per-topic CSV files (both logger versions): written as the logger writes
// them, read from their folder or any of their files, and every bad file named with its line and
// column.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

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

}  // namespace
}  // namespace ssc
