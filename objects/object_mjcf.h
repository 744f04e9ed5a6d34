// Writing test objects as MJCF (tinyxml2). Per object, into one directory:
//
//   <name>.xml         the object alone: a static body at W holding its convex pieces (boxes,
//                      cylinders, meshes given by their vertices); loads on its own in MuJoCo
//   <name>_arm.xml     the UR-10 scene: the rig's arm template (arm, F/T, cup, table, light,
//                      `home` keyframe) with its disk replaced by the object
//   <name>_gantry.xml  the same from the gantry template (the cup on a gantry)
//   <name>_flex.xml    the same from the flex template (the gantry with the flex skirt lip)
//   <name>_probe.xml   the cup on a mocap body "probe" over the object (table, light): for
//                      kinematic probing and the per-scene step cost
//
// Scenes include the object file by name and the repository's models by paths relative to the
// output directory, so the output is the same bytes wherever the tree is checked out.
#ifndef SSC_OBJECTS_OBJECT_MJCF_H_
#define SSC_OBJECTS_OBJECT_MJCF_H_

#include <string>

#include "objects/object_spec.h"

namespace ssc {

// The scenes (names under the repository's scenes/) an object's UR-10, gantry and flex scenes
// are made from, their disk replaced by the object (runtime/rig.h names them).
struct ObjectSceneTemplates {
  std::string arm, gantry, flex;
};

struct ObjectFiles {
  // File names, no directory: the object, its scenes (the UR-10, the gantry with the segment lip,
  // the gantry with the flex skirt lip) and its probe scene.
  std::string object, arm_scene, gantry_scene, flex_scene, probe_scene;
};
ObjectFiles ObjectFileNames(const std::string& object_name);

// Writes the object's four files into out_dir (created if missing); `repo_dir` holds models/
// and scenes/ (SourceDir() for the repository). False with *error naming the file on failure.
bool WriteObjectFiles(const ObjectSpec& spec, const std::string& out_dir,
                      const std::string& repo_dir, const ObjectSceneTemplates& templates,
                      std::string* error);

// Writes the files of every object of AllObjects() into out_dir (e.g. build/scenes/objects/);
// returns how many objects, or -1 with *error set.
int WriteAllObjectScenes(const std::string& out_dir, const std::string& repo_dir,
                         const ObjectSceneTemplates& templates, std::string* error);

}  // namespace ssc

#endif  // SSC_OBJECTS_OBJECT_MJCF_H_
