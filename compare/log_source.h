// Picking a log's format and loading it: the lab's per-topic CSV recording (a folder or any of
// its files), the lab's DataLog .mat, or the plain CSV for other robots (docs/robot_logs.md).
#ifndef SSC_COMPARE_LOG_SOURCE_H_
#define SSC_COMPARE_LOG_SOURCE_H_

#include <string>

#include "robotlog/robot_log.h"

namespace ssc {

enum class LogFormat { kTopicCsv, kMat, kPlain };
const char* LogFormatName(LogFormat format);

// A folder, a .mat file, a .csv whose first line starts with ROStimestamp (one topic file of a
// recording) or any other .csv (the plain format).
bool DetectLogFormat(const std::string& path, LogFormat* format, LoadError* error);

struct LoadedLog {
  LogFormat format = LogFormat::kPlain;
  RobotLog raw;      // the lab formats: as recorded (with the script's arguments for a .mat)
  ProcessedLog log;  // lab formats: in the log's base frame; plain: already in the scene frame
};

// Loads and processes (ProcessRobotLog with `options`, whose X_scene_base is ignored: the frame
// is set afterwards, compare/frames.h).
bool LoadLog(const std::string& path, const ProcessOptions& options, LoadedLog* out,
             LoadError* error);

}  // namespace ssc

#endif  // SSC_COMPARE_LOG_SOURCE_H_
