// ssc_plugin_doc: prints docs/plugin.md from the plugin's config-key table.
#include <cstdio>

#include "plugin/chamber_pressure_config.h"

int main() {
  std::fputs(ssc::ChamberPressureConfigMarkdown().c_str(), stdout);
  return 0;
}
