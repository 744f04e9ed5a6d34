// The crimp met in a trial and hopped (docs/flex_skirt.md, "The crimp"): corner_a330 in the flex
// tier, the default effects, seed 1, the law at dL 10 mm. The published law steps the cup past
// the notch's apex; the skirt's stretch over the notch, folded in under the throat, seals the cup
// within a control period or two and the trial ends there as failure II. crimp_hop detects that
// seal's onset, hops back over the edge and carries on round the corner to the goal. Two flex
// trials, about 25 s of CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "objects/object_mjcf.h"
#include "objects/object_spec.h"
#include "runtime/mujoco_model.h"
#include "studies/object_trials.h"
#include "tests/scratch_dir.h"

namespace ssc {
namespace {

struct CornerRun {
  ObjectTrialRow row;
  int hops = 0;  // rises of the tool 2 mm or more above the hold height
};

CornerRun RunCorner(const std::string& controller) {
  const ObjectSpec spec = ObjectByName("corner_a330");
  std::string error;
  EXPECT_TRUE(WriteObjectFiles(spec, ScratchDir().string(), ResourceDir(),
                               RigObjectSceneTemplates(), &error))
      << error;
  const std::string scene =
      (ScratchDir() / ObjectSceneFile(spec, ObjectSceneKind::kFlex, 10.0)).string();
  ModelPtr model = LoadModel(scene, &error);
  EXPECT_TRUE(model) << error;
  CornerRun run;
  if (!model) return run;
  ContourLawParams law;
  law.step_mm = 10;
  ControllerChoice choice;
  choice.name = controller;
  run.row = RunObjectTrial(model.get(), spec, law, FittedRobotEffects(), 1, true, choice);
  bool up = false;
  for (const TrialLogRow& l : run.row.result.log) {
    if (l.phase != TrialPhase::kFollow) continue;
    const bool now = l.tool_m[2] > run.row.result.hold_height_m + 2e-3;
    run.hops += now && !up;
    up = now;
  }
  return run;
}

TEST(CrimpTrialTest, TheLawSealsAtTheConcaveCornerAndCrimpHopHopsAndCarriesOnToTheGoal) {
  const CornerRun law = RunCorner("published");
  EXPECT_EQ(law.row.result.outcome, Outcome::kFailureGrasp) << law.row.result.detail;
  EXPECT_EQ(law.hops, 0);
  // Sealed past the notch's apex (60 mm along the edge), short of the goal 23 mm past it.
  EXPECT_GT(law.row.end_arc_mm, 55);
  EXPECT_LT(law.row.end_arc_mm, 80);

  const CornerRun hop = RunCorner("crimp_hop");
  EXPECT_GE(hop.hops, 1);
  EXPECT_EQ(hop.row.result.outcome, Outcome::kSuccess) << hop.row.result.detail;
  EXPECT_GT(hop.row.end_arc_mm, law.row.end_arc_mm + 10);
}

}  // namespace
}  // namespace ssc
