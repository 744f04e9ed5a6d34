// Frames between a robot log and a replay scene (docs/robot_logs.md, "Frames"):
//
//   log base frame --(X_scene_log)--> scene (world) frame
//
// The lab's poses are tool0 in base_link, the UR "Base" frame turned 180 deg about z; the scenes
// put the UR Base frame at the world origin. With an object pose in the log's base frame (from
// the log, or --object-pose), the log is moved so that this object lands on the scene's object:
// X_scene_log(p) = R (p - p_object) + p_scene_object, R = Rz(-yaw) R_base, where R_base turns
// the log's base frame into the UR Base frame. Without one, X_scene_log = R_base.
#ifndef SSC_COMPARE_FRAMES_H_
#define SSC_COMPARE_FRAMES_H_

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "compare/log_source.h"
#include "geometry/dimensions.h"

namespace ssc {

// The frame a lab log's poses are given in.
enum class LogFrame {
  kBaseLink,  // ROS base_link (the lab's tf): the UR Base frame turned 180 deg about z
  kUrBase,    // the UR controller's Base frame (RTDE), the scenes' world orientation
};
// "base_link" or "base"; false for anything else.
bool ParseLogFrame(const std::string& name, LogFrame* frame);
const char* LogFrameName(LogFrame frame);

// The disk benchmark's set-up in the lab (../shared/reference/lab-logs.md): the 35 mm disk's
// engage point (its centre, the cup above it) in base_link, m.
inline constexpr double kLabDiskCentreX = -0.630, kLabDiskCentreY = 0.097;
inline constexpr double kLabDiskEngageZ = 0.015;

// An object in the log's base frame: its centre, its top surface and its turn about z.
struct ObjectPose {
  bool known = false;
  double x_m = 0, y_m = 0, top_z_m = 0, yaw_rad = 0;
  double radius_m = std::numeric_limits<double>::quiet_NaN();  // a disk's, when the log has it
  std::string source;                                          // where it came from
  std::string note;  // a consistency remark (e.g. the start offset checked against the log)
};

// An object of the replay scene: a static geom the cup can touch (not a plane).
struct SceneObject {
  std::string name;
  int geom = -1;
  double x_m = 0, y_m = 0, top_z_m = 0;
  double radius_m = std::numeric_limits<double>::quiet_NaN();  // cylinders (disks)
  std::array<double, 2> half_size_m{};                         // its x, y extent (bounding box)
};
std::vector<SceneObject> FindSceneObjects(const mjModel* m);

// The disk benchmark's object from a lab recording: its centre is where the recording starts
// (the script starts logging with the cup above the disk's centre), its top the lowest steady
// TCP height (the cup held at the force band while following) plus `contact_depth_m`, how far
// the twin's lip plane sits below a surface at that force. `log` in the log's base frame.
ObjectPose DiskPoseFromLog(const LoadedLog& log, double contact_depth_m);

// The transform above; `scene_object` is used only when `object.known`.
Eigen::Isometry3d SceneFromLog(LogFrame frame, const ObjectPose& object,
                               const SceneObject& scene_object);

// The scene object nearest to where `object` lands without the object alignment (R_base only).
const SceneObject* NearestSceneObject(const std::vector<SceneObject>& objects, LogFrame frame,
                                      const ObjectPose& object);

// The cup can reach an object when its tool centre comes within the cup's outer radius of it.
inline constexpr double kCupReachM = 0.5e-3 * kCupBodyDiameterMm;

struct Reach {
  double closest_m = std::numeric_limits<double>::infinity();
  double t_s = 0;
  std::array<double, 3> tcp_m{};
  std::string object;
};
// The closest approach of the logged tool centre (scene frame) to any of `objects`.
Reach ClosestApproach(const mjModel* m, const std::vector<SceneObject>& objects,
                      const ProcessedLog& scene_log);

}  // namespace ssc

#endif  // SSC_COMPARE_FRAMES_H_
