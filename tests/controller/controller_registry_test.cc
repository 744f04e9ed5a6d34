// The controller interface as pure logic: the command's range check, the registry's strict
// parameter parsing, and the published law through the interface.
#include "controller/controller_registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "controller/published_controller.h"

namespace ssc {
namespace {

TEST(ControllerCommandTest, FiniteCommandsWithinRangePassAndOthersNameWhatIsWrong) {
  ControllerCommand c;
  c.step_m = {0.007, -0.002};
  EXPECT_EQ(CheckControllerCommand(c), "");
  c.step_m = {std::numeric_limits<double>::quiet_NaN(), 0};
  EXPECT_NE(CheckControllerCommand(c).find("not finite"), std::string::npos);
  c.step_m = {kMaxCommandStepM * 0.8, kMaxCommandStepM * 0.8};  // longer than the limit
  EXPECT_NE(CheckControllerCommand(c).find("step length"), std::string::npos);
  c.step_m = {0, 0};
  c.height_offset_m = kMaxHeightOffsetM * 1.01;
  EXPECT_NE(CheckControllerCommand(c).find("height offset"), std::string::npos);
  c.height_offset_m = std::numeric_limits<double>::infinity();
  EXPECT_NE(CheckControllerCommand(c).find("height offset"), std::string::npos);
  c.height_offset_m = kMinHeightOffsetM;
  EXPECT_EQ(CheckControllerCommand(c), "");
}

struct TestParams {
  double gain = 2;
  double limit_mm = 5;
};

class TestController : public Controller {
 public:
  TestController(const ControllerContext&, const TestParams& p) : p_(p) {}
  ControllerCommand Step(const ControllerInput&) override {
    ControllerCommand c;
    c.step_m = {p_.gain * 1e-3, p_.limit_mm * 1e-3};
    return c;
  }

 private:
  TestParams p_;
};

ControllerType TestType() {
  return MakeControllerType<TestController, TestParams>(
      "test", "a test controller",
      {{"gain", "1", 0, 10, "a gain", &TestParams::gain},
       {"limit_mm", "mm", 1, 20, "a limit", &TestParams::limit_mm}});
}

TEST(ControllerRegistryTest, KeyTableDefaultsComeFromTheParamsStruct) {
  const ControllerType t = TestType();
  ASSERT_EQ(t.keys.size(), 2u);
  EXPECT_EQ(t.keys[0].key, "gain");
  EXPECT_EQ(t.keys[0].default_value, TestParams{}.gain);
  EXPECT_EQ(t.keys[1].default_value, TestParams{}.limit_mm);
  EXPECT_EQ(t.keys[1].unit, "mm");
}

TEST(ControllerRegistryTest, ValuesParseOverTheDefaultsIntoTheController) {
  const ControllerType t = TestType();
  ControllerValues v;
  std::string error;
  ASSERT_TRUE(ParseControllerValues(t, "limit_mm=7.5", &v, &error)) << error;
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], TestParams{}.gain);
  EXPECT_EQ(v[1], 7.5);
  const ControllerCommand c = t.make({}, v)->Step({});
  EXPECT_DOUBLE_EQ(c.step_m[1], 7.5e-3);
  ASSERT_TRUE(ParseControllerValues(t, "", &v, &error));
  EXPECT_EQ(v[1], TestParams{}.limit_mm);
}

TEST(ControllerRegistryTest, UnknownKeysBadValuesAndRepeatsAreRefusedNamingTheKey) {
  const ControllerType t = TestType();
  ControllerValues v;
  std::string error;
  EXPECT_FALSE(ParseControllerValues(t, "gian=1", &v, &error));
  EXPECT_NE(error.find("unknown key 'gian'"), std::string::npos) << error;
  EXPECT_NE(error.find("gain, limit_mm"), std::string::npos) << error;
  EXPECT_FALSE(ParseControllerValues(t, "limit_mm=50", &v, &error));
  EXPECT_NE(error.find("limit_mm"), std::string::npos) << error;
  EXPECT_NE(error.find("[1, 20]"), std::string::npos) << error;
  EXPECT_FALSE(ParseControllerValues(t, "gain=1,", &v, &error));  // a stray comma
  EXPECT_NE(error.find("expected key=value"), std::string::npos) << error;
  for (const char* bad : {"gain=nan", "gain=1mm", "gain=", "gain", "gain=1,gain=2"}) {
    EXPECT_FALSE(ParseControllerValues(t, bad, &v, &error)) << bad;
    EXPECT_NE(error.find("gain"), std::string::npos) << bad << ": " << error;
  }
}

// Counts and on/off switches take whole numbers only: 0.0001 is not "on", 8.5 points is no count.
TEST(ControllerRegistryTest, WholeKeysRefuseFractionsNamingTheKey) {
  ControllerChoice choice;
  std::string error;
  for (const char* bad : {"tare_in_air=0.0001", "tare_in_air=0.5", "timing=0.9"}) {
    EXPECT_FALSE(ParseControllerChoice("fast", bad, &choice, &error)) << bad;
    EXPECT_NE(error.find("not a whole number"), std::string::npos) << bad << ": " << error;
  }
  EXPECT_FALSE(ParseControllerChoice("edge_track", "fit_points=8.5", &choice, &error));
  EXPECT_NE(error.find("fit_points"), std::string::npos) << error;
  EXPECT_TRUE(ParseControllerChoice("fast", "tare_in_air=1,timing=0", &choice, &error)) << error;
  // Values set directly (a tune point, a binding) go through the same check.
  ASSERT_TRUE(ParseControllerChoice("fast", "", &choice, &error));
  const ControllerType* fast = FindControllerType("fast");
  for (size_t i = 0; i < fast->keys.size(); ++i) {
    if (fast->keys[i].key == "tare_in_air") choice.values[i] = 0.0001;
  }
  EXPECT_NE(choice.Validate().find("tare_in_air"), std::string::npos) << choice.Validate();
  // Every switch of every controller is a whole key.
  for (const ControllerType& t : ControllerTypes()) {
    for (const ControllerParamKey& k : t.keys) {
      if (k.what.rfind("1: ", 0) == 0) {
        EXPECT_TRUE(k.whole) << t.name << "." << k.key;
      }
    }
  }
}

