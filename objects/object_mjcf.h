// Writing test objects as MJCF (tinyxml2): a standalone object file and two scenes per object.
//
//   <name>_object.xml  the object alone (convex pieces as mesh/cylinder geoms, or a height
//                      field); loads on its own in any MuJoCo viewer, and the scenes include it
//   <name>.xml         the object with the UR-10, F/T and cup (from scenes/disk_benchmark.xml)
//   <name>_gantry.xml  the object with the cup on the light gantry (disk_benchmark_gantry.xml)
//
// Scenes are made from the disk benchmark scenes: the disk is removed, the table lowered under
// the objects (they extend 50 mm below their top face, so holes are through-holes), the object
// file included, and model paths made absolute (the files live in the build tree).
#ifndef SSC_OBJECTS_OBJECT_MJCF_H_
#define SSC_OBJECTS_OBJECT_MJCF_H_

#include <string>

#include "objects/object_spec.h"

namespace ssc {

// Writes the object's three files into out_dir; false with *error naming the file on failure.
bool WriteObjectScenes(const ObjectSpec& spec, const std::string& out_dir,
                       const std::string& repo_dir, std::string* error);

// Writes every object of AllObjects(); returns how many, or -1 on error.
int WriteAllObjectScenes(const std::string& out_dir, const std::string& repo_dir,
                         std::string* error);

}  // namespace ssc

#endif  // SSC_OBJECTS_OBJECT_MJCF_H_
