// Sweep files: rows whole or not at all on resume, and the manifest that refuses to mix rows
// made with other options.
#include "studies/sweep_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/csv_cell.h"
#include "common/output_file.h"
#include "studies/controller_tune.h"
#include "studies/object_trials.h"
#include "studies/trial_io.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

const std::string kRow1 =
    "gantry,100,2,7.5,0,11,success,209.7,32.6,-2.4,0.8,0.7,29.5,7.1,0.3,0.7,2.4,359.8,51,31.0,"
    "\"swept 359.8 deg, done\"";
const std::string kRow2 =
    "gantry,100,2,7.5,1,12,failure_II,20.1,30.0,-5.0,1.0,0.1,3.0,6.0,0.2,1.0,3.0,40.0,9,8.0,\"x\"";
const std::string kRow3 =
    "gantry,150,2,7.5,0,13,success,209.7,32.6,-2.4,0.8,0.7,29.5,7.1,0.3,0.7,2.4,359.8,51,31.0,"
    "\"y\"";

class SweepIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ssc_sweep_io_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    csv_ = (dir_ / "sweep.csv").string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Write(const std::string& text) { std::ofstream(csv_, std::ios::binary) << text; }
  std::string Read() {
    std::ifstream in(csv_, std::ios::binary);
    std::stringstream b;
    b << in.rdbuf();
    return b.str();
  }
  fs::path dir_;
  std::string csv_;
  const std::string header_ = SweepCsvHeader();
};

TEST_F(SweepIoTest, TheHeaderFieldCountMatchesTheRows) {
  const SweepCsvContents c = ParseSweepCsv(header_ + "\n" + kRow1 + "\n", header_);
  EXPECT_TRUE(c.has_header);
  ASSERT_EQ(c.rows.size(), 1u);
  EXPECT_EQ(c.rows[0].seed, 11u);
  EXPECT_EQ(c.dropped, 0);
}

TEST_F(SweepIoTest, ATornTailIsDroppedEvenWhenItHoldsTheOutcome) {
  // Cut inside the metrics: the outcome field is there, the row is not whole.
  Write(header_ + "\n" + kRow1 + "\n" + kRow2.substr(0, kRow2.find(",20.1") + 4));
  SweepCsvContents c;
  std::string error;
  ASSERT_TRUE(LoadSweepCsvForResume(csv_, header_, &c, &error)) << error;
  EXPECT_EQ(c.rows.size(), 1u);
  EXPECT_EQ(c.dropped, 1);
  EXPECT_EQ(Read(), header_ + "\n" + kRow1 + "\n") << "file rewritten without the torn tail";
  // Appending now starts on a fresh line.
  SweepRowWriter w;
  ASSERT_TRUE(w.Open(csv_, &error)) << error;
  ASSERT_TRUE(w.Append(kRow2, &error)) << error;
  EXPECT_EQ(ParseSweepCsv(Read(), header_).rows.size(), 2u);
}

TEST_F(SweepIoTest, ARowTornEarlierDoesNotGlueOntoTheNext) {
  // An old writer left a torn row and appended the next one onto it.
  Write(header_ + "\n" + kRow1.substr(0, 30) + kRow2 + "\n" + kRow3 + "\n");
  SweepCsvContents c;
  std::string error;
  ASSERT_TRUE(LoadSweepCsvForResume(csv_, header_, &c, &error)) << error;
  ASSERT_EQ(c.rows.size(), 1u) << "the glued line counts as no trial";
  EXPECT_DOUBLE_EQ(c.rows[0].pref_pa, 150);
  EXPECT_EQ(c.dropped, 1);
  EXPECT_EQ(Read(), header_ + "\n" + kRow3 + "\n");
}

TEST_F(SweepIoTest, MalformedKeysAndForeignFilesAreNotRows) {
  std::string bad = kRow1;
  bad.replace(bad.find(",100,"), 5, ",0x64,");
  EXPECT_EQ(ParseSweepCsv(header_ + "\n" + bad + "\n", header_).rows.size(), 0u);
  Write("t_s,x_m\n1,2\n");
  SweepCsvContents c;
  std::string error;
  EXPECT_FALSE(LoadSweepCsvForResume(csv_, header_, &c, &error));
  EXPECT_NE(error.find("header"), std::string::npos) << error;
  EXPECT_EQ(Read(), "t_s,x_m\n1,2\n") << "a foreign file is left alone";
}

