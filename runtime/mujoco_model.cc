#include "runtime/mujoco_model.h"

#include <dlfcn.h>
#include <mujoco/mjxmacro.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/input_file.h"
#include "common/scene_files.h"
#include "plugin/chamber_pressure_config.h"

namespace ssc {
namespace {

// MuJoCo passes tinyxml2's parse error on as it is ("XML parse error 14:\nError=XML_ERROR_
// MISMATCHED_ELEMENT ErrorID=14 (0xe) Line number=3: XMLElement name=body"). Said plainly:
// "line 3: malformed XML: a closing tag does not match the open element <body>". Other
// messages are returned unchanged.
std::string ReadableXmlError(const std::string& message) {
  const size_t at = message.find("Error=XML_ERROR_");
  if (at == std::string::npos) return message;
  size_t end = message.find_first_of(" \n", at);
  const std::string name = message.substr(at + 16, end == std::string::npos ? end : end - at - 16);
  std::string out = "malformed XML";
  if (const size_t line = message.find("Line number="); line != std::string::npos) {
    out = "line " + std::to_string(std::atoi(message.c_str() + line + 12)) + ": " + out;
  }
  std::string element;
  if (const size_t e = message.find("XMLElement name="); e != std::string::npos) {
    element = message.substr(e + 16);
    if (const size_t cut = element.find_first_of(" \n"); cut != std::string::npos) {
      element.resize(cut);
    }
  }
  static const std::pair<const char*, const char*> kPlain[] = {
      {"MISMATCHED_ELEMENT", "a closing tag does not match the open element"},
      {"PARSING_ELEMENT", "cannot read the element"},
      {"PARSING_ATTRIBUTE", "cannot read an attribute of the element"},
      {"PARSING_TEXT", "cannot read the text"},
      {"PARSING_COMMENT", "an unfinished comment"},
      {"EMPTY_DOCUMENT", "the file holds no XML"},
      {"PARSING", "cannot read the file as XML"},
  };
  std::string what = name;  // an unknown code keeps tinyxml2's name
  for (const auto& [code, plain] : kPlain) {
    if (name == code) what = plain;
  }
  out += ": " + what;
  if (!element.empty()) out += " <" + element + ">";
  return out;
}

// MuJoCo reports plugin init failures through mju_warning; capture them while loading.
std::mutex g_warning_mutex;
std::string* g_captured = nullptr;
void (*g_previous_warning)(const char*) = nullptr;

void CaptureWarning(const char* msg) {
  if (g_captured) {
    if (!g_captured->empty()) *g_captured += "; ";
    *g_captured += msg;
  } else if (g_previous_warning) {
    g_previous_warning(msg);
  }
}

class WarningCapture {
 public:
  explicit WarningCapture(std::string* sink) : lock_(g_warning_mutex) {
    g_previous_warning = mju_user_warning;
    g_captured = sink;
    mju_user_warning = CaptureWarning;
  }
  ~WarningCapture() {
    mju_user_warning = g_previous_warning;
    g_captured = nullptr;
  }

