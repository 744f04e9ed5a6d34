// MuJoCo warning/error handlers for hosts that kept MuJoCo's defaults, which append every
// message to MUJOCO_LOG.TXT in the working directory: ours print to stderr only.
#ifndef SSC_PLUGIN_MUJOCO_MESSAGES_H_
#define SSC_PLUGIN_MUJOCO_MESSAGES_H_

namespace ssc {

// Sets mju_user_warning / mju_user_error where they are unset (a host's own handlers, e.g. the
// mujoco Python package's error handler, stay). Loading the plugin library calls it.
void InstallMuJoCoMessageHandlers();

}  // namespace ssc

#endif  // SSC_PLUGIN_MUJOCO_MESSAGES_H_