TEST_F(SweepIoTest, RowsNeverSpanLines) {
  SweepRowWriter w;
  std::string error;
  ASSERT_TRUE(w.Open(csv_, &error));
  ASSERT_TRUE(w.Append(header_, &error));
  std::string row = kRow1;
  row.replace(row.find("done"), 4, "do\nne");
  ASSERT_TRUE(w.Append(row, &error));
  const SweepCsvContents c = ParseSweepCsv(Read(), header_);
  EXPECT_EQ(c.rows.size(), 1u);
  EXPECT_EQ(c.dropped, 0);
}

TEST_F(SweepIoTest, ManifestKeepsNumbersAsNumbersAndRoundTripsItsTexts) {
  const SweepManifest written = {{"seed", "18446744073709551615"},
                                 {"timeout_s", "120"},
                                 {"goal_band_m", "0.0125"},
                                 {"tiny", "1e-07"},
                                 {"start_x_m", "-0.65"},
                                 {"scene", "disk_benchmark"},
                                 {"model_hash", "00ab12cd34ef5678"},
                                 {"leading_zero", "007"},
                                 {"dead_band", "on"},
                                 {"flag", "true"}};
  const std::string json = SweepManifestJson(written);
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_TRUE(j["seed"].is_number_unsigned()) << json;
  EXPECT_TRUE(j["timeout_s"].is_number()) << json;
  EXPECT_TRUE(j["goal_band_m"].is_number_float()) << json;
  EXPECT_TRUE(j["start_x_m"].is_number()) << json;
  EXPECT_TRUE(j["flag"].is_boolean()) << json;
  EXPECT_TRUE(j["scene"].is_string()) << json;
  EXPECT_TRUE(j["model_hash"].is_string()) << json;
  EXPECT_TRUE(j["leading_zero"].is_string()) << json;  // "007" is not JSON's 7
  SweepManifest read;
  std::string error;
  ASSERT_TRUE(ParseSweepManifest(json, &read, &error)) << error;
  EXPECT_EQ(read, written);
  EXPECT_FALSE(ParseSweepManifest("{\"seed\": [1]}", &read, &error));
  EXPECT_NE(error.find("'seed'"), std::string::npos) << error;
}

// Another study's table resumes by the sweep's rules: torn and malformed lines dropped, rows
// the study refuses or repeats dropped, the rest kept by key; other options refused; one run
// per table at a time; appends whole.
TEST_F(SweepIoTest, AStudyTableResumesByTheSweepsRules) {
  const std::string table = (dir_ / "objects.csv").string(), header = "object,seed,outcome";
  const SweepManifest manifest = {{"seeds", "2"}};
  auto check = [](const std::vector<std::string_view>& f, std::string* why) {
    if (f[2] != "success" && f[2] != "timeout") {
      *why = "outcome '" + std::string(f[2]) + "' is not a finished trial's";
      return std::string();
    }
    return std::string(f[0]) + " " + std::string(f[1]);
  };
  std::string error;
  {
    ResumableTable t;
    ASSERT_TRUE(t.Open(table, header, manifest, check, "test", &error)) << error;
    EXPECT_EQ(t.kept(), 0u);
    ASSERT_TRUE(t.Append("disk,1,success", &error)) << error;
    ASSERT_TRUE(t.Append("disk,2,running", &error)) << error;
    ASSERT_TRUE(t.Append("hole,1,timeout", &error)) << error;
    ASSERT_TRUE(t.Append("disk,1,timeout", &error)) << error;  // a second row for disk 1
    ResumableTable second;  // the same table while the first holds it
    EXPECT_FALSE(second.Open(table, header, manifest, check, "test", &error));
    EXPECT_NE(error.find("pid " + std::to_string(::getpid())), std::string::npos) << error;
  }
  std::ofstream(table, std::ios::app) << "hole,2,succ";  // torn
  {
    ResumableTable t;
    ASSERT_TRUE(t.Open(table, header, manifest, check, "test", &error)) << error;
    EXPECT_EQ(t.kept(), 2u);
    EXPECT_EQ(t.Kept("disk 1"), "disk,1,success");  // the first row for a key wins
    EXPECT_EQ(t.Kept("hole 1"), "hole,1,timeout");
    EXPECT_EQ(t.Kept("disk 2"), "");  // not finished: runs again
    ASSERT_TRUE(t.Append("hole,2,success", &error)) << error;
  }
  std::ifstream in(table);
  std::stringstream text;
  text << in.rdbuf();
  // Each row sealed with its digest (FNV-1a of the rest of the row, 16 hex digits).
  std::string unsealed;
  std::stringstream lines(text.str());
  for (std::string line; std::getline(lines, line);) {
    const size_t comma = line.rfind(',');
    ASSERT_NE(comma, std::string::npos) << line;
    EXPECT_EQ(line.size() - comma - 1, line.rfind("row_digest") == comma + 1 ? 10u : 16u) << line;
    unsealed += line.substr(0, comma) + "\n";
  }
  EXPECT_EQ(unsealed, header + "\ndisk,1,success\nhole,1,timeout\nhole,2,success\n");
  // A row changed since it was written (an outcome edited by hand) is not trusted.
  {
    std::string edited = text.str();
    const size_t at = edited.find("hole,1,timeout");
    ASSERT_NE(at, std::string::npos);
    edited.replace(at, 14, "hole,1,success");
    std::ofstream(table, std::ios::trunc) << edited;
    ResumableTable t;
    ASSERT_TRUE(t.Open(table, header, manifest, check, "test", &error)) << error;
    EXPECT_EQ(t.Kept("hole 1"), "");
    EXPECT_EQ(t.Kept("disk 1"), "disk,1,success");
    EXPECT_EQ(t.kept(), 2u);
  }
  ResumableTable other;
  EXPECT_FALSE(other.Open(table, header, {{"seeds", "3"}}, check, "test", &error));
  EXPECT_NE(error.find("seeds: 2 in the file, 3 now"), std::string::npos) << error;
}

