// The config keys of the ssc.chamber_pressure plugin, in ONE table: key, unit, range, one-line
// meaning and how it maps onto ChamberPressureConfig. The table is used to register the keys with
// MuJoCo, to parse and validate them (through the strict number reader), to print a config and
// to generate docs/plugin.md (ssc_plugin_doc; a test checks the doc against it). Defaults are
// the defaults of the pure parameter structs (one home for each). Adding a key = one row in
// chamber_pressure_config.cc (plus, for a new field, its member and default in the struct).
// Pure C++: no MuJoCo types, so the parser is unit-tested and fuzzed alone.
#ifndef SSC_PLUGIN_CHAMBER_PRESSURE_CONFIG_H_
#define SSC_PLUGIN_CHAMBER_PRESSURE_CONFIG_H_

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/strict_number.h"
#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/flow_network.h"
#include "plugin/pneumatics/lip_ring.h"
#include "plugin/pneumatics/sensor_chain.h"

namespace ssc {

inline constexpr char kChamberPressurePluginName[] = "ssc.chamber_pressure";
inline constexpr int kNumGeomGroups = 6;  // MuJoCo's mjNGROUP (checked where MuJoCo is seen)

// Every config value, parsed and validated once.
struct ChamberPressureConfig {
  CupGeometry geometry;
  LipMechanics lip;
  PneumaticParams pneumatics;
  SensorChainParams sensor;
  double ray_start_m = 0.01;
  std::array<unsigned char, kNumGeomGroups> ray_groups{1, 0, 1, 0, 0, 0};  // 1 = seen by rays
  int lip_geom_group = 4;
  // A flex skirt only (segment lips carry none). Off by default: the modelled skirt lacks the
  // chamber walls that hold the real lip against a sealed cup's vacuum (docs/pneumatics.md).
  int lip_vacuum_load = 0;
  // How far the lip plane may be pressed below a surface: a trial's approach stops there if the
  // F/T has not read its preload yet, and no controller takes the cup deeper.
  double lip_max_press_m = 0.002;
};

// One config key. Numeric keys use get/set (value in the key's unit); a key with parse_text
// (a list, e.g. ray_groups) uses parse_text/format_text instead.
struct ChamberPressureConfigKey {
  const char* key;      // the unit is in the name (_mm, _pa, _hz)
  const char* unit;     // for messages and docs ("" = dimensionless)
  const char* section;  // geometry, pneumatics, sensor chain
  const char* meaning;  // one line
  NumberRange range;
  double (*get)(const ChamberPressureConfig&);
  void (*set)(ChamberPressureConfig*, double);
  bool (*parse_text)(std::string_view text, ChamberPressureConfig* c, std::string* error) = nullptr;
  std::string (*format_text)(const ChamberPressureConfig& c) = nullptr;
};

const std::vector<ChamberPressureConfigKey>& ChamberPressureConfigKeys();

// The key's value in `c` as config text ("5.5", "0 2").
std::string ConfigValueText(const ChamberPressureConfigKey& k, const ChamberPressureConfig& c);

// Parses a config from `lookup` (key -> value text; nullptr or "" when the key is not given).
// Every given value must parse fully and lie in its range; the cross-key rules and the pure
// structs' own Validate() are checked after. On error returns nullopt and *error names the key,
// the value and the valid range.
std::optional<ChamberPressureConfig> ParseChamberPressureConfig(
    const std::function<const char*(const char* key)>& lookup, std::string* error);

// MuJoCo hands a plugin "" both for a key that is absent and for value="": this scans an MJCF
// file and the files it <include>s for <config ... value=""> (or all blanks) and returns an
// error naming the file, line and key; "" when there is none (or a file cannot be read: the
// MuJoCo load reports that).
std::string FindEmptyConfigValues(const std::string& mjcf_path);

// "key = value unit" lines for every key (what a run used).
std::string DescribeChamberPressureConfig(const ChamberPressureConfig& c);

// docs/plugin.md, generated from the table.
std::string ChamberPressureConfigMarkdown();

}  // namespace ssc

#endif  // SSC_PLUGIN_CHAMBER_PRESSURE_CONFIG_H_
