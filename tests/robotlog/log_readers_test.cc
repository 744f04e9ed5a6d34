// All readers against damaged input: cut files and non-files, an endless line, seeded
// perturbations of valid files and random bytes; each loads with its invariants or is refused
// with a located message, never a crash.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <random>
#include <string>
#include <vector>

#include "robotlog_fixtures.h"

namespace ssc {
namespace {

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
