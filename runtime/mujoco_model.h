// Loading MuJoCo models with clear errors, and the start-up version check.
#ifndef SSC_RUNTIME_MUJOCO_MODEL_H_
#define SSC_RUNTIME_MUJOCO_MODEL_H_

#include <memory>
#include <string>

#include <mujoco/mujoco.h>

namespace ssc {

// Empty when the linked libmujoco matches the headers compiled against; otherwise a message.
std::string CheckMuJoCoVersion();

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

// Loads an MJCF file. On failure returns null and sets *error to "<path>: <compiler message>".
// MuJoCo warnings raised while making data (e.g. a plugin rejecting its config) are captured and
// reported the same way instead of being printed.
ModelPtr LoadModel(const std::string& path, std::string* error);

// The stability study (docs/stability.md): results unchanged up to 8 ms with every integrator,
// unstable at 16 ms.
inline constexpr double kLargestTestedTimestepS = 0.008;

// A model's time step: "" when usable; else why not (0, negative or not finite would never
// advance time). Above kLargestTestedTimestepS *warning (if given) says so and names the limit.
std::string CheckTimestep(double timestep_s, std::string* warning);

// Makes mjData for a model, capturing plugin init failures into *error.
DataPtr MakeData(const mjModel* m, std::string* error);

// Resolves a scene argument: an existing path, or a name under <repo>/scenes (with or without
// ".xml").
std::string ResolveScenePath(const std::string& scene);

// Repository root (compile-time SSC_SOURCE_DIR, overridable by the SSC_SOURCE_DIR variable).
std::string SourceDir();

// The text of models/ssc_tool.xml with `config_xml` (e.g. <config key="noise_pa" value="0"/>)
// inside its pressure-plugin instance; empty (and *error set) when the model cannot be read.
std::string ToolModelWithConfig(const std::string& config_xml, std::string* error);

// Writes a copy of `scene_path` into dir/scenes/ and the tool model with `config_xml` into
// dir/models/ (scenes refer to ../models/ssc_tool.xml); returns the new scene's path.
std::string SceneWithToolConfig(const std::string& scene_path, const std::string& dir,
                                const std::string& config_xml, std::string* error);

}  // namespace ssc

#endif  // SSC_RUNTIME_MUJOCO_MODEL_H_
