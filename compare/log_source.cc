#include "compare/log_source.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "common/input_file.h"

namespace ssc {

const char* LogFormatName(LogFormat format) {
  switch (format) {
    case LogFormat::kTopicCsv:
      return "lab per-topic CSV recording";
    case LogFormat::kMat:
      return "lab DataLog .mat";
    case LogFormat::kPlain:
      break;
  }
  return "plain CSV";
}

bool DetectLogFormat(const std::string& path, LogFormat* format, LoadError* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    *error = {path, 0, 0, "no such file or folder"};
    return false;
  }
  if (fs::is_directory(path, ec)) {
    *format = LogFormat::kTopicCsv;
    return true;
  }
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    *error = {path, 0, 0, why};
    return false;
  }
  if (fs::path(path).extension() == ".mat") {
    *format = LogFormat::kMat;
    return true;
  }
  // A topic file starts with the logger's time column; read no more than that.
  std::ifstream f(path, std::ios::binary);
  char head[16] = {};
  f.read(head, 15);
  const std::string start(head, static_cast<size_t>(f.gcount()));
  const size_t bom = start.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  *format = start.compare(bom, 12, "ROStimestamp") == 0 ? LogFormat::kTopicCsv : LogFormat::kPlain;
  return true;
}

bool LoadLog(const std::string& path, const ProcessOptions& options, LoadedLog* out,
             LoadError* error) {
  *out = LoadedLog();
  if (!DetectLogFormat(path, &out->format, error)) return false;
  if (out->format == LogFormat::kPlain) return LoadPlainLog(path, &out->log, error);
  const bool loaded = out->format == LogFormat::kMat
                          ? LoadRobotLogMat(path, &out->raw, error)
                          : LoadTopicCsvRecording(path, &out->raw, error);
  ProcessOptions base = options;
  base.X_scene_base = Eigen::Isometry3d::Identity();
  return loaded && ProcessRobotLog(out->raw, base, &out->log, error);
}

}  // namespace ssc