// Every table the project writes and every reader of it agree on a free-text cell: random
// details with commas, quotes, line breaks and UTF-8 come back whole from each writer through
// the resume reader (one whole row, the header's field count) and CsvCellText; a line break
// becomes a space (rows never span lines). A fixed seed: the same 400 cases each run.
TEST_F(SweepIoTest, EveryWriterAndReaderAgreeOnFreeText) {
  std::mt19937 rng(20261128);
  const std::vector<std::string> alphabet = {"a", "Z", "0",  ",",        "\"", "\"\"", "\n", "\r",
                                             " ", ";", "\\", "\xc3\xa9", "'",  "=",    ":"};
  for (int n = 0; n < 400; ++n) {
    std::string detail, expected;
    const int length = static_cast<int>(rng() % 40);
    for (int i = 0; i < length; ++i) {
      const std::string& piece = alphabet[rng() % alphabet.size()];
      detail += piece;
      expected += piece == "\n" || piece == "\r" ? " " : piece;
    }
    TrialResult result;
    result.detail = detail;
    ObjectTrialRow object;
    object.object = "corner_a090";
    object.kind = "corner";
    object.tier = "gantry";
    object.result.detail = detail;
    TuneEvaluation tuned;
    tuned.label = "eval 1";
    tuned.controller = "fast:" + detail;
    tuned.refused = "x" + detail;  // never empty: an empty reason means the point ran
    const std::vector<std::pair<std::string, std::string>> tables = {
        {SweepCsvHeader(), SweepCsvRow("disk_benchmark_fast", TrialConfig(), 1, result)},
        {ObjectTableHeader(), ObjectTableRow(object)},
        {TuneCsvHeader({}), TuneCsvRow(tuned, 0)}};
    for (const auto& [header, row] : tables) {
      std::string last, second;
      const CsvRows rows = ParseCsvRows(header + "\n" + row + "\n", header,
                                        [&](const std::vector<std::string_view>& f, int) {
                                          last = CsvCellText(f.back());
                                          second = CsvCellText(f[1]);
                                          return true;
                                        });
      ASSERT_EQ(rows.lines.size(), 1u) << "detail '" << detail << "': " << row;
      EXPECT_EQ(rows.dropped, 0);
      if (header == TuneCsvHeader({})) {
        EXPECT_EQ(second, "fast:" + expected) << row;
        EXPECT_EQ(last, "refused: x" + expected) << row;
      } else {
        EXPECT_EQ(last, expected) << row;
      }
    }
  }
}

TEST_F(SweepIoTest, ResumingWithOtherOptionsIsRefusedNamingTheDifference) {
  const SweepManifest first = {{"seed", "1"}, {"scene", "gantry"}, {"timeout_s", "120"}};
  std::string error;
  ASSERT_TRUE(CheckOrWriteSweepManifest(csv_, false, first, &error)) << error;
  EXPECT_TRUE(fs::exists(dir_ / "sweep.json"));
  EXPECT_TRUE(CheckOrWriteSweepManifest(csv_, true, first, &error)) << error;
  SweepManifest other = first;
  other["seed"] = "2";
  other["timeout_s"] = "60";
  EXPECT_FALSE(CheckOrWriteSweepManifest(csv_, true, other, &error));
  EXPECT_NE(error.find("seed: 1 in the file, 2 now"), std::string::npos) << error;
  EXPECT_NE(error.find("timeout_s: 120 in the file, 60 now"), std::string::npos) << error;
  // Rows without a manifest: nobody can tell what made them.
  fs::remove(dir_ / "sweep.json");
  EXPECT_FALSE(CheckOrWriteSweepManifest(csv_, true, first, &error));
  EXPECT_NE(error.find("no "), std::string::npos) << error;
  // A damaged manifest is an error, not a fresh start.
  std::ofstream(dir_ / "sweep.json") << "{\"seed\": ";
  EXPECT_FALSE(CheckOrWriteSweepManifest(csv_, true, first, &error));
}

