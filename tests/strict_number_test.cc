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
  EXPECT_EQ(NumberRange::Whole(0, 9007199254740992.0).ToString(),
            "a whole number in [0, 9007199254740992]");
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

TEST(CommandLineTest, OutputDirectoryIsCheckedBeforeWork) {
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() / ("ssc_cli_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(tmp);
  std::ofstream(tmp / "a_file") << "x";
  std::string error;
  EXPECT_FALSE(cli::PrepareOutputDir((tmp / "a_file").string(), &error));
  EXPECT_NE(error.find("not a directory"), std::string::npos) << error;
  EXPECT_FALSE(cli::PrepareOutputDir((tmp / "a_file" / "below").string(), &error));
  EXPECT_NE(error.find("a_file"), std::string::npos) << error;
  EXPECT_TRUE(cli::PrepareOutputDir((tmp / "new" / "deeper").string(), &error)) << error;
  EXPECT_TRUE(std::filesystem::is_directory(tmp / "new" / "deeper"));
  EXPECT_FALSE(cli::PrepareOutputFile(tmp.string(), &error));
  std::string out = (tmp / "a_file").string();
  cli::Command cmd("test", "t");
  cmd.OutputDir("out", &out, "out");
  EXPECT_EQ(ParseArgs(&cmd, {}), 2);  // the default itself is checked
  std::filesystem::remove_all(tmp);
}

}  // namespace
}  // namespace ssc
