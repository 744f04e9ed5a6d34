// libFuzzer target for the plugin's config parser (tools/fuzz_inputs.sh builds and runs it).
// Input: "key=value" lines; each value goes to ParseChamberPressureConfig as MuJoCo would hand
// it over. The parser must return a config or an error, never crash, hang or read out of bounds;
// an accepted config must hold every numeric key within its range.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "plugin/chamber_pressure_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::map<std::string, std::string> given;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    const std::string line = text.substr(pos, nl - pos);
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) given[line.substr(0, eq)] = line.substr(eq + 1);
    pos = nl + 1;
  }
  std::string error;
  const auto config = ssc::ParseChamberPressureConfig(
      [&given](const char* key) -> const char* {
        auto it = given.find(key);
        return it == given.end() ? nullptr : it->second.c_str();
      },
      &error);
  if (config) {
    for (const ssc::ChamberPressureConfigKey& k : ssc::ChamberPressureConfigKeys()) {
      // Unit round trips (mm -> m -> mm) may move the last bit: allow a relative 1e-12.
      if (!k.parse_text) {
        const double v = k.get(*config);
        ssc::NumberRange loose = k.range;
        loose.whole = false;
        loose.lo -= 1e-12 * std::abs(loose.lo);
        loose.hi += 1e-12 * std::abs(loose.hi);
        loose.lo_open = loose.hi_open = false;
        if (!loose.Contains(v)) std::abort();
      }
    }
    (void)ssc::DescribeChamberPressureConfig(*config);
  } else if (error.empty()) {
    std::abort();  // a refusal always says why
  }
  return 0;
}
