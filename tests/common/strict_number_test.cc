// The strict number reader and the command-line layer built on it.
#include "common/strict_number.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "apps/ssc/cli.h"

namespace ssc {
namespace {

TEST(StrictNumberTest, AcceptsDecimalNumbersOnly) {
  const NumberRange any;
  double v = 0;
  std::string e;
  for (const auto& [text, want] : std::vector<std::pair<std::string, double>>{
           {"100", 100}, {"-6", -6}, {"2.5e-3", 2.5e-3}, {".5", 0.5}, {" 7 ", 7}, {"+1E2", 100}}) {
    EXPECT_TRUE(ParseNumber(text, any, &v, &e)) << text << ": " << e;
    EXPECT_DOUBLE_EQ(v, want) << text;
  }
  for (const char* bad : {"", " ", "0x10", "inf", "-inf", "nan", "1e", "5mm", "1,", "1,5", "--1",
                          "1e400", "1 2", ".", "e5", "1..2"}) {
    v = 42;
    EXPECT_FALSE(ParseNumber(bad, any, &v, &e)) << bad;
    EXPECT_DOUBLE_EQ(v, 42) << "target changed on a rejected value: " << bad;
    EXPECT_FALSE(e.empty());
  }
}

TEST(StrictNumberTest, RangesAndWholeNumbers) {
  double v = 0;
  std::string e;
  EXPECT_FALSE(ParseNumber("0", NumberRange::Positive(10), &v, &e));
  EXPECT_NE(e.find("(0, 10]"), std::string::npos) << e;
  EXPECT_TRUE(ParseNumber("10", NumberRange::Positive(10), &v, &e));
  EXPECT_FALSE(ParseNumber("10", NumberRange::Positive(10).OpenHigh(), &v, &e));
  EXPECT_FALSE(ParseNumber("1.5", NumberRange::Whole(0, 5), &v, &e));
  EXPECT_NE(e.find("whole"), std::string::npos) << e;
  EXPECT_TRUE(ParseNumber("3", NumberRange::Whole(0, 5), &v, &e));
  EXPECT_EQ(NumberRange::Whole(0, 9007199254740991.0).ToString(),
            "a whole number in [0, 9007199254740991]");
  // Whole numbers are judged from the text, and only where doubles are exact: 2^53 + 1 would
  // silently become 2^53, and 9007199254740990.6 would round to a whole double.
  const NumberRange seeds = NumberRange::Whole(0, 1e300);
  for (const char* whole : {"3", "1.0", "1.5e1", "3e2", "9007199254740991", "0.0e5"}) {
    EXPECT_TRUE(ParseNumber(whole, seeds, &v, &e)) << whole << ": " << e;
  }
  EXPECT_DOUBLE_EQ(v, 0);
  for (const char* bad : {"2.5", "1e-1", "9007199254740990.6", "0.5e0"}) {
    EXPECT_FALSE(ParseNumber(bad, seeds, &v, &e)) << bad;
    EXPECT_NE(e.find("not a whole number"), std::string::npos) << e;
  }
  for (const char* big : {"9007199254740992", "9007199254740993", "1e20"}) {
    EXPECT_FALSE(ParseNumber(big, seeds, &v, &e)) << big;
    EXPECT_NE(e.find("2^53"), std::string::npos) << e;
  }
}

TEST(StrictNumberTest, NameListsRejectEmptyItemsAndRepeats) {
  std::vector<std::string> out;
  std::string e;
  EXPECT_TRUE(ParseNameList("period_s, smoothing_s", &out, &e)) << e;
  EXPECT_EQ(out, (std::vector<std::string>{"period_s", "smoothing_s"}));
  for (const char* bad : {"", "period_s,", ",period_s", "a,,b", "period_s,period_s"}) {
    EXPECT_FALSE(ParseNameList(bad, &out, &e)) << bad;
    EXPECT_FALSE(e.empty());
  }
  EXPECT_FALSE(ParseNameList("a,b,a", &out, &e));
  EXPECT_NE(e.find("twice"), std::string::npos) << e;
}

TEST(StrictNumberTest, ListsRejectEmptyItemsAndRepeats) {
  std::vector<double> out;
  std::string e;
  const NumberRange r = NumberRange::Closed(0, 1000);
  EXPECT_TRUE(ParseNumberList("40,70, 100", r, true, &out, &e)) << e;
  EXPECT_EQ(out, (std::vector<double>{40, 70, 100}));
  EXPECT_FALSE(ParseNumberList("40,70,", r, true, &out, &e));
  EXPECT_NE(e.find("item 3"), std::string::npos) << e;
  EXPECT_FALSE(ParseNumberList(",40", r, true, &out, &e));
  EXPECT_FALSE(ParseNumberList("40,,70", r, true, &out, &e));
  EXPECT_FALSE(ParseNumberList("", r, true, &out, &e));
  EXPECT_FALSE(ParseNumberList("40,40.0", r, true, &out, &e));
  EXPECT_NE(e.find("twice"), std::string::npos) << e;
  EXPECT_TRUE(ParseNumberList("40,40", r, false, &out, &e));
  EXPECT_FALSE(ParseNumberList("40,2000", r, true, &out, &e));
  EXPECT_NE(e.find("item 2"), std::string::npos) << e;
}

// Runs a Command over the given arguments; returns the exit code (-1 = go on).
int ParseArgs(cli::Command* cmd, std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  int rc = 0;
  return cmd->Parse(static_cast<int>(argv.size()), argv.data(), &rc) ? -1 : rc;
}

TEST(CommandLineTest, TypedOptionsKeepDefaultsAndRejectStrayInput) {
  auto make = [](double* pref, std::vector<double>* steps, long* n, bool* flag) {
    auto cmd = std::make_unique<cli::Command>("test", "a test command");
    cmd->Number("pref", pref, "P_ref", "Pa", NumberRange::Positive(1e6));
    cmd->NumberList("step", steps, "steps", "mm", NumberRange::Positive(100));
    cmd->Integer("repeats", n, "repeats", NumberRange::Closed(1, 1000));
    cmd->Flag("no-plot", flag, "skip");
    return cmd;
  };
  double pref = 100;
  std::vector<double> steps = {2.5, 5};
  long n = 3;
  bool flag = false;
  EXPECT_EQ(ParseArgs(make(&pref, &steps, &n, &flag).get(), {}), -1);
  EXPECT_EQ(pref, 100);
  EXPECT_EQ(steps, (std::vector<double>{2.5, 5}));
  EXPECT_EQ(ParseArgs(make(&pref, &steps, &n, &flag).get(),
                      {"--pref", "150", "--step=1,2", "--repeats", "7", "--no-plot"}),
            -1);
  EXPECT_EQ(pref, 150);
  EXPECT_EQ(steps, (std::vector<double>{1, 2}));
  EXPECT_EQ(n, 7);
  EXPECT_TRUE(flag);
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"stray"},
                                             {"--pref"},
                                             {"--pref", "0x10"},
                                             {"--pref", "1", "--pref", "2"},
                                             {"--repeats", "2.5"},
                                             {"--repeats", "0"},
                                             {"--step", "1,"},
                                             {"--step", "1,1"},
                                             {"--unknown", "1"},
                                             {"--pref", ""}}) {
    EXPECT_EQ(ParseArgs(make(&pref, &steps, &n, &flag).get(), bad), 2) << bad[0];
  }
}

