// ssc_object_cost [OUT_DIR [STEPS]]: writes every test object's files into OUT_DIR (default
// /tmp/ssc_object_scenes) and prints the mean mj_step cost of each probe scene as a Markdown
// table (docs/objects.md).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "objects/object_mjcf.h"
#include "runtime/mujoco_model.h"
#include "studies/object_step_cost.h"
#include "studies/object_trials.h"

int main(int argc, char** argv) {
  if (argc > 1 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::printf("usage: ssc_object_cost [OUT_DIR [STEPS]]\n");
    return 0;
  }
  if (const std::string e = ssc::CheckMuJoCoVersion(); !e.empty()) {
    std::fprintf(stderr, "%s\n", e.c_str());
    return 1;
  }
  const std::string out = argc > 1 ? argv[1] : "/tmp/ssc_object_scenes";
  ssc::StepCostOptions options;
  if (argc > 2) options.steps = std::max(1, std::atoi(argv[2]));
  std::string error;
  if (ssc::WriteAllObjectScenes(out, ssc::SourceDir(), ssc::RigObjectSceneTemplates(), &error) <
      0) {
    std::fprintf(stderr, "ssc_object_cost: %s\n", error.c_str());
    return 1;
  }
  std::printf("| object | object geoms | contacts per step | mean mj_step (us) |\n");
  std::printf("| --- | --- | --- | --- |\n");
  for (const ssc::ObjectSpec& spec : ssc::AllObjects()) {
    const std::string scene =
        (std::filesystem::path(out) / ssc::ObjectFileNames(spec.name).probe_scene).string();
    const auto cost = ssc::MeasureStepCost(spec, scene, options, &error);
    if (!cost) {
      std::fprintf(stderr, "ssc_object_cost: %s\n", error.c_str());
      return 1;
    }
    std::printf("| %s | %d | %.1f | %.1f |\n", spec.name.c_str(), cost->object_geoms,
                cost->contacts, cost->step_us);
    std::fflush(stdout);
  }
  return 0;
}
