#include "plugin/chamber_pressure_config.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "common/xml_text.h"

namespace ssc {
namespace {

using C = ChamberPressureConfig;

bool ParseGroups(std::string_view text, C* c, std::string* error) {
  std::array<unsigned char, kNumGeomGroups> groups{};
  int count = 0;
  std::istringstream in{std::string(text)};
  std::string token;
  const NumberRange range = NumberRange::Whole(0, kNumGeomGroups - 1);
  while (in >> token) {
    double g = 0;
    std::string e;
    if (!ParseNumber(token, range, &g, &e)) {
      *error = "geom group " + e;
      return false;
    }
    if (groups[static_cast<int>(g)]) {
      *error = "geom group " + token + " is listed twice";
      return false;
    }
    groups[static_cast<int>(g)] = 1;
    ++count;
  }
  if (count == 0) {
    *error = "lists no geom group; expected space-separated groups, each " + range.ToString();
    return false;
  }
  c->ray_groups = groups;
  return true;
}

std::string FormatGroups(const C& c) {
  std::string s;
  for (int g = 0; g < kNumGeomGroups; ++g) {
    if (c.ray_groups[g]) s += (s.empty() ? "" : " ") + std::to_string(g);
  }
  return s;
}

// Getters and setters in the key's unit; the structs hold SI units (to_si = 1 / to_key,
// written out so that a given value converts exactly as it always has).
#define SSC_KEY_SCALED(member, to_key, to_si) \
  [](const C& c) { return c.member * (to_key); }, [](C* c, double v) { c->member = v * (to_si); }
#define SSC_KEY_INT(member, type)                           \
  [](const C& c) { return static_cast<double>(c.member); }, \
      [](C* c, double v) { c->member = static_cast<type>(v); }

// constexpr: the table is built from the plugin library's load-time initialiser, maybe before
// this file's dynamic initialisers have run.
constexpr NumberRange kArea = NumberRange::Positive(10000);
constexpr double kDegPerRad = 57.29577951308232;

}  // namespace

const std::vector<ChamberPressureConfigKey>& ChamberPressureConfigKeys() {
  static const std::vector<ChamberPressureConfigKey> keys = {
      // Geometry.
      {"opening_radius_mm", "mm", "geometry", "internal radius of the cup's opening",
       NumberRange::Closed(0.5, 50), SSC_KEY_SCALED(geometry.opening_radius_m, 1e3, 1e-3)},
      {"open_depth_mm", "mm", "geometry",
       "depth scale of the continuous seal: a layer of air this thick under the lip tips passes "
       "air freely, thinner ones in proportion (no threshold)",
       NumberRange::Closed(0.05, 10), SSC_KEY_SCALED(geometry.open_depth_m, 1e3, 1e-3)},
      {"lip_roughness_um", "um", "geometry", "leak gap of a lip segment lying on a surface",
       NumberRange::Closed(0, 1000), SSC_KEY_SCALED(geometry.lip_roughness_gap_m, 1e6, 1e-6)},
      {"rays_per_chamber", "", "geometry", "radial rays sampling each chamber's opening",
       NumberRange::Whole(1, kMaxRaysPerChamber), SSC_KEY_INT(geometry.rays_per_chamber, int)},
      {"ray_start_mm", "mm", "geometry", "rays start this far above the lip plane",
       NumberRange::Closed(0.1, 1000), SSC_KEY_SCALED(ray_start_m, 1e3, 1e-3)},
      {"ray_groups", "", "geometry",
       "geom groups the rays see, space-separated (group 1 is the robot; not the lip's group)",
       NumberRange::Whole(0, kNumGeomGroups - 1), nullptr, nullptr, ParseGroups, FormatGroups},
      {"lip_geom_group", "", "geometry", "geom group of the lip segments under the sensor's site",
       NumberRange::Whole(0, kNumGeomGroups - 1), SSC_KEY_INT(lip_geom_group, int)},
      // Lip mechanics (docs/pneumatics.md: the lip ring, shear and tilt).
      {"lip_bending_nmm2", "N mm^2", "lip",
       "EI of the lip ring bent out of its plane (couples the lip segments; 0 = uncoupled)",
       NumberRange::Closed(0, 100), SSC_KEY_SCALED(lip.bending_stiffness_nm2, 1e6, 1e-6)},
      {"lip_shear_n_per_mm", "N/mm", "lip",
       "lateral stiffness of the lip carrier under friction; 0 = rigid (off), soft cup ~1",
       NumberRange::Closed(0, 100), SSC_KEY_SCALED(lip.shear_stiffness_n_per_m, 1e-3, 1e3)},
      {"lip_tilt_nmm_per_deg", "N mm/deg", "lip",
       "tilt stiffness of the lip carrier about its pivot; 0 = rigid (off), soft cup ~5",
       NumberRange::Closed(0, 1000),
       SSC_KEY_SCALED(lip.tilt_stiffness_nm_per_rad, 1e3 / kDegPerRad, 1e-3 * kDegPerRad)},
      {"lip_vacuum_load", "", "lip",
       "1 = each chamber's vacuum loads a flex skirt lip and the cup (pressure x area); 0 = off",
       NumberRange::Whole(0, 1), SSC_KEY_INT(lip_vacuum_load, int)},
      {"lip_max_press_mm", "mm", "lip",
       "deepest press of the lip plane below a surface before rigid parts of the tool would land; "
       "refused beyond the tool's own (segments' slide travel; skirt: wall clearance less its "
       "thickness)",
       NumberRange::Closed(0.1, 20), SSC_KEY_SCALED(lip_max_press_m, 1e3, 1e-3)},
      // Pneumatics.
      {"pump_max_vacuum_pa", "Pa", "pneumatics", "pump vacuum at zero flow",
       NumberRange::Positive(100000).OpenHigh(),
       SSC_KEY_SCALED(pneumatics.pump_max_vacuum_pa, 1, 1)},
      {"pump_free_flow_lpm", "L/min", "pneumatics", "pump flow at zero vacuum",
       NumberRange::Positive(60000),
       [](const C& c) { return c.pneumatics.pump_free_flow_m3_s * 60000.0; },
       [](C* c, double v) { c->pneumatics.pump_free_flow_m3_s = v / 60000.0; }},
      {"port_area_mm2", "mm^2", "pneumatics", "restriction from each chamber to the shared port",
       kArea, SSC_KEY_SCALED(pneumatics.port_area_m2, 1e6, 1e-6)},
      {"neighbour_area_mm2", "mm^2", "pneumatics", "restriction between neighbouring chambers",
       NumberRange::Closed(0, 10000), SSC_KEY_SCALED(pneumatics.neighbour_area_m2, 1e6, 1e-6)},
      {"tap_recovery", "", "pneumatics",
       "fraction of an inflow jet's dynamic pressure the tap recovers", NumberRange::Closed(0, 1),
       SSC_KEY_SCALED(pneumatics.tap_recovery, 1, 1)},
      {"jet_area_mm2", "mm^2", "pneumatics", "leak area at which the inflow jet fills the chamber",
       kArea, SSC_KEY_SCALED(pneumatics.jet_area_m2, 1e6, 1e-6)},
      {"discharge_coeff", "", "pneumatics", "orifice discharge coefficient C_d",
       NumberRange::Positive(1), SSC_KEY_SCALED(pneumatics.discharge_coeff, 1, 1)},
      {"air_density_kg_m3", "kg/m^3", "pneumatics", "ambient air density",
       NumberRange::Positive(10).OpenLow(), SSC_KEY_SCALED(pneumatics.air_density_kg_m3, 1, 1)},
      // Sensor chain.
      {"sample_rate_hz", "Hz", "sensor chain", "pressure sensor sample rate (zero-order hold)",
       NumberRange::Closed(1, 100000), SSC_KEY_SCALED(sensor.sample_rate_hz, 1, 1)},
      {"noise_pa", "Pa", "sensor chain", "1-sigma noise per chamber per sample",
       NumberRange::Closed(0, 10000), SSC_KEY_SCALED(sensor.noise_pa, 1, 1)},
      {"average_samples", "", "sensor chain", "host moving-average window, samples",
       NumberRange::Whole(1, kMaxAverageSamples), SSC_KEY_INT(sensor.average_samples, int)},
      {"lag_ms", "ms", "sensor chain", "first-order lag of tube and sensor (0 = none)",
       NumberRange::Closed(0, 10000), SSC_KEY_SCALED(sensor.lag_s, 1e3, 1e-3)},
      {"seed", "", "sensor chain", "noise seed (combined with the run's seed)", kSeedRange,
       SSC_KEY_INT(sensor.seed, std::uint64_t)},
  };
  return keys;
}

#undef SSC_KEY_SCALED
#undef SSC_KEY_INT

std::string ConfigValueText(const ChamberPressureConfigKey& k, const ChamberPressureConfig& c) {
  return k.format_text ? k.format_text(c) : FormatNumber(k.get(c));
}

std::optional<ChamberPressureConfig> ParseChamberPressureConfig(
    const std::function<const char*(const char* key)>& lookup, std::string* error) {
  ChamberPressureConfig c;
  const std::string plugin = kChamberPressurePluginName;
  for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) {
    const char* text = lookup(k.key);
    if (text == nullptr || text[0] == '\0') continue;  // not given: the default
    std::string e;
    bool ok = false;
    if (k.parse_text) {
      ok = k.parse_text(text, &c, &e);
    } else {
      double v = 0;
      ok = ParseNumber(text, k.range, &v, &e);
      if (ok) k.set(&c, v);
    }
    if (!ok) {
      *error = plugin + ": config key '" + k.key + "' has value '" + text + "': " + e +
               (k.unit[0] && !k.parse_text ? std::string(" ") + k.unit : "");
      return std::nullopt;
    }
  }
  if (c.ray_groups[c.lip_geom_group]) {
    *error = plugin + ": lip_geom_group " + std::to_string(c.lip_geom_group) +
             " is also in ray_groups: the rays would hit the cup's own lip";
    return std::nullopt;
  }
  // The pure structs check their own invariants (relations between keys included).
  for (const std::string& e :
       {c.geometry.Validate(), c.pneumatics.Validate(), c.sensor.Validate()}) {
    if (!e.empty()) {
      *error = plugin + ": " + e;
      return std::nullopt;
    }
  }
  return c;
}

