// ssc sil SCRIPT [ARGS...]: runs a lab script against the twin (software in the loop). The work
// is Python's (the stand-ins for rospy, tf and ur_rtde live in the ssc_twin package), so this
// execs `PYTHON -m ssc_twin.sil` with the same arguments; docs/sil.md.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/ssc/commands.h"
#include "runtime/mujoco_model.h"

namespace ssc {

namespace {

// $SSC_PYTHON, else the project's venv beside the sources, else python3 on the PATH.
std::string SilPython() {
  if (const char* env = std::getenv("SSC_PYTHON"); env && *env) return env;
  const std::filesystem::path venv = std::filesystem::path(SourceDir()) / ".venv/bin/python";
  std::error_code ec;
  if (std::filesystem::exists(venv, ec)) return venv.string();
  return "python3";
}

}  // namespace

int RunSilCommand(int argc, char** argv) {
  const std::string python = SilPython();
  // In a build tree, the ssc_twin package staged beside bin/ (python/CMakeLists.txt).
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path staged = self.parent_path().parent_path() / "python_pkg";
  if (!ec && std::filesystem::exists(staged / "ssc_twin", ec)) {
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = staged.string() + (old && *old ? ":" + std::string(old) : "");
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  std::vector<char*> args;
  static char dash_m[] = "-m", module[] = "ssc_twin.sil";
  args.push_back(const_cast<char*>(python.c_str()));
  args.push_back(dash_m);
  args.push_back(module);
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  if (argc == 0) {
    std::fprintf(stderr,
                 "usage: ssc sil [options] SCRIPT [ARGS...]   (ssc sil --help; docs/sil.md)\n");
    return 2;
  }
  execvp(python.c_str(), args.data());
  std::fprintf(stderr,
               "ssc sil: cannot run %s (%s); set SSC_PYTHON to a Python with the ssc_twin package "
               "installed (pip install .; docs/python.md)\n",
               python.c_str(), std::strerror(errno));
  return 1;
}

}  // namespace ssc
