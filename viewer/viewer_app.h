// ssc view: the twin in a window. MuJoCo's renderer, a mouse camera like MuJoCo's own viewer,
// the same trial controller (mjcb_control) as headless runs, live pressure plots and overlays.
#ifndef SSC_VIEWER_VIEWER_APP_H_
#define SSC_VIEWER_VIEWER_APP_H_

#include <functional>
#include <string>

#include "runtime/trial.h"

namespace ssc {

// The camera at the start (T cycles through them): the whole arm and the cup (a close-up in
// scenes without an arm), the cup alone close up and following it, or MuJoCo's free camera.
enum class ViewerCamera { kOverview, kCup, kFree };

struct ViewerOptions {
  std::string scene_path;
  TrialConfig config;      // the trial the controller runs
  std::string screenshot;  // non-empty: render off-screen after `time_s` and exit
  double time_s = 5.0;     // simulated seconds before the screenshot
  int width = 1280, height = 720;
  double speed = 1.0;  // simulated seconds per wall second (slow motion < 1)
  ViewerCamera camera = ViewerCamera::kOverview;
  // A test object: the overview frames the cup and the object, not the whole arm.
  bool frame_object = false;
  // Called once the display, the scene and the trial are known to work, before anything is
  // written: creates the output locations; returns 0 or the exit code (message printed).
  std::function<int()> create_outputs;
};

// Returns the process exit code (common/exit_codes.h). Without a display: one line on stderr
// and kExitFailed.
int RunViewer(const ViewerOptions& options);

}  // namespace ssc

#endif  // SSC_VIEWER_VIEWER_APP_H_