TEST(ControllerRegistryTest, ThePublishedLawIsTheDefaultAndTakesNoParameters) {
  ControllerChoice choice;
  EXPECT_TRUE(choice.IsPublished());
  EXPECT_EQ(choice.Validate(), "");
  EXPECT_EQ(ControllerTypes().front().name, "published");
  std::string error;
  EXPECT_FALSE(ParseControllerChoice("published", "beta=2", &choice, &error));
  EXPECT_NE(error.find("takes no parameters"), std::string::npos) << error;
  EXPECT_FALSE(ParseControllerChoice("pubished", "", &choice, &error));
  EXPECT_NE(error.find("unknown controller 'pubished'"), std::string::npos) << error;
  EXPECT_NE(error.find("published"), std::string::npos) << error;
  choice.name = "nonesuch";
  EXPECT_NE(choice.Validate(), "");
  EXPECT_EQ(choice.Make({}), nullptr);
}

// The rule between keys holds however the values arrive: parsed, or set directly (a search's
// point, a binding), so a choice that breaks it never validates nor builds a controller.
TEST(ControllerRegistryTest, ARuleBetweenKeysHoldsForValuesSetDirectly) {
  const ControllerType* fast = FindControllerType("fast");
  ASSERT_NE(fast, nullptr);
  ASSERT_EQ(fast->orders.size(), 1u);
  EXPECT_EQ(KeyOrderText(*fast, fast->orders[0]), "step_min_mm <= step_max_mm");
  ControllerChoice choice;
  std::string error;
  ASSERT_TRUE(ParseControllerChoice("fast", "step_min_mm=6,step_max_mm=6", &choice, &error));
  EXPECT_EQ(choice.Validate(), "");
  choice.values[fast->orders[0].lower] = 9;  // above step_max_mm = 6
  const std::string why = choice.Validate();
  EXPECT_NE(why.find("step_min_mm = 9 exceeds step_max_mm = 6"), std::string::npos) << why;
  EXPECT_NE(why.find("step_min_mm <= step_max_mm"), std::string::npos) << why;
  EXPECT_EQ(choice.Make({}), nullptr);
  EXPECT_EQ(CheckKeyOrders(*fast, choice.values), why.substr(why.find("step_min_mm")));
}

TEST(ControllerRegistryTest, EveryRegisteredKeyHasAUnitARangeAndADefaultInIt) {
  for (const ControllerType& t : ControllerTypes()) {
    EXPECT_FALSE(t.what.empty()) << t.name;
    ASSERT_TRUE(t.make) << t.name;
    ControllerValues defaults;
    for (const ControllerParamKey& k : t.keys) defaults.push_back(k.default_value);
    EXPECT_EQ(CheckKeyOrders(t, defaults), "") << t.name;  // the defaults keep the rules
    for (const ControllerKeyOrder& o : t.orders) {         // each rule names two of the type's keys
      EXPECT_LT(o.lower, t.keys.size()) << t.name;
      EXPECT_LT(o.upper, t.keys.size()) << t.name;
      EXPECT_NE(o.lower, o.upper) << t.name;
    }
    for (const ControllerParamKey& k : t.keys) {
      EXPECT_FALSE(k.unit.empty()) << t.name << "." << k.key;
      EXPECT_LT(k.min, k.max) << t.name << "." << k.key;
      EXPECT_GE(k.default_value, k.min) << t.name << "." << k.key;
      EXPECT_LE(k.default_value, k.max) << t.name << "." << k.key;
    }
    ControllerChoice choice;
    choice.name = t.name;
    EXPECT_NE(choice.Make({}), nullptr) << t.name;
  }
}

TEST(PublishedControllerTest, ItsStepIsTheLawsStepAndTheHeightIsHeld) {
  ControllerContext context;
  context.law.p_ref_pa = 70;
  context.law.beta = 1.5;
  context.law.step_mm = 5;
  ControllerChoice choice;
  std::unique_ptr<Controller> c = choice.Make(context);
  ASSERT_NE(c, nullptr);
  for (const std::array<double, 4>& p : std::array<std::array<double, 4>, 3>{
           {{200, 180, 20, 30}, {3, 2, 1, 4}, {5000, 4000, 6000, 3000}}}) {
    ControllerInput in;
    in.p_pa = p;
    const ControllerCommand cmd = c->Step(in);
    const ContourStep law = ComputeContourStep(p, context.law);
    EXPECT_EQ(cmd.step_m, law.step_m);  // to the bit
    EXPECT_EQ(cmd.height_offset_m, 0.0);
    EXPECT_FALSE(cmd.lifted);
  }
}

}  // namespace
}  // namespace ssc
