// The twin against robot logs written exactly as the lab records them
// (tests/compare/lab_log_generator): every form must open unchanged, land the disk where the lab
// had it, and replay must recover what was changed; a replay that misses every object is an error,
// never a report.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "compare/comparison.h"
#include "lab_log_generator.h"
#include "runtime/mujoco_model.h"
#include "studies/tool_variants.h"
#include "tests/scratch_dir.h"
#include "trial/robot_effects.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  ModelPtr gantry;
  TrialConfig config;
  TrialResult trial;
  SceneObject disk;
};

const Fixture& Shared() {
  static Fixture f = [] {
    Fixture x;
    std::string error;
    x.gantry = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
    x.config.law.step_mm = 7.5;
    // The ideal loop: the replay must reproduce this run. (With the default step error the
    // mocap replay reads the iteration instants 0.78-0.81 of the run; docs/robot_logs.md.)
    x.config.effects = RobotEffectsParams();
    x.trial = RunTrial(x.gantry.get(), x.config, true, &error);
    x.disk = FindSceneObjects(x.gantry.get()).front();
    return x;
  }();
  return f;
}

std::string TempDir(const std::string& tag) {
  const fs::path p = ScratchDir() / ("ssc_compare_" + tag);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

testing::LabForms Generate(const std::string& tag, const LabSetup& setup,
                           const LogPerturbation& perturbation) {
  const Fixture& f = Shared();
  testing::LabForms forms;
  std::string error;
  EXPECT_TRUE(testing::WriteLabForms(f.trial, f.config, f.disk, setup, perturbation, TempDir(tag),
                                     &forms, &error))
      << error;
  return forms;
}

CompareResult Compare(const std::string& log, const std::string& out, bool closed_loop = false,
                      CompareOptions o = CompareOptions()) {
  o.log_path = log;
  o.out_dir = out;
  o.processing.moving_average = 1;  // the twin's pressures already carry the host's filter
  o.closed_loop = closed_loop;
  CompareResult r;
  std::string error;
  EXPECT_TRUE(RunComparison(o, &r, &error)) << log << ": " << error;
  return r;
}

TEST(CompareTest, EveryLabFormOpensUnchangedAndReplaysTheRun) {
  ASSERT_EQ(Shared().trial.outcome, Outcome::kSuccess);
  const testing::LabForms forms = Generate("plain", LabSetup(), LogPerturbation());
  for (const std::string& log :
       {forms.newer_dir, forms.newer_file, forms.older_dir, forms.mat_path}) {
    const CompareResult r = Compare(log, TempDir("out_plain"));
    // The disk found where the lab's script had it, from the log alone.
    EXPECT_TRUE(r.setup.object.known) << log;
    EXPECT_NEAR(r.setup.object.x_m, kLabDiskCentreX, 0.5e-3) << log;
    EXPECT_NEAR(r.setup.object.y_m, kLabDiskCentreY, 0.5e-3) << log;
    EXPECT_LT(r.setup.reach.closest_m, 1e-3) << log;
    for (int k = 0; k < 4; ++k) {
      EXPECT_GT(r.replay.correlation[k], 0.95) << log << " chamber " << k;
      EXPECT_NEAR(r.replay.mean_ratio[k], 1.0, 0.05) << log << " chamber " << k;
    }
    EXPECT_LT(r.replay.direction_median_deg, 5.0) << log;
    EXPECT_GT(r.replay.direction_samples, 100) << log;
  }
  // The .mat adds the script's arguments and its history: the twin's controller at the same
  // poses agrees with the logged iterations.
  const CompareResult r = Compare(forms.mat_path, TempDir("out_mat"));
  ASSERT_TRUE(r.history.ran) << r.history_warning;
  EXPECT_EQ(r.history.iterations, static_cast<int>(forms.log.args.history.size()));
  EXPECT_NEAR(r.history.time_offset_s, 1.0, 0.02);  // the 1 s in-air lead
  EXPECT_LT(r.history.match_rms_mm, 0.1);
  EXPECT_LT(r.history.r_p_median_deg, 5.0);
  EXPECT_LT(r.history.r_p_final_median_deg, 5.0);
  // The mocap replay reads the iterations' instants within about 10 % of the gantry trial.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r.history.p_mean_ratio[k], 1.0, 0.1) << k;
  EXPECT_LT(r.history.f_normal_rms_n, 0.5);
}

TEST(CompareTest, KnownPerturbationsAreRecoveredFromEachForm) {
  // The "robot": 30 % more sensitive sensors with offsets and noise, sampled at 166 Hz, a pose
  // 5 ms late, the disk 8 cm away from where the lab had it and 3 mm higher, the history's
  // clock started 2.5 s later.
  LabSetup setup;
  setup.disk_x_m = -0.55;
  setup.disk_y_m = 0.12;
  setup.disk_top_z_m = 0.008;
  setup.history_time_offset_s = 2.5;
  LogPerturbation p;
  p.pressure_scale = 1.3;
  p.sensor_offset_pa = {30, -40, 50, 10};
  p.noise_pa = 3;
  p.pressure_rate_hz = 166;
  p.pose_delay_s = 0.005;
  p.seed = 11;
  const testing::LabForms forms = Generate("perturbed", setup, p);
  for (const std::string& log : {forms.newer_dir, forms.older_dir, forms.mat_path}) {
    const CompareResult r = Compare(log, TempDir("out_perturbed"));
    EXPECT_NEAR(r.setup.object.x_m, -0.55, 1e-3) << log;
    EXPECT_NEAR(r.setup.object.y_m, 0.12, 1e-3) << log;
    EXPECT_NEAR(r.setup.object.top_z_m, 0.008, 1e-3) << log;
    // The gain shows as the ratio of means; the offsets are removed by the in-air offset.
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(r.replay.mean_ratio[k], 1 / 1.3, 0.05) << log << " chamber " << k;
    }
    EXPECT_LT(r.replay.direction_median_deg, 10.0) << log;
  }
  // The history's pressures carry the same gain: against the unchanged run's history, 1.3.
  const CompareResult r = Compare(forms.mat_path, TempDir("out_perturbed_mat"));
  const CompareResult unchanged =
      Compare(Generate("unchanged", LabSetup(), LogPerturbation()).mat_path, TempDir("out_u"));
  ASSERT_TRUE(r.history.ran) << r.history_warning;
  EXPECT_NEAR(r.history.time_offset_s, 1.0 - 2.5, 0.02);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(unchanged.history.p_mean_ratio[k] / r.history.p_mean_ratio[k], 1.3, 0.05) << k;
  }
}

