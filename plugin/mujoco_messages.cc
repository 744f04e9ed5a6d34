#include "plugin/mujoco_messages.h"

#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ssc {
namespace {

// The project's scenes attach the tool model with an empty prefix, and MuJoCo warns on every
// load that such a model may not save correctly. Harmless here: the tool is attached once, its
// names do not clash with the arm's, and the twin never saves a compiled model back to MJCF.
constexpr const char* kEmptyPrefixAttach = "Attaching a spec with an empty prefix";

void PrintWarning(const char* msg) {
  if (std::strstr(msg, kEmptyPrefixAttach) != nullptr) return;
  std::fprintf(stderr, "MuJoCo warning: %s\n", msg);
}

void PrintErrorAndExit(const char* msg) {
  std::fprintf(stderr, "MuJoCo error: %s\n", msg);
  std::exit(1);
}

}  // namespace

void InstallMuJoCoMessageHandlers() {
  if (mju_user_warning == nullptr) mju_user_warning = PrintWarning;
  if (mju_user_error == nullptr) mju_user_error = PrintErrorAndExit;
}

}  // namespace ssc
