// Variants of the tool model, in memory, for calibration and simulator-cost studies: the pressure
// plugin's config keys set to given values, and the same cup with a different number of lip
// segments (same total lip stiffness, same ring radius).
//
// A scene is read once (ToolModelVariants::Read: the scene and every file it includes or
// attaches); each variant edits the tool's MJCF tree (tinyxml2) and compiles through MuJoCo's
// virtual file system and mjSpec (mj_parseXMLString, mj_compile): no file is read or written per
// variant, so an optimiser evaluation touches no disk. Why not mjs_setPluginAttributes on a
// parsed spec: it takes a std::map, and the MuJoCo wheel's library is built with libc++ (its
// std::map is not this build's libstdc++ one); a map passed across crashes inside MuJoCo.
#ifndef SSC_STUDIES_TOOL_VARIANTS_H_
#define SSC_STUDIES_TOOL_VARIANTS_H_

#include <map>
#include <memory>
#include <string>

#include "runtime/mujoco_model.h"

namespace ssc {

// The pressure plugin's config: key -> value as MJCF text (e.g. {"noise_pa", "0"}).
using PluginConfig = std::map<std::string, std::string>;

struct ToolVariant {
  PluginConfig config;   // set (added or replaced) in the ssc.chamber_pressure instance
  int lip_segments = 0;  // 0: as in the model; else 4..256, a multiple of 4
};

class ToolModelVariants {
 public:
  // Reads `scene_path` and the files it refers to (recursively). Null + *error when a file
  // cannot be read or no file holds the ssc.chamber_pressure plugin instance.
  static std::unique_ptr<ToolModelVariants> Read(const std::string& scene_path, std::string* error);
  // The scene with the variant tool, compiled in memory. Null + *error (compiler or plugin
  // message, e.g. a config value out of range) on failure.
  ModelPtr Compile(const ToolVariant& variant, std::string* error) const;
  // The tool model's MJCF text with the variant (e.g. to write a calibrated model).
  std::string ToolXml(const ToolVariant& variant, std::string* error) const;

 private:
  std::string label_;
  ModelTexts texts_;
  int tool_file_ = -1;  // index into texts_.files of the tool model; -1: the main file
};

// One variant of one scene (reads the scene's files once, then compiles).
ModelPtr ToolModelVariant(const std::string& scene_path, const PluginConfig& config,
                          std::string* error);

// The MJCF text `tool_xml` with `config` set in its ssc.chamber_pressure instance. Empty +
// *error when it holds no such instance.
std::string ToolXmlWithConfig(const std::string& tool_xml, const PluginConfig& config,
                              std::string* error);

// Rewrites the MJCF text of models/ssc_tool.xml (`tool_xml`) with `segments` lip segments
// (4..256, a multiple of 4 so each chamber gets the same share). Empty + *error on failure.
std::string ToolWithLipSegments(const std::string& tool_xml, int segments, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_TOOL_VARIANTS_H_
