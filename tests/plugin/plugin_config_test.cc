// The plugin's config-key table: strict parsing of every key, defaults from the pure structs,
// and docs/plugin.md generated from the table.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "plugin/chamber_pressure_config.h"

namespace ssc {
namespace {

std::optional<ChamberPressureConfig> Parse(const std::map<std::string, std::string>& given,
                                           std::string* error) {
  return ParseChamberPressureConfig(
      [&given](const char* key) -> const char* {
        auto it = given.find(key);
        return it == given.end() ? nullptr : it->second.c_str();
      },
      error);
}

TEST(PluginConfigTest, EveryKeyOnceAndDefaultsAreTheStructDefaults) {
  std::set<std::string> seen;
  const ChamberPressureConfig defaults;
  std::string error;
  for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) {
    EXPECT_TRUE(seen.insert(k.key).second) << "key listed twice: " << k.key;
    // Giving each key its default text reproduces the default config (get/set agree).
    const std::string text = ConfigValueText(k, defaults);
    const auto c = Parse({{k.key, text}}, &error);
    ASSERT_TRUE(c) << k.key << "=" << text << ": " << error;
    EXPECT_EQ(ConfigValueText(k, *c), text) << k.key;
    if (!k.parse_text) {
      EXPECT_TRUE(k.range.Contains(k.get(defaults))) << k.key;
    }
  }
  EXPECT_EQ(seen.size(), 25u);
}

TEST(PluginConfigTest, ValuesReachTheirMembersInSiUnits) {
  std::string error;
  const auto c = Parse({{"opening_radius_mm", "6"},
                        {"pump_free_flow_lpm", "18"},
                        {"lag_ms", "4"},
                        {"ray_groups", "0 3"},
                        {"seed", "12"},
                        {"lip_shear_n_per_mm", "1.5"},
                        {"lip_tilt_nmm_per_deg", "5"},
                        {"lip_max_press_mm", "3"}},
                       &error);
  ASSERT_TRUE(c) << error;
  EXPECT_DOUBLE_EQ(c->lip_max_press_m, 3e-3);
  EXPECT_DOUBLE_EQ(c->geometry.opening_radius_m, 6e-3);
  EXPECT_DOUBLE_EQ(c->pneumatics.pump_free_flow_m3_s, 18 / 60000.0);
  EXPECT_DOUBLE_EQ(c->sensor.lag_s, 4e-3);
  EXPECT_EQ(c->ray_groups[3], 1);
  EXPECT_EQ(c->ray_groups[2], 0);
  EXPECT_EQ(c->sensor.seed, 12u);
  EXPECT_DOUBLE_EQ(c->lip.shear_stiffness_n_per_m, 1500.0);
  EXPECT_NEAR(c->lip.tilt_stiffness_nm_per_rad, 5e-3 * 180 / 3.14159265358979323846, 1e-15);
}

TEST(PluginConfigTest, BadValuesNameKeyValueAndRange) {
  struct Case {
    const char* key;
    const char* value;
    const char* expect;
  };
  for (const Case& c :
       {Case{"noise_pa", "0x10", "[0, 10000]"}, Case{"noise_pa", "inf", "noise_pa"},
        Case{"noise_pa", "6 Pa", "decimal"}, Case{"open_depth_mm", "-1", "[0.05, 10] mm"},
        Case{"port_area_mm2", "0", "(0, 10000] mm^2"},
        Case{"rays_per_chamber", "2.5", "whole number"}, Case{"seed", "-1", "seed"},
        Case{"ray_groups", "0 9", "ray_groups"}, Case{"ray_groups", "0 0", "twice"},
        Case{"ray_groups", "0 x", "ray_groups"}, Case{"ray_groups", "4", "lip_geom_group"},
        Case{"average_samples", "65", "[1, 64]"}}) {
    std::string error;
    EXPECT_FALSE(Parse({{c.key, c.value}}, &error)) << c.key << "=" << c.value;
    EXPECT_NE(error.find(c.key), std::string::npos) << error;
    EXPECT_NE(error.find(c.expect), std::string::npos) << error;
    EXPECT_NE(error.find(c.value), std::string::npos) << error;
  }
}

TEST(PluginConfigTest, DocsAreGeneratedFromTheTable) {
  std::ifstream in(std::string(SSC_SOURCE_DIR) + "/docs/plugin.md");
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_EQ(doc.str(), ChamberPressureConfigMarkdown())
      << "docs/plugin.md is stale: build/bin/ssc_plugin_doc > docs/plugin.md";
  for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) {
    EXPECT_NE(doc.str().find(std::string("`") + k.key + "`"), std::string::npos) << k.key;
  }
}

}  // namespace
}  // namespace ssc
