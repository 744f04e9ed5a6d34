// MuJoCo warning/error handlers for hosts that kept MuJoCo's defaults, which append every
// message to MUJOCO_LOG.TXT in the working directory: ours print to stderr only.
#ifndef SSC_PLUGIN_MUJOCO_MESSAGES_H_
#define SSC_PLUGIN_MUJOCO_MESSAGES_H_

namespace ssc {

// Sets mju_user_warning / mju_user_error where they are unset (a host's own handlers, e.g. the
// mujoco Python package's error handler, stay). Loading the plugin library calls it.
void InstallMuJoCoMessageHandlers();

// Whether our warning handler prints `msg`. It leaves out one pair only: MuJoCo's note that the
// flex M+K solve of the discrete integrator ran out of opt.iterations ("Flex stiffness is too
// ill-conditioned for the effective-metric block preconditioner ...") and the inertia warning
// MuJoCo raises right after it for the same solve: the flex scenes cap the iterations below what
// that solve needs on purpose, measured harmless (docs/flex_cost.md, "The skirt's M+K solve and
// MuJoCo's inertia warning"). An inertia warning that does not follow the flex note (a singular
// mass matrix) is printed, as is every other.
// `after_flex_note` carries the pairing from one message to the next (one per thread).
bool PrintsMuJoCoWarning(const char* msg, bool* after_flex_note);

}  // namespace ssc

#endif  // SSC_PLUGIN_MUJOCO_MESSAGES_H_
