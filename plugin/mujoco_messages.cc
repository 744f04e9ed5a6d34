#include "plugin/mujoco_messages.h"

#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ssc {
namespace {

bool StartsWith(const char* s, const char* prefix) {
  return std::strncmp(s, prefix, std::strlen(prefix)) == 0;
}

void PrintWarning(const char* msg) {
  thread_local bool after_flex_note = false;
  if (PrintsMuJoCoWarning(msg, &after_flex_note)) {
    std::fprintf(stderr, "MuJoCo warning: %s\n", msg);
  }
}

void PrintErrorAndExit(const char* msg) {
  std::fprintf(stderr, "MuJoCo error: %s\n", msg);
  std::exit(1);
}

}  // namespace

bool PrintsMuJoCoWarning(const char* msg, bool* after_flex_note) {
  // MuJoCo 4.0's texts (engine_derivative.c, mjd_effSolve; mj_warning's mjWARN_INERTIA).
  static const char* const kFlexNote =
      "Flex stiffness is too ill-conditioned for the effective-metric block preconditioner";
  static const char* const kInertia = "Inertia matrix is too close to singular";
  if (msg == nullptr) return false;
  const bool paired = *after_flex_note;
  *after_flex_note = StartsWith(msg, kFlexNote);
  if (*after_flex_note) return false;
  return !(paired && StartsWith(msg, kInertia));
}

void InstallMuJoCoMessageHandlers() {
  if (mju_user_warning == nullptr) mju_user_warning = PrintWarning;
  if (mju_user_error == nullptr) mju_user_error = PrintErrorAndExit;
}

}  // namespace ssc