// Resume trusts no row: each is checked against its key and the options.
class ResumeRowsTest : public SweepIoTest {
 protected:
  SweepRowExpectations Expect() const {
    SweepRowExpectations e;
    e.scene = "gantry";
    // kRow1..3 carry seeds 11, 12, 13: the seed of a grid point here is 11 + repeat + pref/150.
    e.seed_of = [](const SweepRowKey& r) {
      return static_cast<std::uint64_t>(11 + r.repeat + (r.pref_pa > 120 ? 2 : 0));
    };
    e.outcomes = {"success", "failure_I", "failure_II", "timeout", "unstable", "lost_edge"};
    e.success = "success";
    return e;
  }
  std::vector<SweepRowProblem> Check(const std::vector<std::string>& lines, SweepCsvContents* c) {
    std::string text = header_ + "\n";
    for (const std::string& l : lines) text += l + "\n";
    *c = ParseSweepCsv(text, header_);
    return DropImpossibleSweepRows(Expect(), c);
  }
  static std::string Replace(std::string row, const std::string& from, const std::string& to) {
    return row.replace(row.find(from), from.size(), to);
  }
};

TEST_F(ResumeRowsTest, GoodRowsAreAllKept) {
  SweepCsvContents c;
  EXPECT_TRUE(Check({kRow1, kRow2, kRow3}, &c).empty());
  EXPECT_EQ(c.rows.size(), 3u);
}

TEST_F(ResumeRowsTest, ARowWhoseSeedWasEditedIsDropped) {
  SweepCsvContents c;
  const auto problems = Check({Replace(kRow1, ",0,11,", ",0,99,"), kRow2}, &c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_NE(problems[0].why.find("seed 99 is not this grid point's seed 11"), std::string::npos)
      << problems[0].why;
  ASSERT_EQ(c.rows.size(), 1u);
  EXPECT_EQ(c.rows[0].seed, 12u);
}

TEST_F(ResumeRowsTest, ASecondRowForOneTrialIsDroppedNamingTheFirst) {
  SweepCsvContents c;
  const auto problems = Check({kRow1, kRow2, kRow1}, &c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 4);
  EXPECT_NE(problems[0].why.find("trial of line 2"), std::string::npos) << problems[0].why;
  EXPECT_EQ(c.lines, (std::vector<std::string>{kRow1, kRow2}));
}

TEST_F(ResumeRowsTest, ImpossibleValuesAreDropped) {
  SweepCsvContents c;
  const auto problems =
      Check({Replace(kRow1, ",success,209.7,", ",success,nan,"),
             Replace(kRow2, "failure_II", "bogus"), Replace(kRow3, ",51,31.0,", ",51,abc,")},
            &c);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_NE(problems[0].why.find("success with s_mm = nan"), std::string::npos);
  EXPECT_NE(problems[1].why.find("outcome 'bogus'"), std::string::npos);
  EXPECT_NE(problems[2].why.find("not a number"), std::string::npos);
  EXPECT_TRUE(c.rows.empty());
  // A failure may lack a path: failure_II with s_mm = nan is a row.
  EXPECT_TRUE(Check({Replace(kRow2, ",failure_II,20.1,", ",failure_II,nan,")}, &c).empty());
}

TEST_F(ResumeRowsTest, ARowOfAnotherSceneIsDropped) {
  SweepCsvContents c;
  const auto problems = Check({Replace(kRow1, "gantry,", "arm,")}, &c);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].why.find("scene 'arm'"), std::string::npos);
}

TEST_F(SweepIoTest, OneSweepAtATimePerOutputNamingTheHolder) {
  std::string error;
  {
    SweepOutputLock first;
    ASSERT_TRUE(first.Acquire(csv_, &error)) << error;
    SweepOutputLock second;  // another open file description: flock refuses it
    EXPECT_FALSE(second.Acquire(csv_, &error));
    EXPECT_NE(error.find("pid " + std::to_string(::getpid())), std::string::npos) << error;
  }
  EXPECT_FALSE(fs::exists(csv_ + ".lock"));  // released and removed
  SweepOutputLock again;
  EXPECT_TRUE(again.Acquire(csv_, &error)) << error;
}

