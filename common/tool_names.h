// Names of the tool's parts in a compiled scene. models/ssc_tool.xml names its parts locally
// ("tool", "tool_site", "ft_force", "lip_0", the plugin instance "pressure", ...); every scene
// attaches it with a non-empty prefix, <attach model="ssc_tool" body="tool" prefix="ssc_"/>,
// so in the scene they read "ssc_tool", "ssc_tool_site", "ssc_ft_force", "ssc_lip_0",
// "ssc_pressure". (An empty prefix makes MuJoCo warn that the model may not save correctly.)
#ifndef SSC_COMMON_TOOL_NAMES_H_
#define SSC_COMMON_TOOL_NAMES_H_

namespace ssc {

inline constexpr const char* kToolAttachPrefix = "ssc_";       // <attach prefix=...>
inline constexpr const char* kToolAttachBody = "tool";         // <attach body=...>: the tool's root
inline constexpr const char* kToolSiteName = "ssc_tool_site";  // the lip plane's centre
inline constexpr const char* kToolForceSensorName = "ssc_ft_force";    // F/T force, N
inline constexpr const char* kToolTorqueSensorName = "ssc_ft_torque";  // F/T torque, N m

}  // namespace ssc

#endif  // SSC_COMMON_TOOL_NAMES_H_
