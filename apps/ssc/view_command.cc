// ssc view: the interactive viewer, or an off-screen screenshot.
#include <cstdio>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/trial_options.h"
#include <filesystem>

#include "runtime/mujoco_model.h"
#include "objects/object_mjcf.h"
#include "studies/object_trials.h"
#include "viewer/viewer_app.h"

namespace ssc {

int RunViewCommand(int argc, char** argv) {
  std::vector<cli::Option> options = {
      {"pref", "100", "P_ref, Pa"},
      {"beta", "2", "beta"},
      {"step", "7.5", "step length dL, mm"},
      {"seed", "1", "sensor noise seed"},
      {"speed", "1", "simulated seconds per wall second at start (- / = change it)"},
      {"screenshot", "", "render off-screen to this PNG after --time and exit"},
      {"time", "5", "simulated seconds before the screenshot, s"},
      {"width", "1280", "image width, px"},
      {"height", "720", "image height, px"}};
  for (const cli::Option& o : TrialSettingOptions()) options.push_back(o);
  cli::Parser p("view",
                "ssc view [SCENE] [options]: the twin in a window with the trial controller running\n"
                "(the same mjcb_control callback as headless trials: same seed, same trajectory).\n"
                "SCENE: a name under scenes/ (default disk_benchmark), a path, or a test object by\n"
                "name (disk_d10, hole_d06, corner_a090, volute, semicircle_strip, fillet, ...).",
                options);
  if (!p.Parse(argc, argv)) {
    if (p.help_requested()) return 0;
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  ViewerOptions v;
  long seed = 0, width = 0, height = 0;
  std::string error;
  if (!p.GetDouble("pref", &v.config.law.p_ref_pa) || !p.GetDouble("beta", &v.config.law.beta) ||
      !p.GetDouble("step", &v.config.law.step_mm) || !p.GetInt("seed", &seed) ||
      !p.GetDouble("speed", &v.speed) || !p.GetDouble("time", &v.time_s) ||
      !p.GetInt("width", &width) || !p.GetInt("height", &height)) {
    std::fprintf(stderr, "%s\n", p.error().c_str());
    return 2;
  }
  if (!ReadTrialSettings(&p, &v.config, &error)) {
    std::fprintf(stderr, "ssc view: %s\n", error.c_str());
    return 2;
  }
  if (seed < 0 || width < 16 || height < 16 || width > 8192 || height > 8192 || v.speed <= 0) {
    std::fprintf(stderr, "ssc view: need seed >= 0, width/height in [16, 8192] px, speed > 0\n");
    return 2;
  }
  v.config.seed = static_cast<std::uint64_t>(seed);
  if (const std::string e = v.config.Validate(); !e.empty()) {
    std::fprintf(stderr, "ssc view: %s\n", e.c_str());
    return 2;
  }
  v.width = static_cast<int>(width);
  v.height = static_cast<int>(height);
  v.screenshot = p.Get("screenshot");
  const std::string scene = p.positional().empty() ? "disk_benchmark" : p.positional()[0];
  v.scene_path = ResolveScenePath(scene);
  if (!std::filesystem::exists(v.scene_path)) {
    // A test object by name: write its scenes (out/objects/scenes) and open the arm scene, with
    // the trial set up for that object.
    const ObjectSpec spec = ObjectByName(scene);
    if (spec.name.empty()) {
      std::fprintf(stderr, "ssc view: '%s' is neither a scene file, a scene under scenes/, nor a "
                           "test object (ssc objects --help lists them)\n", scene.c_str());
      return 2;
    }
    const std::string dir = (std::filesystem::path("out") / "objects" / "scenes").string();
    if (!WriteObjectFiles(spec, dir, SourceDir(), &error)) {
      std::fprintf(stderr, "ssc view: %s\n", error.c_str());
      return 1;
    }
    v.scene_path = std::filesystem::absolute(std::filesystem::path(dir) / ObjectFileNames(spec.name).arm_scene).string();
    const ContourLawParams law = v.config.law;
    const std::uint64_t run_seed = v.config.seed;
    v.config = ObjectTrialConfig(spec, law, run_seed);
  }
  return RunViewer(v);
}

}  // namespace ssc