TEST_F(SweepIoTest, AnOutputFileIsWholeOrAbsent) {
  const std::string path = (dir_ / "out.txt").string();
  std::string error;
  {
    OutputFile f(path);
    f.Write("partial");
    EXPECT_FALSE(fs::exists(path));  // nothing under the final name before Commit
  }
  EXPECT_TRUE(fs::is_empty(dir_));  // abandoned: the temporary file is gone too
  ASSERT_TRUE(WriteWholeFile(path, "whole\n", &error)) << error;
  EXPECT_TRUE(fs::exists(path));
  // An unwritable target keeps the old content and names the file and the reason.
  EXPECT_FALSE(WriteWholeFile((dir_ / "no_dir" / "x.txt").string(), "x", &error));
  EXPECT_NE(error.find("no_dir/x.txt: cannot create: No such file or directory"), std::string::npos)
      << error;
}

// The default scene is recorded for the reader but does not define the rows (the "scene" key
// does): a sweep started before the default changed resumes.
TEST_F(SweepIoTest, TheDefaultSceneIsRecordedButNotCompared) {
  const SweepManifest first = {{"scene", "gantry"}, {"default_scene", "gantry"}};
  std::string error;
  ASSERT_TRUE(CheckOrWriteSweepManifest(csv_, false, first, &error)) << error;
  SweepManifest later = first;
  later["default_scene"] = "light";
  EXPECT_TRUE(CheckOrWriteSweepManifest(csv_, true, later, &error)) << error;
  later.erase("default_scene");
  EXPECT_TRUE(CheckOrWriteSweepManifest(csv_, true, later, &error)) << error;
  later["scene"] = "light";
  EXPECT_FALSE(CheckOrWriteSweepManifest(csv_, true, later, &error));
  EXPECT_NE(error.find("scene: gantry in the file, light now"), std::string::npos) << error;
}

// A scene's fingerprint covers what MuJoCo reads for it, found without compiling: a nested
// include, the model it attaches (from the attaching file's folder), a mesh from the compiler's
// meshdir; a file named but absent is recorded too, and a commented-out include is not.
TEST_F(SweepIoTest, SceneFileHashesCoverEveryFilePulledIn) {
  const fs::path scene = dir_ / "scene";
  fs::create_directories(scene / "parts");
  fs::create_directories(scene / "meshes");
  auto put = [](const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
  };
  put(scene / "main.xml",
      "<mujoco><compiler meshdir=\"meshes\"/><include file=\"parts/arm.xml\"/>\n"
      "<!-- <include file=\"old.xml\"/> -->\n"
      "<asset><texture name=\"t\" file=\"grid.png\"/></asset></mujoco>");
  put(scene / "parts" / "arm.xml",
      "<mujoco><asset><model name=\"tool\" file=\"tool.xml\"/><mesh file=\"cup.stl\"/>"
      "</asset></mujoco>");
  put(scene / "parts" / "tool.xml", "<mujoco><geom size=\"0.4\"/></mujoco>");
  put(scene / "meshes" / "cup.stl", "solid cup");
  put(scene / "old.xml", "<mujoco/>");
  const auto before = SceneFileHashes((scene / "main.xml").string());
  const fs::path abs = fs::absolute(scene).lexically_normal();
  const std::vector<fs::path> files = {"main.xml", "parts/arm.xml", "parts/tool.xml",
                                       "meshes/cup.stl", "grid.png"};
  ASSERT_EQ(before.size(), files.size());
  for (const fs::path& f : files) EXPECT_EQ(before.count((abs / f).string()), 1u) << f;
  EXPECT_EQ(before.at((abs / "grid.png").string()), "no such file");
  // Each file changed alone changes its own hash and no other.
  for (const fs::path& f : {fs::path("parts/tool.xml"), fs::path("meshes/cup.stl")}) {
    const auto was = SceneFileHashes((scene / "main.xml").string());
    put(scene / f, "changed " + f.string());
    const auto now = SceneFileHashes((scene / "main.xml").string());
    for (const auto& [path, hash] : now) {
      EXPECT_EQ(hash != was.at(path), path == (abs / f).string()) << path;
    }
  }
  put(scene / "grid.png", "png");
  EXPECT_NE(SceneFileHashes((scene / "main.xml").string()).at((abs / "grid.png").string()),
            "no such file");
}

}  // namespace
}  // namespace ssc