TEST(CompareTest, AReplayThatMissesEveryObjectIsAnError) {
  const testing::LabForms forms = Generate("miss", LabSetup(), LogPerturbation());
  // The object said to be where the UR Base frame would put it: the path lands 1.2 m away.
  CompareOptions o;
  o.log_path = forms.newer_dir;
  o.out_dir = TempDir("out_miss");
  o.object_pose = {0.63, -0.097, 0.005};
  o.processing.moving_average = 1;  // the twin's pressures already carry the host's filter
  CompareResult r;
  std::string error;
  EXPECT_FALSE(RunComparison(o, &r, &error));
  EXPECT_NE(error.find("never comes within reach"), std::string::npos) << error;
  EXPECT_NE(error.find("closest approach"), std::string::npos) << error;
  EXPECT_NE(error.find("to 'disk'"), std::string::npos) << error;
  EXPECT_NE(error.find("log poses in base_link, object pose from --object-pose"), std::string::npos)
      << error;
  EXPECT_FALSE(fs::exists(fs::path(o.out_dir) / "report.json"));  // no report of 0 Pa
  // The same pose given right: replay runs.
  o.object_pose = {kLabDiskCentreX, kLabDiskCentreY, 0.005};
  EXPECT_TRUE(RunComparison(o, &r, &error)) << error;
  EXPECT_GT(r.replay.correlation[0], 0.9);
}

