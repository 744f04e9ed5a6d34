// The comparison's report files: report.md (for people), report.json (nlohmann-json), the
// sample series (series.csv) and, with a history, the iteration table (history.csv).
#ifndef SSC_COMPARE_REPORT_H_
#define SSC_COMPARE_REPORT_H_

#include <string>

#include "compare/closed_loop.h"
#include "compare/frames.h"
#include "compare/replay.h"

namespace ssc {

// What the log was and how it was placed in the scene.
struct ComparisonSetup {
  std::string log_path;
  std::string format;
  std::string log_frame;  // "base_link", "base", or "scene" (plain CSV)
  ObjectPose object;      // in the log's base frame (known = false: none)
  SceneObject scene_object;
  Eigen::Isometry3d X_scene_log = Eigen::Isometry3d::Identity();
  Reach reach;
  double contact_depth_m = 0;
};

bool WriteComparisonReport(const std::string& dir, const ComparisonSetup& setup,
                           const ReplayComparison& replay, const HistoryComparison* history,
                           const ClosedLoopComparison* closed, std::string* error);

}  // namespace ssc

#endif  // SSC_COMPARE_REPORT_H_