namespace {

std::string FindEmptyConfigValuesIn(const std::filesystem::path& file,
                                    const std::filesystem::path& main_dir, int depth) {
  std::string text;
  if (depth > 16 || !ReadXmlWithoutComments(file, &text)) return "";
  static const std::regex config_tag(R"(<config\b[^>]*>)");
  static const std::regex empty_value(R"(\bvalue\s*=\s*(["'])\s*\1)");
  static const std::regex key_attr(R"(\bkey\s*=\s*["']([^"']*)["'])");
  // Files this one brings in: <include file=...> and <model file=...> (attached sub-models).
  static const std::regex include_tag(
      R"(<(?:include|model)\b[^>]*\bfile\s*=\s*["']([^"']+\.xml)["'])");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), config_tag);
       it != std::sregex_iterator(); ++it) {
    const std::string tag = it->str();
    if (!std::regex_search(tag, empty_value)) continue;
    std::smatch key;
    std::regex_search(tag, key, key_attr);
    const long line = 1 + std::count(text.begin(), text.begin() + it->position(), '\n');
    return file.string() + ":" + std::to_string(line) + ": config key '" +
           (key.size() > 1 ? key[1].str() : std::string("?")) +
           "' has an empty value; give a value or remove the line to use the default "
           "(docs/plugin.md)";
  }
  for (auto it = std::sregex_iterator(text.begin(), text.end(), include_tag);
       it != std::sregex_iterator(); ++it) {
    const std::filesystem::path name = (*it)[1].str();
    // MuJoCo resolves includes from the main file's folder; try the including file's too.
    std::filesystem::path next = name.is_absolute() ? name : main_dir / name;
    if (!std::filesystem::exists(next)) next = file.parent_path() / name;
    if (std::string e = FindEmptyConfigValuesIn(next, main_dir, depth + 1); !e.empty()) return e;
  }
  return "";
}

}  // namespace

