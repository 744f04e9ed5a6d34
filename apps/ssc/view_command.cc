// ssc view: the interactive viewer, or an off-screen screenshot.
#include <cstdio>
#include <filesystem>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/trial_options.h"
#include "common/exit_codes.h"
#include "objects/object_mjcf.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/object_trials.h"
#include "viewer/viewer_app.h"

namespace ssc {

int RunViewCommand(int argc, char** argv) {
  cli::Command cmd(
      "view",
      "ssc view [SCENE | --scene SCENE] [options]: the twin in a window with the trial controller "
      "running\n"
      "(the same mjcb_control callback as headless trials: same seed, same trajectory).\n"
      "SCENE: a name under scenes/ (default " +
          std::string(DefaultScene()) +
          "), a path, or a test object by\n"
          "name (disk_d10, hole_d06, corner_a090, volute, semicircle_strip, fillet, ...).");
  ViewerOptions v;
  TrialSettings settings;
  std::string scene, scene_option;
  long width = 1280, height = 720;
  cmd.Positional("SCENE", &scene, "scene name, path or test object", false);
  cmd.Text("scene", &scene_option, "the same as SCENE (as in ssc trial --scene)");
  std::string kind_name;
  cmd.Text("scene-kind", &kind_name,
           std::string("a test object's scene: ") + kObjectSceneKindNames +
               " (as in ssc objects; default the default scene's, " +
               ObjectSceneKindName(ObjectSceneKindOfTier(RigTierFor(RigUse::kTrial))) +
               "); only with a test object");
  std::string camera = "overview";
  cmd.Choice("camera", &camera,
             "camera at start: overview (the arm and the cup), cup (a close-up that follows the "
             "cup), free (MuJoCo's); T cycles them",
             {"overview", "cup", "free"});
  AddLawOptions(&cmd, &v.config.law);
  cmd.Seed("seed", &v.config.seed, "sensor noise seed");
  cmd.Number("speed", &v.speed, "simulated seconds per wall second at start (- / = change it)", "",
             NumberRange::Positive(1000));
  cmd.OutputFile("screenshot", &v.screenshot,
                 "render off-screen to this PNG after --time and exit");
  cmd.Number("time", &v.time_s, "simulated seconds before the screenshot", "s",
             NumberRange::Closed(0, 3600));
  cmd.Integer("width", &width, "image width, px", NumberRange::Closed(16, 8192));
  cmd.Integer("height", &height, "image height, px", NumberRange::Closed(16, 8192));
  AddControllerOptions(&cmd, &settings.controller, &settings.controller_params,
                       &v.config.controller);
  AddTrialSettingOptions(&cmd, &v.config, &settings);
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  if (!scene.empty() && !scene_option.empty() && scene != scene_option) {
    return cmd.Fail("SCENE '" + scene + "' and --scene '" + scene_option +
                    "' name different scenes: give one");
  }
  if (scene.empty()) scene = scene_option.empty() ? DefaultScene() : scene_option;
  ObjectSceneKind kind = ObjectSceneKindOfTier(RigTierFor(RigUse::kTrial));
  if (std::string e; !kind_name.empty() && !ObjectSceneKindByName(kind_name, &kind, &e)) {
    return cmd.Fail("--scene-kind: " + e);
  }
  v.camera = camera == "cup"    ? ViewerCamera::kCup
             : camera == "free" ? ViewerCamera::kFree
                                : ViewerCamera::kOverview;
  std::string error;
  v.width = static_cast<int>(width);
  v.height = static_cast<int>(height);
  v.scene_path = ResolveScenePath(scene);
  const bool is_file = std::filesystem::exists(v.scene_path);
  if (is_file && !kind_name.empty()) {
    return cmd.Fail("--scene-kind '" + kind_name + "' picks a test object's scene; '" + scene +
                    "' is a scene file (for the flex tier name " +
                    RigObjectTemplate(RigKind::kFlex).scene + ")");
  }
  if (!is_file) {
    // A test object by name: write its scenes (out/objects/scenes) and open the arm scene, with
    // the trial set up for that object.
    const ObjectSpec spec = ObjectByName(scene);
    if (spec.name.empty()) {
      std::fprintf(stderr,
                   "ssc view: '%s' is neither a scene file, a scene under scenes/, nor a "
                   "test object (ssc objects --help lists them)\n",
                   scene.c_str());
      return kExitMissingInput;
    }
    const std::string dir = (std::filesystem::path("out") / "objects" / "scenes").string();
    if (!WriteObjectFiles(spec, dir, SourceDir(), RigObjectSceneTemplates(), &error)) {
      std::fprintf(stderr, "ssc view: %s\n", error.c_str());
      return 1;
    }
    v.scene_path = std::filesystem::absolute(std::filesystem::path(dir) /
                                             ObjectSceneFile(spec, kind, v.config.law.step_mm))
                       .string();
    v.config = ObjectTrialConfig(spec, v.config);  // the options hold on objects too
    v.frame_object = true;
  }
  v.create_outputs = [&cmd]() { return cmd.CreateOutputs(); };
  return RunViewer(v);
}

}  // namespace ssc
