#include "runtime/mujoco_model.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

#include "common/input_file.h"
#include "plugin/chamber_pressure_config.h"

namespace ssc {
namespace {

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

// The folder of the binary that holds this code (the ssc executable, or the Python module).
std::filesystem::path ThisBinaryDir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&HasResources), &info) == 0 || info.dli_fname == nullptr) {
    return {};
  }
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::canonical(info.dli_fname, ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

std::string g_resource_dir;  // SetResourceDir

// Takes a compiled model; refuses (deletes it, null + *error prefixed by `label`) a bad time step
// or a plugin that rejects its config when data is made.
ModelPtr CheckedModel(mjModel* m, const std::string& label, std::string* error) {
  std::string step_warning;
  if (std::string e = CheckTimestep(m->opt.timestep, &step_warning); !e.empty()) {
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
    const std::filesystem::path bin = ThisBinaryDir();
    if (!bin.empty()) {
      // <prefix>/bin/ssc -> <prefix>/share/ssc; the Python package keeps them beside _core.
      for (const std::filesystem::path& dir : {bin.parent_path() / "share" / "ssc", bin}) {
        if (HasResources(dir)) return dir.lexically_normal().string();
      }
    }
    return std::string(SSC_SOURCE_DIR);
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
    *error = label + ": " + buffer;
    if (!warnings.empty() && error->find(warnings) == std::string::npos) {
      *error += " (" + warnings + ")";
    }
    return nullptr;
  }
  return CheckedModel(m, label, error);
}

ModelPtr LoadModel(const std::string& path, std::string* error) {
  InstallMuJoCoMessageHandlers();
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    *error = path + ": " + why;
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
    *error = path + ": " + buffer;
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