TEST(CommandLineTest, OutputDirectoryIsCheckedBeforeWorkAndCreatedOnlyWhenAsked) {
  namespace fs = std::filesystem;
  const fs::path tmp = fs::temp_directory_path() / ("ssc_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  std::ofstream(tmp / "a_file") << "x";
  fs::create_symlink(tmp / "nothing_here", tmp / "dangling");
  std::string error;
  for (const fs::path& bad :
       {tmp / "a_file", tmp / "a_file" / "below", tmp / "dangling", tmp / std::string(300, 'a')}) {
    EXPECT_FALSE(cli::CheckOutputDir(bad.string(), &error)) << bad;
    EXPECT_FALSE(cli::CreateOutputDir(bad.string(), &error)) << bad;
  }
  EXPECT_FALSE(cli::CheckOutputDir((tmp / "a_file").string(), &error));
  EXPECT_NE(error.find("not a directory"), std::string::npos) << error;
  EXPECT_FALSE(cli::CheckOutputDir((tmp / "a_file" / "below").string(), &error));
  EXPECT_NE(error.find("a_file"), std::string::npos) << error;
  EXPECT_FALSE(cli::CheckOutputDir((tmp / "dangling" / "x").string(), &error));
  EXPECT_NE(error.find("dangling"), std::string::npos) << error;
  EXPECT_FALSE(cli::CheckOutputDir("", &error));
  // The check creates nothing; CreateOutputDir does.
  EXPECT_TRUE(cli::CheckOutputDir((tmp / "new" / "deeper").string(), &error)) << error;
  EXPECT_FALSE(fs::exists(tmp / "new"));
  EXPECT_TRUE(cli::CreateOutputDir((tmp / "new" / "deeper").string(), &error)) << error;
  EXPECT_TRUE(fs::is_directory(tmp / "new" / "deeper"));
  EXPECT_FALSE(cli::CheckOutputFile(tmp.string(), &error));
  EXPECT_TRUE(cli::CheckOutputFile((tmp / "later" / "x.png").string(), &error)) << error;
  EXPECT_FALSE(fs::exists(tmp / "later"));

  // Through a command: Parse() checks (the default too) and creates nothing; CreateOutputs()
  // makes the directory and the output file's directory.
  {
    std::string out = (tmp / "a_file").string();
    cli::Command cmd("test", "t");
    cmd.OutputDir("out", &out, "out");
    EXPECT_EQ(ParseArgs(&cmd, {}), 2);
  }
  std::string out = (tmp / "made" / "here").string(), shot;
  cli::Command cmd("test", "t");
  cmd.OutputDir("out", &out, "out");
  cmd.OutputFile("screenshot", &shot, "png");
  EXPECT_EQ(ParseArgs(&cmd, {"--screenshot", (tmp / "shots" / "x.png").string()}), -1);
  EXPECT_FALSE(fs::exists(tmp / "made"));
  EXPECT_FALSE(fs::exists(tmp / "shots"));
  EXPECT_EQ(cmd.CreateOutputs(), 0);
  EXPECT_TRUE(fs::is_directory(tmp / "made" / "here"));
  EXPECT_TRUE(fs::is_directory(tmp / "shots"));
  EXPECT_FALSE(fs::exists(tmp / "shots" / "x.png"));
  fs::remove_all(tmp);
}

}  // namespace
}  // namespace ssc
