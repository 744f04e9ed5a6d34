// `ssc compare` as one library call: load the log, place it in the scene, check that the cup
// reaches an object, replay, compare the controller's iterations and (optionally) run the closed
// loop, write the report.
#ifndef SSC_COMPARE_COMPARISON_H_
#define SSC_COMPARE_COMPARISON_H_

#include <functional>
#include <string>
#include <vector>

#include "compare/closed_loop.h"
#include "compare/report.h"
#include "runtime/rig.h"

namespace ssc {

struct CompareOptions {
  std::string log_path;
  std::string scene = RigTierFor(RigUse::kReplay).scene;  // replay scene (name or path)
  std::string loop_scene = DefaultScene();                // closed loop and the lip depth
  std::string out_dir = "out/compare";
  ProcessOptions processing;  // offset window, average, TCP offset
  LogFrame frame = LogFrame::kBaseLink;
  std::vector<double> object_pose;  // empty, or x, y, top z (m) [, yaw (deg)] in the log frame
  bool closed_loop = false;
  TrialConfig loop_config;    // defaults for what the file does not give
  bool override_law = false;  // the command line's P_ref, beta, dL win over the file's
  // Sees the fraction of the replay done, every 1 % (optional; ssc compare shows it on stderr).
  std::function<void(double)> progress;
};

struct CompareResult {
  ComparisonSetup setup;
  ReplayComparison replay;
  HistoryComparison history;
  std::string history_warning;            // why the history was not compared, if it exists
  std::vector<std::string> log_warnings;  // what the log reader kept quiet about otherwise
  ClosedLoopComparison closed;
};

// False with a message naming the file, the frame or the step that failed. A replay whose cup
// never comes within kCupReachM of any scene object is an error that names the closest approach
// and the frames in use.
bool RunComparison(const CompareOptions& options, CompareResult* result, std::string* error);

}  // namespace ssc

#endif  // SSC_COMPARE_COMPARISON_H_