std::string FindEmptyConfigValues(const std::string& mjcf_path) {
  const std::filesystem::path path(mjcf_path);
  return FindEmptyConfigValuesIn(path, path.parent_path(), 0);
}

std::string DescribeChamberPressureConfig(const ChamberPressureConfig& c) {
  std::ostringstream os;
  for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) {
    os << k.key << " = " << ConfigValueText(k, c) << (k.unit[0] ? " " : "") << k.unit << '\n';
  }
  return os.str();
}

std::string ChamberPressureConfigMarkdown() {
  const ChamberPressureConfig defaults;
  std::ostringstream os;
  os << "# The `ssc.chamber_pressure` plugin: config keys\n\n"
        "<!-- Generated by ssc_plugin_doc from plugin/chamber_pressure_config.cc; do not edit.\n"
        "     Regenerate: build/bin/ssc_plugin_doc > docs/plugin.md (a test checks it). -->\n\n"
        "Every key is optional; a key that is given must hold a plain decimal number (no hex, no\n"
        "`inf`/`nan`, no empty value) inside its range, or the model fails to load with a message\n"
        "naming the key, the value and the range. Units are in the key names.\n\n"
        "```xml\n"
        "<extension><plugin plugin=\"ssc.chamber_pressure\">\n"
        "  <instance name=\"ssc_pressure\"><config key=\"noise_pa\" value=\"6\"/></instance>\n"
        "</plugin></extension>\n"
        "<sensor><plugin name=\"ssc_chamber_pressure\" instance=\"ssc_pressure\"\n"
        "                objtype=\"site\" objname=\"ssc_tool_site\"/></sensor>\n"
        "```\n\n"
        "The sensor's output is the host-filtered vacuum of chambers 1..4 in Pa (positive =\n"
        "vacuum); see plugin/chamber_pressure_sensor.h for what it reads each sample.\n";
  std::string section;
  for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) {
    if (section != k.section) {
      section = k.section;
      os << "\n## " << char(section[0] - 'a' + 'A') << section.substr(1) << "\n\n"
         << "| key | unit | default | valid | meaning |\n| --- | --- | --- | --- | --- |\n";
    }
    const std::string valid =
        k.parse_text ? "groups, each " + k.range.ToString() : k.range.ToString();
    os << "| `" << k.key << "` | " << (k.unit[0] ? k.unit : "-") << " | "
       << ConfigValueText(k, defaults) << " | " << valid << " | " << k.meaning << " |\n";
  }
  os << "\nAlso rejected: `ray_groups` containing `lip_geom_group` (the rays would hit the lip), "
        "and\nvalue combinations the pneumatic model's own checks refuse.\n";
  return os.str();
}

}  // namespace ssc