TEST(CompareTest, ClosedLoopTakesItsParametersFromTheMatAlone) {
  // A run at dL = 5 mm, P_ref 150 Pa; the command line's defaults (7.5 mm, 100 Pa) must not be
  // used: the file's d_lat (metres) and Pref are.
  const Fixture& f = Shared();
  TrialConfig c;
  c.law.step_mm = 5;
  c.law.p_ref_pa = 150;
  std::string error;
  const TrialResult run = RunTrial(f.gantry.get(), c, true, &error);
  ASSERT_EQ(run.outcome, Outcome::kSuccess) << run.detail;
  testing::LabForms forms;
  ASSERT_TRUE(testing::WriteLabForms(run, c, f.disk, LabSetup(), LogPerturbation(), TempDir("loop"),
                                     &forms, &error))
      << error;
  CompareOptions o;
  o.loop_config.seed = 9;  // another noise realisation of the same controller
  const CompareResult r = Compare(forms.mat_path, TempDir("out_loop"), true, o);
  ASSERT_TRUE(r.closed.ran);
  EXPECT_NE(r.closed.parameters.find("P_ref, beta, dL (d_lat)"), std::string::npos)
      << r.closed.parameters;
  EXPECT_EQ(r.closed.twin_outcome, "success");
  EXPECT_NEAR(r.closed.twin.dr_mm, r.closed.log.dr_mm, 0.5);
  // At 7.5 mm the twin would take about 2/3 of the time.
  EXPECT_NEAR(r.closed.twin.duration_s, r.closed.log.duration_s, 0.15 * r.closed.log.duration_s);
  EXPECT_LT(r.closed.path_distance_mean_mm, 1.5);
  ASSERT_TRUE(r.history.ran);
  EXPECT_LT(r.history.r_p_median_deg, 5.0);
}

TEST(CompareTest, ALipThatPeelsIsReplayedOnlyWhenTheReplayDragsTheLipToo) {
  // The "robot": the twin with the trailing-lip peel on (robot effects: slip 1 mm, 0.6 decades),
  // so every logged sample has the trailing chambers low. The replay drags the lip along the
  // logged path with the same effect and reads the same stream (ratio of means 1.00 +- 0.07:
  // measured 0.944-0.954, correlation 0.995, the lip pressed at the start, where it lands);
  // a replay of the plugin alone reads the trailing chambers too high and turns the direction.
  const Fixture& f = Shared();
  TrialConfig c = f.config;
  std::string error;
  ASSERT_TRUE(ParseRobotEffects("slip_mm=1,peel_decades=0.6", &c.effects, &error)) << error;
  const TrialResult run = RunTrial(f.gantry.get(), c, true, &error);
  ASSERT_FALSE(run.log.empty()) << error;
  testing::LabForms forms;
  ASSERT_TRUE(testing::WriteLabForms(run, c, f.disk, LabSetup(), LogPerturbation(),
                                     TempDir("peel_forms"), &forms, &error))
      << error;
  CompareOptions with_lip;
  with_lip.loop_config.effects = c.effects;
  const CompareResult same = Compare(forms.mat_path, TempDir("out_peel"), false, with_lip);
  const CompareResult plugin_only = Compare(forms.mat_path, TempDir("out_peel_plugin"));
  double worst_same = 0, worst_plugin = 0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(same.replay.mean_ratio[k], 1.0, 0.07) << k;
    worst_same = std::max(worst_same, std::fabs(same.replay.mean_ratio[k] - 1.0));
    worst_plugin = std::max(worst_plugin, std::fabs(plugin_only.replay.mean_ratio[k] - 1.0));
  }
  EXPECT_GT(worst_plugin, 2 * worst_same);
  EXPECT_LT(same.replay.direction_median_deg, plugin_only.replay.direction_median_deg);
}

TEST(CompareTest, ReplayExposesARobotWithAStrongerPump) {
  // The "robot": the twin with a 40 % stronger pump, logged with 8 Pa of noise. Replayed in the
  // default twin, the twin reads less vacuum than the log wherever the cup seals (ratio of
  // means below 0.92, against 1.00 +- 0.05 unchanged) and still agrees on direction.
  std::string error;
  ModelPtr strong = ToolModelVariant(SourceDir() + "/scenes/disk_benchmark_gantry.xml",
                                     {{"pump_free_flow_lpm", "18.06"}}, &error);
  ASSERT_TRUE(strong) << error;
  const Fixture& f = Shared();
  const TrialResult robot_run = RunTrial(strong.get(), f.config, true, &error);
  LogPerturbation p;
  p.noise_pa = 8;
  p.seed = 5;
  testing::LabForms forms;
  ASSERT_TRUE(testing::WriteLabForms(robot_run, f.config, f.disk, LabSetup(), p,
                                     TempDir("strong_forms"), &forms, &error))
      << error;
  const CompareResult r = Compare(forms.mat_path, TempDir("out_strong"));
  for (int k = 0; k < 4; ++k) EXPECT_LT(r.replay.mean_ratio[k], 0.92) << k;
  EXPECT_LT(r.replay.pbar_bias_pa, -20.0);
  EXPECT_LT(r.replay.direction_median_deg, 10.0);
}

}  // namespace
}  // namespace ssc
