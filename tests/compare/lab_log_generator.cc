#include "lab_log_generator.h"

#include <filesystem>
#include <vector>

#include "robotlog/mat_log.h"
#include "robotlog/topic_csv.h"

namespace ssc::testing {

bool WriteLabForms(const TrialResult& trial, const TrialConfig& config,
                   const SceneObject& scene_disk, const LabSetup& setup,
                   const LogPerturbation& perturbation, const std::string& dir, LabForms* out,
                   std::string* error) {
  namespace fs = std::filesystem;
  out->log = LabLogFromTrial(trial, config, scene_disk, setup, perturbation);
  out->newer_dir = (fs::path(dir) / "newer").string();
  out->older_dir = (fs::path(dir) / "older").string();
  std::vector<std::string> files;
  if (!WriteTopicCsvRecording(out->newer_dir, out->log, LoggerVersion::kNewer, &files, error) ||
      !WriteTopicCsvRecording(out->older_dir, out->log, LoggerVersion::kOlder, nullptr, error)) {
    return false;
  }
  out->newer_file = files.front();
  // The saver's folder: SuctionExperiment/<yymmdd>/DataLog_<stamp>_<appendTxt>.mat
  const fs::path mat_dir = fs::path(dir) / "SuctionExperiment";
  fs::create_directories(mat_dir);
  out->mat_path =
      (mat_dir / DiskBenchmarkMatName(RecordingStamp(out->log.t0_ns), out->log.args)).string();
  return WriteRobotLogMat(out->mat_path, out->log, error, LoggerVersion::kNewer);
}

}  // namespace ssc::testing
