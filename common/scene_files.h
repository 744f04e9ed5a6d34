// The files an MJCF scene pulls in, found by reading its text (no MuJoCo, nothing compiled): every
// file=... attribute (<include>, <model>, <mesh>, <texture>, <hfield>, <skin>), recursively
// through the XML files it includes or attaches. Header-only, for the checks that read a scene
// before MuJoCo does and for fingerprints of what a scene's results depend on.
#ifndef SSC_COMMON_SCENE_FILES_H_
#define SSC_COMMON_SCENE_FILES_H_

#include <algorithm>
#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "common/xml_text.h"

namespace ssc {

struct SceneFileRef {
  std::filesystem::path from;  // the file that names it
  long line = 0;               // 1-based, in `from`
  std::string tag;             // include, model, mesh, texture, hfield, skin, ...
  std::filesystem::path name;  // as written
  // The places MuJoCo may read it from that exist, most likely first: the main file's folder,
  // the <compiler> meshdir/texturedir/assetdir there (assets), the naming file's folder.
  std::vector<std::filesystem::path> found;
};

// Calls `visit` for every file reference of `main_file`, depth first, and walks on into the
// XML files an <include> or <model> names (each existing place that is a regular file). A
// non-empty string from `visit` stops the walk and is returned; so is nesting deeper than 16
// files. A file that cannot be read is skipped (left to MuJoCo's own message).
inline std::string WalkSceneFiles(const std::filesystem::path& main_file,
                                  const std::function<std::string(const SceneFileRef&)>& visit) {
  namespace fs = std::filesystem;
  std::vector<fs::path> asset_dirs;  // <compiler> meshdir/texturedir/assetdir, seen so far
  std::function<std::string(const fs::path&, int)> walk = [&](const fs::path& file, int depth) {
    if (depth > 16) return file.string() + ": includes nested deeper than 16 files";
    std::string text;
    ReadXmlWithoutComments(file, &text);
    static const std::regex dir_attr(
        R"(<compiler\b[^>]*?\b(?:meshdir|texturedir|assetdir)\s*=\s*["']([^"']+)["'])");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), dir_attr);
         it != std::sregex_iterator(); ++it) {
      asset_dirs.push_back((*it)[1].str());
    }
    static const std::regex file_attr(R"(<(\w+)\b[^>]*?\bfile\s*=\s*["']([^"']+)["'])");
    const fs::path main_dir = main_file.parent_path();
    for (auto it = std::sregex_iterator(text.begin(), text.end(), file_attr);
         it != std::sregex_iterator(); ++it) {
      SceneFileRef ref;
      ref.from = file;
      ref.line = 1 + std::count(text.begin(), text.begin() + it->position(), '\n');
      ref.tag = (*it)[1].str();
      ref.name = (*it)[2].str();
      std::vector<fs::path> candidates;
      if (ref.name.is_absolute()) {
        candidates.push_back(ref.name);
      } else {
        candidates.push_back(main_dir / ref.name);
        if (ref.tag != "include" && ref.tag != "model") {
          for (const fs::path& dir : asset_dirs) {
            candidates.push_back((dir.is_absolute() ? dir : main_dir / dir) / ref.name);
          }
        }
        candidates.push_back(file.parent_path() / ref.name);
      }
      std::error_code ec;
      for (const fs::path& c : candidates) {
        const fs::path normal = c.lexically_normal();
        if (fs::exists(normal, ec) &&
            std::find(ref.found.begin(), ref.found.end(), normal) == ref.found.end()) {
          ref.found.push_back(normal);
        }
      }
      if (std::string e = visit(ref); !e.empty()) return e;
      if (ref.tag != "include" && ref.tag != "model") continue;
      for (const fs::path& next : ref.found) {
        if (next.extension() != ".xml" || !fs::is_regular_file(next, ec)) continue;
        if (std::string e = walk(next, depth + 1); !e.empty()) return e;
      }
    }
    return std::string();
  };
  return walk(main_file, 0);
}

}  // namespace ssc

#endif  // SSC_COMMON_SCENE_FILES_H_
