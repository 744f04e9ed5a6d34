// Loading MuJoCo models with clear errors, and the start-up version check.
#ifndef SSC_RUNTIME_MUJOCO_MODEL_H_
#define SSC_RUNTIME_MUJOCO_MODEL_H_

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "plugin/mujoco_messages.h"

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

// A scene may leave joints of the models it attaches out: <custom><text name="ssc_remove_joints"
// data="joint names, space separated"/></custom>. LoadModel and LoadModelFromTexts then compile it
// without those joints and without the joint equality constraints on them (e.g. the light
// scene's rigid lip carrier; docs/scenes.md). A name the model does not have is an error.
inline constexpr char kRemoveJointsText[] = "ssc_remove_joints";
// Applies that list to a parsed scene (for code that compiles an mjSpec itself). False + *error
// when a named joint does not exist.
bool RemoveListedJoints(mjSpec* spec, std::string* error);

// Loads an MJCF file. On failure returns null and sets *error to "<path>: <compiler message>".
// MuJoCo warnings raised while making data (e.g. a plugin rejecting its config) are captured and
// reported the same way instead of being printed.
ModelPtr LoadModel(const std::string& path, std::string* error);

// "" when `path` (from ResolveScenePath) is a readable regular file, else the message LoadModel
// gives: the path, what it is instead and, for a bare name found nowhere, where scenes were
// looked for. For readers of a scene other than LoadModel (tool variants).
std::string CheckScenePath(const std::string& path);

// The stability study (docs/stability.md): results unchanged up to 8 ms with every integrator,
// unstable at 16 ms.
inline constexpr double kLargestTestedTimestepS = 0.008;
// The smallest time step accepted: 10x below the study's 0.5 ms reference. Smaller steps change
// nothing but the cost (a 10 s trial at 1e-9 s would take 10^10 steps: a hang in practice).
inline constexpr double kSmallestTimestepS = 5e-5;

// A model's time step: "" when usable; else why not (0, negative or not finite would never
// advance time; below kSmallestTimestepS a run takes hours). Above kLargestTestedTimestepS
// *warning (if given) says so and names the limit.
std::string CheckTimestep(double timestep_s, std::string* warning);

// Makes mjData for a model, capturing plugin init failures into *error.
DataPtr MakeData(const mjModel* m, std::string* error);

// Resolves a scene argument: an existing path, or a name under <repo>/scenes (with or without
// ".xml").
std::string ResolveScenePath(const std::string& scene);

// The folder holding models/ and scenes/: SetResourceDir, else $SSC_RESOURCE_DIR (or
// $SSC_SOURCE_DIR) when set, else <prefix>/share/ssc beside an installed binary, or the Python
// package's folder, else <prefix>/share/ssc beside the plugin library the process loaded (a
// program built against an installed prefix, not installed itself), else the source tree this
// was built from (SSC_SOURCE_DIR at compile time).
std::string ResourceDir();
// Overrides all of the above (a program that knows where its models are; empty: look them up).
void SetResourceDir(const std::string& dir);
std::string SourceDir();  // the older name of ResourceDir()

// InstallMuJoCoMessageHandlers (plugin/mujoco_messages.h): LoadModel calls it too.

// MJCF texts held in memory: the main file's text, and every file it includes or attaches under
// the name it is referred to by (e.g. "../models/ssc_tool.xml").
struct ModelTexts {
  std::string main_xml;
  std::vector<std::pair<std::string, std::string>> files;  // name as referred to -> text
};

// Compiles a model from texts in memory (MuJoCo's virtual file system, mj_parseXMLString,
// mj_compile): no file is read or written. Errors as LoadModel's, prefixed by `label`.
ModelPtr LoadModelFromTexts(const ModelTexts& texts, const std::string& label, std::string* error);

}  // namespace ssc

#endif  // SSC_RUNTIME_MUJOCO_MODEL_H_
