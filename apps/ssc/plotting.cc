#include "apps/ssc/plotting.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "runtime/mujoco_model.h"

namespace ssc {

bool RunPlotScript(const std::string& script, const std::vector<std::string>& args) {
  const std::string root = SourceDir();
  std::string python = root + "/.venv/bin/python";
  if (!std::filesystem::exists(python)) {
    std::fprintf(stderr, "plot skipped: %s not found (run tools/setup.sh)\n", python.c_str());
    return false;
  }
  std::string cmd = "MPLBACKEND=Agg '" + python + "' '" + root + "/tools/" + script + "'";
  for (const std::string& a : args) cmd += " '" + a + "'";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::fprintf(stderr, "plot failed: %s exited with %d\n", script.c_str(), rc);
    return false;
  }
  return true;
}

}  // namespace ssc