 private:
  std::lock_guard<std::mutex> lock_;
};

// Looks, never opens: opening a FIFO for reading would block.
bool FileExists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

bool HasResources(const std::filesystem::path& dir) {
  return FileExists((dir / "models" / "ssc_tool.xml").string());
}

// The folder of the binary or shared library that holds `symbol`.
std::filesystem::path FolderOf(const void* symbol) {
  Dl_info info{};
  if (dladdr(symbol, &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::canonical(info.dli_fname, ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

// Where an installed copy keeps models/ and scenes/, from the binary that holds this code (the
// ssc executable, a downstream program installed into the prefix, or the Python module, which
// keeps them beside itself), then from the plugin library the process loaded (a downstream
// program linked against an installed prefix but run from its own build folder:
// <prefix>/lib/libssc_plugin.so -> <prefix>/share/ssc). Empty when neither has them.
std::string InstalledResourceDir() {
  const std::filesystem::path bin = FolderOf(reinterpret_cast<const void*>(&HasResources));
  const std::filesystem::path plugin =
      FolderOf(reinterpret_cast<const void*>(&InstallMuJoCoMessageHandlers));
  std::vector<std::filesystem::path> candidates;
  if (!bin.empty()) {
    candidates.push_back(bin.parent_path() / "share" / "ssc");
    candidates.push_back(bin);
  }
  if (!plugin.empty()) candidates.push_back(plugin.parent_path() / "share" / "ssc");
  for (const std::filesystem::path& dir : candidates) {
    if (HasResources(dir)) return dir.lexically_normal().string();
  }
  return "";
}

std::string g_resource_dir;  // SetResourceDir

// Takes a compiled model; refuses (deletes it, null + *error prefixed by `label`) a bad time step
// or a plugin that rejects its config when data is made.
// Every file a scene names (common/scene_files.h): one that exists but is not a regular file (a
// FIFO would block MuJoCo's reader forever, a device never end) is refused naming the scene
// line. Missing files are left to MuJoCo's own message.
std::string CheckSceneFiles(const std::filesystem::path& main_file) {
  return WalkSceneFiles(main_file, [](const SceneFileRef& ref) {
    for (const std::filesystem::path& place : ref.found) {
      if (const std::string why = CheckInputFile(place.string()); !why.empty()) {
        return ref.from.string() + ":" + std::to_string(ref.line) + ": <" + ref.tag + " file=\"" +
               ref.name.string() + "\">: " + place.string() + " " + why;
      }
    }
    return std::string();
  });
}

// The element kind whose count sizes an mjModel array ("nbody" -> body).
mjtObj ElementKind(const char* rows) {
  static const std::pair<const char*, mjtObj> kinds[] = {
      {"nbody", mjOBJ_BODY},       {"njnt", mjOBJ_JOINT},     {"ngeom", mjOBJ_GEOM},
      {"nsite", mjOBJ_SITE},       {"ncam", mjOBJ_CAMERA},    {"nlight", mjOBJ_LIGHT},
      {"nmesh", mjOBJ_MESH},       {"nhfield", mjOBJ_HFIELD}, {"ntex", mjOBJ_TEXTURE},
      {"nmat", mjOBJ_MATERIAL},    {"npair", mjOBJ_PAIR},     {"neq", mjOBJ_EQUALITY},
      {"ntendon", mjOBJ_TENDON},   {"nu", mjOBJ_ACTUATOR},    {"nsensor", mjOBJ_SENSOR},
      {"nnumeric", mjOBJ_NUMERIC}, {"nkey", mjOBJ_KEY},       {"nflex", mjOBJ_FLEX}};
  for (const auto& [count_name, type] : kinds) {
    if (std::strcmp(rows, count_name) == 0) return type;
  }
  return mjOBJ_UNKNOWN;
}

// The first non-finite number of the compiled model (a NaN or inf typed into the scene, which
// MuJoCo's parser accepts), naming the element: "" when there is none.
template <typename T>
std::string NonFiniteIn(const mjModel* m, const char* field, const char* rows, const T* values,
                        long count, long columns, bool named_only) {
  if constexpr (std::is_floating_point_v<T>) {
    // First pass: the arrays of named elements (what the scene says); second: derived ones.
    if (named_only != (std::strcmp(rows, "nv") == 0 || ElementKind(rows) != mjOBJ_UNKNOWN)) {
      return "";
    }
    for (long i = 0; i < count; ++i) {
      if (std::isfinite(static_cast<double>(values[i]))) continue;
      const long row = columns > 0 ? i / columns : 0;
      std::string element = std::string(rows) + " index " + std::to_string(row);
      if (const mjtObj type = ElementKind(rows); type != mjOBJ_UNKNOWN) {
        const char* name = mj_id2name(m, type, static_cast<int>(row));
        element = std::string(mju_type2Str(type)) + " " +
                  (name != nullptr && name[0] ? "'" + std::string(name) + "'"
                                              : "#" + std::to_string(row) + " (unnamed)");
      }
      if (std::strcmp(rows, "nv") == 0 && row < m->nv) {
        const char* name = mj_id2name(m, mjOBJ_JOINT, m->dof_jntid[row]);
        element =
            "joint '" + std::string(name ? name : "?") + "' (dof " + std::to_string(row) + ")";
      }
      char value[32];
      std::snprintf(value, sizeof(value), "%g", static_cast<double>(values[i]));
      return element + ": " + field + " holds " + value +
             " (a NaN or inf in the scene, or a value that overflows)";
    }
  }
  return "";
}

std::string FindNonFiniteModelValue(const mjModel* m) {
  std::string found;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"  // MuJoCo's preamble copies sizes into ints
  MJMODEL_POINTERS_PREAMBLE(m)
#pragma GCC diagnostic pop
  for (const bool named_only : {true, false}) {
#define X(type, name, nr, nc)                                                                     \
  if (found.empty()) {                                                                            \
    found = NonFiniteIn(m, #name, #nr, m->name, static_cast<long>(m->nr) * (nc), nc, named_only); \
  }
#define XNV X
    MJMODEL_POINTERS
#undef XNV
#undef X
  }
#define X(type, name, n)                                                                           \
  if (found.empty()) {                                                                             \
    found = NonFiniteIn(m, "option " #name, "", reinterpret_cast<const type*>(&m->opt.name), n, 0, \
                        false);                                                                    \
  }
#define XVEC X
  MJOPTION_FIELDS
#undef XVEC
#undef X
      (void)
  nuser_body;
  return found;
}

ModelPtr CheckedModel(mjModel* m, const std::string& label, std::string* error) {
  std::string step_warning;
  if (std::string e = CheckTimestep(m->opt.timestep, &step_warning); !e.empty()) {
    mj_deleteModel(m);
    *error = label + ": " + e;
    return nullptr;
  }
  if (std::string e = FindNonFiniteModelValue(m); !e.empty()) {
    mj_deleteModel(m);
    *error = label + ": " + e;
    return nullptr;
  }
  if (!step_warning.empty()) {
    std::fprintf(stderr, "warning: %s: %s\n", label.c_str(), step_warning.c_str());
  }
  std::string data_error;
  DataPtr probe = MakeData(m, &data_error);
  if (!probe) {
    mj_deleteModel(m);
    *error = label + ": " + data_error;
    return nullptr;
  }
  return ModelPtr(m);
}

// Compiles a parsed scene (joint removals first); null with *error (the compiler's message).
mjModel* CompileSpec(mjSpec* spec, const mjVFS* vfs, std::string* error) {
  if (!RemoveListedJoints(spec, error)) return nullptr;
  mjModel* m = mj_compile(spec, vfs);
  if (m == nullptr) *error = mjs_getError(spec);
  return m;
}

}  // namespace

bool RemoveListedJoints(mjSpec* spec, std::string* error) {
  mjsElement* listed = mjs_findElement(spec, mjOBJ_TEXT, kRemoveJointsText);
  if (listed == nullptr) return true;
  std::istringstream names(mjs_getString(mjs_asText(listed)->data));
  std::vector<std::string> removed;
  for (std::string name; names >> name;) {
    mjsElement* joint = mjs_findElement(spec, mjOBJ_JOINT, name.c_str());
    if (joint == nullptr) {
      *error = std::string("<custom><text name=\"") + kRemoveJointsText + "\"> names joint '" +
               name + "', which the model does not have";
      return false;
    }
    mjs_delete(spec, joint);
    removed.push_back(name);
  }
  auto is_removed = [&removed](const mjString* name) {
    const char* n = mjs_getString(name);
    for (const std::string& r : removed)
      if (r == n) return true;
    return false;
  };
  for (mjsElement* e = mjs_firstElement(spec, mjOBJ_EQUALITY); e;) {
    mjsElement* next = mjs_nextElement(spec, e);
    const mjsEquality* eq = mjs_asEquality(e);
    if (eq->type == mjEQ_JOINT && (is_removed(eq->name1) || is_removed(eq->name2))) {
      mjs_delete(spec, e);
    }
    e = next;
  }
  return true;
}

std::string CheckMuJoCoVersion() {
  if (mj_version() != mjVERSION_HEADER) {
    std::ostringstream os;
    os << "MuJoCo library version " << mj_versionString() << " (" << mj_version()
       << ") does not match the headers this program was built with (" << mjVERSION_HEADER
       << "); the project pins mujoco==" << SSC_MUJOCO_PINNED << ". Rebuild with tools/setup.sh.";
    return os.str();
  }
  return "";
}

void SetResourceDir(const std::string& dir) { g_resource_dir = dir; }

std::string ResourceDir() {
  if (!g_resource_dir.empty()) return g_resource_dir;
  for (const char* var : {"SSC_RESOURCE_DIR", "SSC_SOURCE_DIR"}) {
    const char* env = std::getenv(var);
    if (env && env[0]) return env;
  }
  static const std::string found = [] {
    const std::string installed = InstalledResourceDir();
    return installed.empty() ? std::string(SSC_SOURCE_DIR) : installed;
  }();
  return found;
}

std::string SourceDir() { return ResourceDir(); }

std::string ResolveScenePath(const std::string& scene) {
  // Absolute: MuJoCo 4.0 mis-resolves a model asset's relative path inside an <include> of a
  // relatively named main file ("scenes/x.xml" + "../models/..." loses the "..").
  if (FileExists(scene)) return std::filesystem::absolute(scene).lexically_normal().string();
  const std::string dir = ResourceDir() + "/scenes/";
  if (FileExists(dir + scene)) return dir + scene;
  if (FileExists(dir + scene + ".xml")) return dir + scene + ".xml";
  return scene;
}

ModelPtr LoadModelFromTexts(const ModelTexts& texts, const std::string& label, std::string* error) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  for (const auto& [name, text] : texts.files) {  // a repeated name keeps its first text
    mj_addBufferVFS(&vfs, name.c_str(), text.data(), static_cast<int>(text.size()));
  }
  char buffer[2048] = "";
  std::string warnings;
  mjModel* m = nullptr;
  {
    WarningCapture capture(&warnings);  // (also keeps MuJoCo from writing MUJOCO_LOG.TXT)
    mjSpec* spec = mj_parseXMLString(texts.main_xml.c_str(), &vfs, buffer, sizeof(buffer));
    if (spec != nullptr) {
      std::string compile_error;
      m = CompileSpec(spec, &vfs, &compile_error);
      if (m == nullptr) std::snprintf(buffer, sizeof(buffer), "%s", compile_error.c_str());
      mj_deleteSpec(spec);
    }
  }
  mj_deleteVFS(&vfs);
  if (m == nullptr) {
    *error = label + ": " + ReadableXmlError(buffer);
    if (!warnings.empty() && error->find(warnings) == std::string::npos) {
      *error += " (" + warnings + ")";
    }
    return nullptr;
  }
  return CheckedModel(m, label, error);
}

std::string CheckScenePath(const std::string& path) {
  const std::string why = CheckInputFile(path);
  if (why.empty()) return "";
  // A bare name ResolveScenePath could not find: say where scenes were looked for.
  if (path.find('/') == std::string::npos) {
    return path + ": " + why + " here or in " + ResourceDir() +
           "/scenes (SSC_RESOURCE_DIR names the folder that holds models/ and scenes/)";
  }
  return path + ": " + why;
}

ModelPtr LoadModel(const std::string& path, std::string* error) {
  InstallMuJoCoMessageHandlers();
  if (std::string e = CheckScenePath(path); !e.empty()) {
    *error = e;
    return nullptr;
  }
  if (std::string e = CheckSceneFiles(path); !e.empty()) {
    *error = e;
    return nullptr;
  }
  // MuJoCo passes value="" to plugins as if the key were absent (silently the default).
  if (std::string e = FindEmptyConfigValues(path); !e.empty()) {
    *error = e;
    return nullptr;
  }
  char buffer[2048] = "";
  std::string warnings;
  mjModel* m = nullptr;
  {
    WarningCapture capture(&warnings);
    mjSpec* spec = mj_parseXML(path.c_str(), nullptr, buffer, sizeof(buffer));
    if (spec != nullptr) {
      std::string compile_error;
      m = CompileSpec(spec, nullptr, &compile_error);
      if (m == nullptr) std::snprintf(buffer, sizeof(buffer), "%s", compile_error.c_str());
      mj_deleteSpec(spec);
    }
  }
  if (m == nullptr) {
    *error = path + ": " + ReadableXmlError(buffer);
    if (!warnings.empty()) *error += " (" + warnings + ")";
    return nullptr;
  }
  return CheckedModel(m, path, error);
}

std::string CheckTimestep(double timestep_s, std::string* warning) {
  char buf[320];
  if (!std::isfinite(timestep_s) || timestep_s <= 0) {
    std::snprintf(buf, sizeof(buf),
                  "time step %g s must be > 0 (<option timestep=...>; tested "
                  "stable up to %g ms, docs/stability.md)",
                  timestep_s, kLargestTestedTimestepS * 1e3);
    return buf;
  }
  if (timestep_s < kSmallestTimestepS) {
    std::snprintf(buf, sizeof(buf),
                  "time step %g ms is below %g ms, the smallest accepted (<option "
                  "timestep=...>): a 10 s trial would take %.3g steps; results are unchanged "
                  "from 0.5 ms down (docs/stability.md)",
                  timestep_s * 1e3, kSmallestTimestepS * 1e3, 10 / timestep_s);
    return buf;
  }
  if (warning && timestep_s > kLargestTestedTimestepS * (1 + 1e-9)) {
    std::snprintf(buf, sizeof(buf),
                  "time step %g ms is above %g ms, the largest the stability "
                  "study found unchanged (docs/stability.md); results may be wrong",
                  timestep_s * 1e3, kLargestTestedTimestepS * 1e3);
    *warning = buf;
  }
  return "";
}

DataPtr MakeData(const mjModel* m, std::string* error) {
  std::string warnings;
  mjData* d = nullptr;
  {
    WarningCapture capture(&warnings);
    d = mj_makeData(m);
  }
  if (d == nullptr) {
    *error = warnings.empty() ? "mj_makeData failed" : warnings;
    return nullptr;
  }
  return DataPtr(d);
}

}  // namespace ssc
