// The pure parts of `ssc tune` (studies/controller_tune.h): the score, the Pareto front, the
// search keys and the t quantile.
#include "studies/controller_tune.h"

#include <gtest/gtest.h>

namespace ssc {
namespace {

TEST(TuneScore, SpeedWhenTheRateIsMetAndAPenaltyPerShortfall) {
  EXPECT_DOUBLE_EQ(TuneScore(9, 10, 40.0, 0.9), 40.0);
  EXPECT_DOUBLE_EQ(TuneScore(10, 10, 40.0, 0.9), 40.0);
  EXPECT_NEAR(TuneScore(8, 10, 40.0, 0.9), 40.0 - 0.1 * kTuneShortfallPenaltyMmS, 1e-9);
  // A faster point 10 % short never beats a slower one that meets the rate on the disk.
  EXPECT_LT(TuneScore(8, 10, 60.0, 0.9), TuneScore(9, 10, 30.0, 0.9));
  // No success: no speed to count, the whole shortfall.
  EXPECT_NEAR(TuneScore(0, 10, 0.0, 0.9), -0.9 * kTuneShortfallPenaltyMmS, 1e-9);
  EXPECT_LT(TuneScore(0, 0, 0.0, 0.5), 0.0);
}

TEST(ParetoFront, KeepsOnlyPointsNoOtherBeatsInBoth) {
  // (speed, success)
  const std::vector<std::array<double, 2>> p = {{30, 0.9}, {40, 0.7}, {35, 0.6}, {50, 0.2},
                                                {30, 0.9}, {20, 1.0}, {45, 0.7}};
  const std::vector<std::size_t> front = ParetoFront(p);
  // {35, 0.6} is beaten by {40, 0.7}; {40, 0.7} by {45, 0.7}; the second {30, 0.9} repeats
  // the first. In order of rising speed.
  EXPECT_EQ(front, (std::vector<std::size_t>{5, 0, 6, 3}));
  EXPECT_TRUE(ParetoFront({}).empty());
}

TEST(ParseTuneSearch, ControllerAndLawKeysWithinTheirRanges) {
  const ControllerType* fast = FindControllerType("fast");
  ASSERT_NE(fast, nullptr);
  std::vector<TuneKey> keys;
  std::string error;
  ASSERT_TRUE(ParseTuneSearch(*fast, "step_max_mm=6:12,beta=1:3", &keys, &error)) << error;
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].key, "step_max_mm");
  EXPECT_GE(keys[0].controller_index, 0);
  EXPECT_DOUBLE_EQ(keys[0].lo, 6);
  EXPECT_DOUBLE_EQ(keys[0].hi, 12);
  EXPECT_EQ(keys[1].controller_index, -1);  // a law key
  EXPECT_FALSE(ParseTuneSearch(*fast, "stepmax=1:2", &keys, &error));
  EXPECT_NE(error.find("stepmax"), std::string::npos);
  EXPECT_NE(error.find("step_max_mm"), std::string::npos);  // names the keys there are
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=9:8", &keys, &error));
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=6:31", &keys, &error));
  EXPECT_NE(error.find("[0.5, 30]"), std::string::npos);
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=6:8,step_max_mm=6:9", &keys, &error));
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=6", &keys, &error));
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=6:8x", &keys, &error));
  // The strict number reader's grammar: no hex, nan or inf, whatever strtod would take.
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=0x6:8", &keys, &error));
  EXPECT_NE(error.find("lo:hi"), std::string::npos) << error;
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=nan:8", &keys, &error));
  EXPECT_FALSE(ParseTuneSearch(*fast, "step_max_mm=6:inf", &keys, &error));
  EXPECT_FALSE(ParseTuneSearch(*fast, "", &keys, &error));
}

// fast keeps step_min_mm <= step_max_mm: a box with no such point is refused naming the rule,
// the keys and their ranges (a key not searched at the base value); a box with one is not.
TEST(CheckTuneBox, RefusesABoxWhereNoPointKeepsTheRuleBetweenKeys) {
  const ControllerType* fast = FindControllerType("fast");
  ASSERT_NE(fast, nullptr);
  std::vector<TuneKey> keys;
  std::string error;
  ControllerChoice base;
  ASSERT_TRUE(ParseControllerChoice("fast", "", &base, &error));
  ASSERT_TRUE(ParseTuneSearch(*fast, "step_min_mm=9:12,step_max_mm=5:8", &keys, &error));
  std::string why = CheckTuneBox(keys, base);
  EXPECT_NE(why.find("step_min_mm <= step_max_mm"), std::string::npos) << why;
  EXPECT_NE(why.find("step_min_mm in [9, 12]"), std::string::npos) << why;
  EXPECT_NE(why.find("step_max_mm in [5, 8]"), std::string::npos) << why;
  // Points where the ranges touch keep it (step_min_mm = step_max_mm = 8).
  ASSERT_TRUE(ParseTuneSearch(*fast, "step_min_mm=8:12,step_max_mm=5:8", &keys, &error));
  EXPECT_EQ(CheckTuneBox(keys, base), "");
  // The default box and the documented one hold such points.
  for (const char* box : {"step_max_mm=7.5:14,step_min_mm=3:10,strength_pa=0:300",
                          "step_max_mm=7.5:13,step_min_mm=3:10,strength_pa=0:300,"
                          "lateral_gain=0.3:1.5,lag_gain=0:1,pref_pa=70:200"}) {
    ASSERT_TRUE(ParseTuneSearch(*fast, box, &keys, &error)) << error;
    EXPECT_EQ(CheckTuneBox(keys, base), "") << box;
  }
  // step_max_mm not searched: its base value (7.5 by default, 10 as given) is the range.
  ASSERT_TRUE(ParseTuneSearch(*fast, "step_min_mm=9:12", &keys, &error));
  why = CheckTuneBox(keys, base);
  EXPECT_NE(why.find("step_max_mm = 7.5 (not searched"), std::string::npos) << why;
  ASSERT_TRUE(ParseControllerChoice("fast", "step_max_mm=10", &base, &error));
  EXPECT_EQ(CheckTuneBox(keys, base), "");
  // A controller without rules, or only law keys: nothing to refuse.
  ASSERT_TRUE(ParseTuneSearch(*fast, "beta=1:3", &keys, &error));
  EXPECT_EQ(CheckTuneBox(keys, base), "");
}

TEST(TuneValues, SetAndReadBackTheSearchedKeys) {
  const ControllerType* fast = FindControllerType("fast");
  ASSERT_NE(fast, nullptr);
  std::vector<TuneKey> keys;
  std::string error;
  ASSERT_TRUE(ParseTuneSearch(*fast, "strength_pa=0:300,pref_pa=50:200", &keys, &error));
  TrialConfig base;
  base.controller.name = "fast";  // every default
  const TrialConfig c = WithTuneValues(keys, {120.0, 150.0}, base);
  EXPECT_EQ(TuneValues(keys, c), (std::vector<double>{120.0, 150.0}));
  EXPECT_DOUBLE_EQ(c.law.p_ref_pa, 150.0);
  EXPECT_EQ(c.controller.values.size(), fast->keys.size());
  EXPECT_EQ(c.controller.Validate(), "");
  // The other keys keep their defaults.
  EXPECT_DOUBLE_EQ(c.controller.values[0], fast->keys[0].default_value);
}

}  // namespace
}  // namespace ssc
