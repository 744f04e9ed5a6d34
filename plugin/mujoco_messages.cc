#include "plugin/mujoco_messages.h"

#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstdlib>

namespace ssc {
namespace {

void PrintWarning(const char* msg) { std::fprintf(stderr, "MuJoCo warning: %s\n", msg); }

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
