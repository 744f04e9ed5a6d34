// Contour-following trials on the disk benchmark: controller outcomes of the published
// experiments, forced failures, and the control-callback dispatch.
#include "runtime/trial.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <thread>

#include "common/tool_names.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/approach_cache.h"
#include "runtime/control_dispatch.h"
#include "runtime/deferred_sensor_step.h"
#include "runtime/mujoco_model.h"
#include "studies/sweep.h"
#include "studies/sweep_io.h"
#include "studies/trial_io.h"

namespace ssc {
namespace {

// The light scene: the same cup and disk on a gantry (trajectories compared with the arm in
// docs/trials.md).
const mjModel* Scene() {
  static ModelPtr model = [] {
    std::string error;
    ModelPtr m = LoadModel(SourceDir() + "/scenes/disk_benchmark_gantry.xml", &error);
    EXPECT_TRUE(m) << error;
    return m;
  }();
  return model.get();
}

TrialResult Trial(double pref, double beta, double step, std::uint64_t seed = 1,
                  TrialConfig config = {}) {
  config.law.p_ref_pa = pref;
  config.law.beta = beta;
  config.law.step_mm = step;
  config.seed = seed;
  std::string error;
  TrialResult r = RunTrial(Scene(), config, false, &error);
  EXPECT_TRUE(error.empty()) << error;
  return r;
}

TEST(ToolServoTest, SecondOrderTrackingOvershootsByItsDampingAndZeroKeepsTheFirstOrder) {
  // A 5 mm step of the target along x, the command tracked at 2 ms without the physics: with
  // damping zeta the command overshoots by exp(-pi zeta / sqrt(1 - zeta^2)) (16.3 % at 0.5,
  // 4.6 % at 0.7); damping 0 is the first-order smoothing, which never overshoots.
  const mjModel* m = Scene();
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const int site = mj_name2id(m, mjOBJ_SITE, kToolSiteName);
  ASSERT_GE(site, 0);
  for (double zeta : {0.0, 0.5, 0.7}) {
    std::unique_ptr<ToolServo> servo = MakeToolServo(m);
    std::string error;
    d->time = 0;
    ASSERT_TRUE(servo->Init(m, d, site, &error)) << error;
    ServoParams p;
    p.smoothing_s = 0.08;
    p.damping = zeta;
    servo->set_params(p);
    const Vec3 start = servo->command();
    servo->SetTarget({start[0] + 0.005, start[1], start[2]});
    double peak = 0;
    for (int k = 1; k <= 1500; ++k) {  // 3 s: settled for every zeta here
      d->time = 0.002 * k;
      servo->Track(m, d);
      peak = std::max(peak, servo->command()[0] - start[0]);
    }
    const double overshoot = peak / 0.005 - 1;
    const double expected = zeta > 0 ? std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta)) : 0.0;
    EXPECT_NEAR(overshoot, expected, 0.01) << "zeta " << zeta;
    EXPECT_NEAR(servo->command()[0] - start[0], 0.005, 1e-6) << "zeta " << zeta;
  }
  mj_deleteData(d);
}

TEST(TrialTest, PilotControllerCompletesTheDisk) {
  const TrialResult r = Trial(70, 1.0, 2.5);
  EXPECT_EQ(r.outcome, Outcome::kSuccess) << r.detail;
  EXPECT_GT(r.swept_deg, 355);  // positive: counter-clockwise seen from above
}

TEST(TrialTest, BestControllerCompletesTheDiskAtAllThreeSteps) {
  // The published best controller (P_ref 100 Pa, beta 2) at dL 2.5, 5, 7.5 mm: about 1, 2, 3 cm/s
  // and the cup centre 2.5 mm inside the edge.
  // The ideal loop (effects off): its speed and depth are the geometry of the law and the
  // static curve; the default step error's share of them is checked below.
  const double published_speed_mm_s[3] = {10, 20, 30};
  const double steps[3] = {2.5, 5.0, 7.5};
  TrialConfig ideal;
  ideal.effects = RobotEffectsParams();
  for (int i = 0; i < 3; ++i) {
    const TrialResult r = Trial(100, 2.0, steps[i], 1, ideal);
    EXPECT_EQ(r.outcome, Outcome::kSuccess) << "dL " << steps[i] << ": " << r.detail;
    // One loop, counter-clockwise: success is checked once per control iteration, so the sweep
    // passes 355 deg by at most one step's angle about the centre (dL / r_mean, plus the
    // servo's catching up within one 20 ms path sample: 1 deg).
    const double step_deg = steps[i] / r.metrics.r_mean_mm * 180 / M_PI;
    EXPECT_GE(r.swept_deg, 355) << "dL " << steps[i];
    EXPECT_LE(r.swept_deg, 355 + step_deg + 1) << "dL " << steps[i];
    // The path is that loop: its length over the swept arc at the mean radius is 1 plus the
    // wander (s_c-like; measured 1.00-1.09, the 7.5 mm step zig-zags most).
    const double arc_mm = r.swept_deg * M_PI / 180 * r.metrics.r_mean_mm;
    EXPECT_GT(r.metrics.s_mm / arc_mm, 0.99) << "dL " << steps[i];
    EXPECT_LT(r.metrics.s_mm / arc_mm, 1.15) << "dL " << steps[i];
    // Speed: the control period (0.15 s) and servo smoothing were chosen for the published
    // speeds; measured 9.9, 19.9, 30.0 mm/s. 5 % holds the choice, not the 20 % the published
    // "about" allows.
    EXPECT_NEAR(r.metrics.speed_mm_s, published_speed_mm_s[i], 0.05 * published_speed_mm_s[i]);
    // Where the cup rides: the static curve puts the mean vacuum at P_ref = 100 Pa 2.53 mm inside
    // a straight edge (flow_network_test, the MuJoCo probe 2.55 mm). Following the loop moves the
    // cup outward by the disk's curvature and the servo lag: measured -2.44, -2.38, -2.35 mm
    // (seeds 1-5 agree within 0.02 mm). Band: the static offset +-0.25 mm, which the published
    // -2.5 mm also satisfies; a calibration shift or a lag change beyond it fails here.
    EXPECT_NEAR(r.metrics.dr_mm, -2.53, 0.25) << "dL " << steps[i];
  }
}

TEST(TrialTest, TheDefaultStepErrorWidensTheWanderAtTheIdealLoopsDepth) {
  // The twin's default effects (the fitted step error: 0.38 of the step, capped at 1.43 mm,
  // successive misses correlated 0.29; a 7.9 Pa tare offset per chamber) against the ideal loop,
  // P_ref 100 Pa, beta 1.5, dL 5 mm, seeds 1-3 (both run every seed). Measured: sigma_r 0.87
  // against 0.54 mm, s_c +1.1 against -6.2 %, dr -2.31 against -2.35 mm. The
  // error moves the cup about the edge (toward the published 1.36 mm and +11 %) without moving
  // where it rides; a step error that biased the path, or one that vanished, fails here.
  TrialConfig ideal;
  ideal.effects = RobotEffectsParams();
  ASSERT_TRUE(TrialConfig().effects.AnyOn());  // the default is the fitted set, not the ideal
  double sigma_default = 0, sigma_ideal = 0, sc_default = 0, sc_ideal = 0, dr_default = 0,
         dr_ideal = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const TrialResult d = Trial(100, 1.5, 5.0, seed);
    const TrialResult i = Trial(100, 1.5, 5.0, seed, ideal);
    ASSERT_EQ(d.outcome, Outcome::kSuccess) << seed << ": " << d.detail;
    ASSERT_EQ(i.outcome, Outcome::kSuccess) << seed << ": " << i.detail;
    sigma_default += d.metrics.sigma_r_mm / 3;
    sigma_ideal += i.metrics.sigma_r_mm / 3;
    sc_default += d.metrics.s_c / 3;
    sc_ideal += i.metrics.s_c / 3;
    dr_default += d.metrics.dr_mm / 3;
    dr_ideal += i.metrics.dr_mm / 3;
  }
  EXPECT_GT(sigma_default, sigma_ideal + 0.15);
  EXPECT_GT(sc_default, sc_ideal + 0.05);
  EXPECT_NEAR(dr_default, dr_ideal, 0.3);
}

TEST(TrialTest, WithoutCorrectionTheCupDriftsOffTheEdge) {
  // beta = 0: pure tangential steps; on a disk each step leaves the circle outward, so the cup
  // loses the edge before a loop and the mean vacuum falls below the 5 Pa failure I threshold.
  // (The ideal loop: a step error may carry the uncorrected cup inward instead.)
  TrialConfig ideal;
  ideal.effects = RobotEffectsParams();
  const TrialResult r = Trial(100, 0.0, 2.5, 1, ideal);
  EXPECT_EQ(r.outcome, Outcome::kFailureOffEdge) << r.detail;
  EXPECT_NE(r.detail.find("below 5 Pa"), std::string::npos) << r.detail;
  EXPECT_LT(r.swept_deg, 355);
  EXPECT_GT(r.iterations, 1);  // it followed before it fell off
}

TEST(TrialTest, ObjectOnTheRightTravelsClockwise) {
  TrialConfig c;
  c.law.side = FollowSide::kObjectOnRight;
  c.timeout_s = 3;
  const TrialResult r = Trial(100, 2.0, 5.0, 1, c);
  EXPECT_LT(r.swept_deg, -20) << OutcomeName(r.outcome) << " " << r.detail;
}

TEST(TrialTest, StartingOffTheObjectIsFailureOne) {
  TrialConfig c;
  c.target.start = {0.65 + 0.050, 0.0};  // 15 mm beyond the edge: nothing under the cup
  c.target.goal.band_m = 0;  // under test: the pressure failure, not the band of following
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kFailureOffEdge) << r.detail;
}

TEST(TrialTest, PushedOntoTheSurfaceIsFailureTwo) {
  TrialConfig c;
  c.target.start = {0.65, 0.0};  // stay on the disk centre: the cup seals
  c.target.goal.band_m = 0;      // under test: the pressure failure, not the band of following
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kFailureGrasp) << r.detail;
  EXPECT_NE(r.detail.find("all chambers above 10000 Pa"), std::string::npos) << r.detail;
  EXPECT_EQ(r.iterations, 1);  // sealed from the first control iteration on
}

TEST(TrialTest, StartingFarOffTheEdgeLosesIt) {
  TrialConfig c;  // the benchmark's goal: round the disk within the cup body radius of its edge
  c.target.start = {0.65 + 0.050, 0.0};  // 15 mm beyond the edge
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kLostEdge) << r.detail;
}

TEST(TrialTest, ApproachStopsAtTheStartUpForce) {
  // The approach ends when the tared F/T reads the start-up force: the 16 lip springs (93.75 N/m
  // each, 1500 N/m together) are then compressed by F / 1500 N/m, so the lip plane is held that
  // far below the disk's top (z = 10 mm). The servo's lag past the trigger adds a little:
  // measured 0.71 mm at 1.0 N and 1.06 mm at 1.5 N against 0.67 and 1.00 mm; band 0.1 mm.
  // Landed on the centre, the whole ring rests on the disk.
  for (double force_n : {1.0, 1.5}) {
    TrialConfig c;
    c.target = TrialTarget::Disk(kWorkspaceX, kWorkspaceY, kBenchmarkDiskRadiusM,
                                 kBenchmarkStartOffsetM, DiskLanding::kAtCentre);
    c.approach_force_n = force_n;
    c.timeout_s = 0.2;  // the follow phase is not under test
    const TrialResult centre = Trial(100, 2.0, 2.5, 1, c);
    EXPECT_NEAR(0.010 - centre.hold_height_m, force_n / 1500.0, 1e-4) << force_n << " N";
    // Landed at the start (the default), 3 mm inside the edge, the segments beyond the edge
    // hang over the drop: the rest carry the force, pressed deeper (1.37 against 1.06 mm at 1.5
    // N), but no deeper than the tool's limit.
    c.target =
        TrialTarget::Disk(kWorkspaceX, kWorkspaceY, kBenchmarkDiskRadiusM, kBenchmarkStartOffsetM);
    const TrialResult start = Trial(100, 2.0, 2.5, 1, c);
    EXPECT_GT(0.010 - start.hold_height_m, 0.010 - centre.hold_height_m + 1e-4) << force_n;
    EXPECT_LT(0.010 - start.hold_height_m, 0.002) << force_n;
  }
}

TEST(TrialTest, TheLogHoldsTheLawsValuesOnlyWhereItRan) {
  // The law's mean, differentials and c_f exist at control iterations: NaN on every other row
  // (the approach, the move to the start and between iterations), in the log and in trial.csv.
  TrialConfig c;
  c.seed = 2;
  std::string error;
  mjData* d = mj_makeData(Scene());
  auto trial = ContourTrial::Create(Scene(), d, c, true, &error);
  ASSERT_TRUE(trial) << error;
  const TrialResult r = trial->Run(5.0);  // the approach, the move and about 10 iterations
  mj_deleteData(d);
  int iterations = 0, others_in_follow = 0, before_follow = 0;
  for (const TrialLogRow& row : r.log) {
    for (double v : {row.pbar_pa, row.dpx_pa, row.dpy_pa, row.cf}) {
      EXPECT_EQ(std::isfinite(v), row.iteration) << "t = " << row.t_s;
    }
    iterations += row.iteration;
    others_in_follow += !row.iteration && row.phase == TrialPhase::kFollow;
    before_follow += row.phase != TrialPhase::kFollow;
  }
  EXPECT_GT(iterations, 5);
  EXPECT_GT(others_in_follow, iterations);  // rows between iterations were checked too
  EXPECT_GT(before_follow, 100);
  const auto path = std::filesystem::temp_directory_path() /
                    ("ssc_trial_log_" + std::to_string(::getpid()) + ".csv");
  ASSERT_TRUE(WriteTrialLogCsv(path.string(), r, &error)) << error;
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  EXPECT_NE(header.find(",pbar_pa,dpx_pa,dpy_pa,cf,"), std::string::npos) << header;
  size_t row_index = 0;
  while (std::getline(in, line) && row_index < r.log.size()) {
    const bool nan = line.find(",nan,nan,nan,nan,") != std::string::npos;
    EXPECT_EQ(nan, !r.log[row_index].iteration) << line;
    ++row_index;
  }
  EXPECT_EQ(row_index, r.log.size());
  std::filesystem::remove(path);
}

TEST(TrialTest, SameSeedSameTrajectory) {
  const TrialResult a = Trial(100, 2.0, 5.0, 7), b = Trial(100, 2.0, 5.0, 7);
  const TrialResult c = Trial(100, 2.0, 5.0, 8);
  EXPECT_EQ(a.metrics.s_mm, b.metrics.s_mm);
  EXPECT_EQ(a.metrics.sigma_r_mm, b.metrics.sigma_r_mm);
  EXPECT_NE(a.metrics.s_mm, c.metrics.s_mm);
}

TEST(TrialTest, InvalidConfigIsRejectedWithTheField) {
  TrialConfig c;
  c.law.p_ref_pa = 1e6;
  std::string error;
  mjData* d = mj_makeData(Scene());
  auto trial = ContourTrial::Create(Scene(), d, c, false, &error);
  EXPECT_FALSE(trial);
  EXPECT_NE(error.find("pref_pa"), std::string::npos) << error;
  mj_deleteData(d);
}

std::vector<std::string> SortedRows(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::string> rows;
  std::string line;
  while (std::getline(f, line)) rows.push_back(line);
  std::sort(rows.begin(), rows.end());
  return rows;
}

// The summary is JSON a parser reads back, whatever the free text holds.
TEST(TrialIoTest, SummaryJsonEscapesTextAndRoundTrips) {
  TrialConfig c;
  TrialResult r;
  r.outcome = Outcome::kLostEdge;
  r.detail = "quote \" backslash \\ newline \n tab \t";
  r.swept_deg = 123.456;
  r.metrics.s_mm = std::nan("");
  const auto path = std::filesystem::temp_directory_path() /
                    ("ssc_summary_" + std::to_string(::getpid()) + ".json");
  std::string error;
  ASSERT_TRUE(WriteTrialSummaryJson(path.string(), "a \"scene\"", c, r, &error)) << error;
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  std::filesystem::remove(path);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["scene"], "a \"scene\"");
  EXPECT_EQ(j["detail"], r.detail);
  EXPECT_EQ(j["outcome"], "lost_edge");
  EXPECT_DOUBLE_EQ(j["metrics"]["swept_deg"].get<double>(), 123.456);
  EXPECT_TRUE(j["metrics"]["s_mm"].is_null());  // not finite: null, still valid JSON
  EXPECT_DOUBLE_EQ(j["parameters"]["pref_pa"].get<double>(), c.law.p_ref_pa);
}

// Bitwise equality of the mjData arrays that carry a run on (state, warm start, controls,
// plugin state, sensor outputs).
void ExpectSameData(const mjModel* m, const mjData* a, const mjData* b) {
  auto same = [](const char* what, const mjtNum* x, const mjtNum* y, mjtSize n) {
    for (mjtSize i = 0; i < n; ++i) {
      if (std::memcmp(x + i, y + i, sizeof(mjtNum)) != 0) {
        ADD_FAILURE() << what << "[" << i << "]: " << x[i] << " vs " << y[i];
        return;
      }
    }
  };
  same("time", &a->time, &b->time, 1);
  same("qpos", a->qpos, b->qpos, m->nq);
  same("qvel", a->qvel, b->qvel, m->nv);
  same("act", a->act, b->act, m->na);
  same("ctrl", a->ctrl, b->ctrl, m->nu);
  same("qacc_warmstart", a->qacc_warmstart, b->qacc_warmstart, m->nv);
  same("plugin_state", a->plugin_state, b->plugin_state, m->npluginstate);
  same("sensordata", a->sensordata, b->sensordata, m->nsensordata);
  for (int i = 0; i < m->neq; ++i) EXPECT_EQ(a->eq_active[i], b->eq_active[i]) << i;
}

TrialConfig SharedApproachConfig(double pref, double beta, double step, std::uint64_t seed) {
  TrialConfig c;
  c.law.p_ref_pa = pref;
  c.law.beta = beta;
  c.law.step_mm = step;
  c.seed = seed;
  c.timeout_s = 3;
  // Effects on: the lip shear runs through the move, the chamber spread draws from the seed.
  std::string error;
  EXPECT_TRUE(ParseRobotEffects("slip_mm=1,tilt_decades=0.08,drift_pa=1,gain_spread=0.1",
                                &c.effects, &error))
      << error;
  return c;
}

TEST(SharedApproachTest, ResumedTrialEqualsARunFromScratchToTheBit) {
  const mjModel* m = Scene();
  std::string error;
  // Trial A publishes its follow start; trial B (other law and seed) runs from scratch and, as C,
  // from A's follow start.
  const TrialConfig a_config = SharedApproachConfig(70, 1, 5, 1);
  const TrialConfig b_config = SharedApproachConfig(150, 3, 7.5, 2);
  ASSERT_EQ(ApproachKeyOf(a_config), ApproachKeyOf(b_config));
  DataPtr da = MakeData(m, &error), db = MakeData(m, &error), dc = MakeData(m, &error);
  auto a = ContourTrial::Create(m, da.get(), a_config, false, &error);
  auto b = ContourTrial::Create(m, db.get(), b_config, false, &error);
  auto c = ContourTrial::Create(m, dc.get(), b_config, false, &error);
  ASSERT_TRUE(a && b && c) << error;
  ASSERT_TRUE(a->RunToFollowStart());
  ASSERT_TRUE(b->RunToFollowStart());
  c->ResumeAtFollowStart(da.get(), a->SaveFollowStart());
  EXPECT_EQ(c->phase(), TrialPhase::kFollow);
  ExpectSameData(m, db.get(), dc.get());
  // The seeds' noise differs (so the comparison above could fail).
  const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m, da.get());
  EXPECT_NE(da->sensordata[sensor->sensor_adr()], db->sensordata[sensor->sensor_adr()]);
  const TrialResult rb = b->Run(), rc = c->Run();
  EXPECT_EQ(SweepCsvRow("s", b_config, 0, rb), SweepCsvRow("s", b_config, 0, rc));
  EXPECT_EQ(rb.hold_height_m, rc.hold_height_m);
  EXPECT_EQ(b->path(), c->path());
  ExpectSameData(m, db.get(), dc.get());
}

TEST(SharedApproachTest, CacheSimulatesEachApproachOnceAndKeysOnWhatTheApproachReads) {
  const mjModel* m = Scene();
  ApproachCache cache(m);
  EXPECT_EQ(cache.unshareable_reason(), "");
  std::string error;
  const TrialConfig first = SharedApproachConfig(70, 1, 5, 1);
  TrialConfig other_law = SharedApproachConfig(200, 0.5, 2.5, 9);
  other_law.control_period_s = 0.25;
  other_law.timeout_s = 2;
  EXPECT_EQ(ApproachKeyOf(first), ApproachKeyOf(other_law));
  TrialConfig other_force = first;
  other_force.approach_force_n = 2.0;
  EXPECT_NE(ApproachKeyOf(first), ApproachKeyOf(other_force));
  TrialConfig other_start = first;
  other_start.target.start[0] += 1e-3;
  EXPECT_NE(ApproachKeyOf(first), ApproachKeyOf(other_start));
  TrialConfig other_smoothing = first;
  other_smoothing.servo.smoothing_s = 0.1;
  EXPECT_NE(ApproachKeyOf(first), ApproachKeyOf(other_smoothing));
  TrialConfig other_slip = first;
  other_slip.effects.lip.slip_mm = 0.5;
  EXPECT_NE(ApproachKeyOf(first), ApproachKeyOf(other_slip));

  const TrialResult scratch = RunTrial(m, other_law, false, &error);
  RunTrialShared(m, first, &cache, &error);
  const TrialResult shared = RunTrialShared(m, other_law, &cache, &error);
  RunTrialShared(m, other_force, &cache, &error);
  EXPECT_EQ(cache.counts().simulated, 2);
  EXPECT_EQ(cache.counts().resumed, 1);
  EXPECT_EQ(cache.counts().unshared, 0);
  EXPECT_EQ(SweepCsvRow("s", other_law, 0, scratch), SweepCsvRow("s", other_law, 0, shared));
}

TEST(SweepTest, ParallelSweepGivesTheSameRowsAsSerialAndResumes) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("ssc_sweep_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  SweepSpec spec;
  spec.scene_name = "disk_benchmark_gantry";
  spec.base.timeout_s = 4;  // short trials: this tests the machinery, not the outcomes
  spec.pref_pa = {70, 100};
  spec.beta = {1.0, 2.0};
  spec.step_mm = {7.5};
  spec.repeats = 1;
  spec.seed = 3;
  SweepSummary summary;
  std::string error;
  spec.threads = 1;
  spec.out_csv = (dir / "serial.csv").string();
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  EXPECT_EQ(summary.ran, 4);
  spec.threads = 2;
  spec.out_csv = (dir / "parallel.csv").string();
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  const auto serial = SortedRows((dir / "serial.csv").string());
  EXPECT_EQ(serial.size(), 5u);  // header + 4
  EXPECT_EQ(serial, SortedRows((dir / "parallel.csv").string()));
  // The manifest names the scene and the project's default scene (chosen by ssc equivalence).
  SweepManifest manifest;
  std::ifstream json_file((dir / "parallel.json").string());
  const std::string json((std::istreambuf_iterator<char>(json_file)),
                         std::istreambuf_iterator<char>());
  ASSERT_TRUE(ParseSweepManifest(json, &manifest, &error)) << error;
  EXPECT_EQ(manifest["scene"], "disk_benchmark_gantry");
  EXPECT_EQ(manifest["default_scene"], DefaultScene());
  // Re-running resumes: nothing left to run, no duplicate rows.
  ASSERT_TRUE(RunSweep(Scene(), spec, nullptr, &summary, &error)) << error;
  EXPECT_EQ(summary.ran, 0);
  EXPECT_EQ(summary.skipped, 4);
  EXPECT_EQ(SortedRows((dir / "parallel.csv").string()).size(), 5u);
  std::filesystem::remove_all(dir);
}

TEST(SweepTest, ASceneThatCannotHostATrialIsAnErrorNotRowsOfUnstable) {
  // Before the check, every trial of such a sweep was written as an "unstable" row and the
  // study reported figures on them (a scene whose F/T sensor had been renamed did this).
  const auto dir =
      std::filesystem::temp_directory_path() / ("ssc_sweep_bare_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string xml = (dir / "bare.xml").string();
  std::ofstream(xml) << "<mujoco><worldbody><body><joint type='slide'/>"
                        "<geom size='0.01'/></body></worldbody></mujoco>";
  std::string error;
  ModelPtr bare = LoadModel(xml, &error);
  ASSERT_TRUE(bare) << error;
  SweepSpec spec;
  spec.scene_name = "bare";
  spec.pref_pa = {100};
  spec.beta = {2.0};
  spec.step_mm = {5};
  spec.out_csv = (dir / "sweep.csv").string();
  SweepSummary summary;
  EXPECT_FALSE(RunSweep(bare.get(), spec, nullptr, &summary, &error));
  EXPECT_NE(error.find("cannot run a trial"), std::string::npos) << error;
  EXPECT_NE(error.find("chamber_pressure"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(spec.out_csv));
  std::filesystem::remove_all(dir);
}

// Counts calls per mjData.
class Counter : public ControlCallback {
 public:
  void Control(const mjModel*, mjData* d) override {
    ++calls;
    last = d;
  }
  int calls = 0;
  const mjData* last = nullptr;
};

TEST(ControlDispatchTest, EachDataReachesItsOwnControllerAcrossThreads) {
  const mjModel* m = Scene();
  mjData* a = mj_makeData(m);
  mjData* b = mj_makeData(m);
  mjData* none = mj_makeData(m);
  Counter ca, cb;
  {
    ScopedControl ra(a, &ca), rb(b, &cb);
    ASSERT_TRUE(ra.ok() && rb.ok());
    std::thread ta([&] {
      for (int i = 0; i < 200; ++i) mj_step(m, a);
    });
    std::thread tb([&] {
      for (int i = 0; i < 300; ++i) mj_step(m, b);
    });
    ta.join();
    tb.join();
    for (int i = 0; i < 50; ++i) mj_step(m, none);
  }
  EXPECT_EQ(ca.calls, 200);
  EXPECT_EQ(cb.calls, 300);
  EXPECT_EQ(ca.last, a);
  EXPECT_EQ(cb.last, b);
  mj_step(m, a);  // unregistered now
  EXPECT_EQ(ca.calls, 200);
  mj_deleteData(a);
  mj_deleteData(b);
  mj_deleteData(none);
}

}  // namespace
}  // namespace ssc

namespace ssc {
namespace {

TEST(TrialEndsTest, TimeoutWhenTheFollowPhaseRunsOutOfTime) {
  TrialConfig c;
  c.timeout_s = 1.0;
  const TrialResult r = Trial(100, 2.0, 2.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kTimeout) << r.detail;
}

TEST(TrialEndsTest, AnUnreachableStartPointEndsTheTrialInsteadOfWaitingForEver) {
  // The gantry's x servo stops at 2 m: a start 1.5 m east of the disk (x = 2.15 m) is never
  // reached. Before the reach limit the trial waited for it without end (a hang).
  TrialConfig c;
  c.target = TrialTarget::Disk(0.65, 0, 0.035, 1.5, DiskLanding::kAtCentre);
  const TrialResult r = Trial(100, 2.0, 7.5, 1, c);
  EXPECT_EQ(r.outcome, Outcome::kTimeout) << r.detail;
  EXPECT_NE(r.detail.find("did not reach the start point (2.1500, 0.0000) m"), std::string::npos)
      << r.detail;
  // Landing there (the default), the landing point is the one never reached.
  c.target = TrialTarget::Disk(0.65, 0, 0.035, 1.5);
  const TrialResult landing = Trial(100, 2.0, 7.5, 1, c);
  EXPECT_NE(landing.detail.find("did not reach the landing point (2.1500, 0.0000) m"),
            std::string::npos)
      << landing.detail;
  EXPECT_LT(landing.sim_time_s, 1.5 / c.move_speed_m_s + 5 + 5) << "waited too long";
  // The target travels 1.5 m at the move speed, then the tool gets 5 s to arrive (+ approach).
  EXPECT_LT(r.sim_time_s, 1.5 / c.move_speed_m_s + 5 + 5) << "waited too long";
  // A reachable one (1 m east) is reached: the limit does not cut normal moves short.
  c.target = TrialTarget::Disk(0.65, 0, 0.035, 1.0);
  c.timeout_s = 0.5;
  const TrialResult far = Trial(100, 2.0, 7.5, 1, c);
  EXPECT_EQ(far.detail.find("did not reach"), std::string::npos) << far.detail;
}

TEST(TrialEndsTest, AControlPeriodLongerThanTheTimeoutIsRefused) {
  TrialConfig c;
  c.timeout_s = 1;
  c.control_period_s = 1;
  EXPECT_EQ(c.Validate(), "");
  c.control_period_s = 1.5;
  EXPECT_NE(c.Validate().find("longer than timeout_s"), std::string::npos) << c.Validate();
}

// mj_step in two parts (runtime/deferred_sensor_step.h): with the acceleration-stage sensors
// asked for, every step is mj_step's to the bit; without, the physics goes on the same and only
// the F/T's reading stays the last one evaluated.
TEST(DeferredSensorStepTest, AskedForItIsMjStepToTheBitWithoutItOnlyTheFtLags) {
  const mjModel* m = Scene();
  ASSERT_TRUE(CanDeferAccSensors(m));
  std::string error;
  DataPtr da = MakeData(m, &error), db = MakeData(m, &error);
  ASSERT_TRUE(da && db) << error;
  for (mjData* d : {da.get(), db.get()}) {
    mj_resetDataKeyframe(m, d, 0);
    d->ctrl[2] -= 0.006;  // the gantry presses the cup onto the disk: the F/T reading moves
  }
  const int ft = m->sensor_adr[mj_name2id(m, mjOBJ_SENSOR, kToolForceSensorName)];
  auto split_step = [&](bool acc_sensors) {
    const mjtNum start = StepToAccSensors(m, db.get());
    FinishStep(m, db.get(), acc_sensors, start);
  };
  for (int i = 0; i < 400; ++i) {
    mj_step(m, da.get());
    split_step(true);
  }
  ExpectSameData(m, da.get(), db.get());
  for (int i = 0; i < 6 * m->nbody; ++i) {
    ASSERT_EQ(da->cfrc_int[i], db->cfrc_int[i]) << i;
  }
  const double ft_z = db->sensordata[ft + 2];
  for (int i = 0; i < 20; ++i) {
    mj_step(m, da.get());
    split_step(false);
  }
  EXPECT_EQ(db->sensordata[ft + 2], ft_z);  // not evaluated: the last reading
  EXPECT_NE(da->sensordata[ft + 2], ft_z);  // (it did move)
  for (int i = 0; i < m->nsensordata; ++i) {
    if (i < ft || i >= ft + 6) {
      EXPECT_EQ(da->sensordata[i], db->sensordata[i]) << i;
    }
  }
  for (int i = 0; i < m->nq; ++i) EXPECT_EQ(da->qpos[i], db->qpos[i]) << i;
  for (int i = 0; i < m->nv; ++i) EXPECT_EQ(da->qvel[i], db->qvel[i]) << i;
  mj_step(m, da.get());
  split_step(true);  // one evaluation brings it back
  ExpectSameData(m, da.get(), db.get());
}

// The flex skirt's scene integrates with the discrete map: the split step is mj_step's to the bit
// there too, through the skirt's contacts, its seal and the chambers' vacuum loading it.
TEST(DeferredSensorStepTest, UnderTheDiscreteIntegratorTheSplitStepIsMjStepToTheBit) {
  std::string error;
  ModelPtr flex = LoadModel(SourceDir() + "/scenes/disk_benchmark_flex.xml", &error);
  ASSERT_TRUE(flex) << error;
  const mjModel* m = flex.get();
  ASSERT_EQ(m->opt.integrator, mjINT_DISCRETE);
  ASSERT_TRUE(CanDeferAccSensors(m));
  DataPtr da = MakeData(m, &error), db = MakeData(m, &error);
  ASSERT_TRUE(da && db) << error;
  for (mjData* d : {da.get(), db.get()}) {
    mj_resetDataKeyframe(m, d, 0);
    d->ctrl[2] -= 0.0055;  // the lip 0.5 mm into the disk: it seals
  }
  const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m, da.get());
  ASSERT_NE(sensor, nullptr);
  const int pressure = sensor->sensor_adr();
  auto both = [&](int steps) {
    for (int i = 0; i < steps; ++i) {
      mj_step(m, da.get());
      const mjtNum start = StepToAccSensors(m, db.get());
      FinishStep(m, db.get(), true, start);
    }
  };
  both(150);
  EXPECT_GT(da->sensordata[pressure], 10000);  // sealed: the vacuum loads the skirt
  ExpectSameData(m, da.get(), db.get());
  for (mjData* d : {da.get(), db.get()}) d->ctrl[0] += 0.033;  // 2 mm inside the edge: it leaks
  both(150);
  EXPECT_LT(da->sensordata[pressure], 10000);
  ExpectSameData(m, da.get(), db.get());
}

// The approach on the skirt (the flex tier), to the end of the approach: the depth the lip
// plane is held below the disk's top and what the F/T read there.
struct SkirtLanding {
  double press_mm = 0, ft_n = 0;
};
SkirtLanding LandOnTheSkirt(const mjModel* flex, DiskLanding landing) {
  std::string error;
  DataPtr d = MakeData(flex, &error);
  EXPECT_TRUE(d) << error;
  TrialConfig c;
  c.target = TrialTarget::Disk(kWorkspaceX, kWorkspaceY, kBenchmarkDiskRadiusM,
                               kBenchmarkStartOffsetM, landing);
  auto trial = ContourTrial::Create(flex, d.get(), c, true, &error);
  EXPECT_TRUE(trial) << error;
  if (!trial) return {};
  while (trial->phase() == TrialPhase::kApproach && trial->Step()) {
  }
  EXPECT_NE(trial->phase(), TrialPhase::kDone) << trial->result().detail;
  return {(c.target.surface_top_z_m - trial->result().hold_height_m) * 1e3,
          trial->result().log.back().ft_normal_n};
}

// Landed where it starts (3 mm inside the edge: the skirt leaks, the vacuum pulls little) the
// skirt carries the preload above its depth limit (lip_max_press_mm 3 mm; measured 2.65 mm at
// 1.5 N). Landed on the centre it seals and its vacuum pulls the cup down harder than the
// disk pushes back: the F/T never reads the preload and the approach ends at the limit.
TEST(TrialTest, OnTheSkirtTheApproachReadsThePreloadWhereTheLabLandsIt) {
  std::string error;
  ModelPtr flex = LoadModel(SourceDir() + "/scenes/disk_benchmark_flex.xml", &error);
  ASSERT_TRUE(flex) << error;
  const SkirtLanding start = LandOnTheSkirt(flex.get(), DiskLanding::kAtStart);
  // (The log's last approach row is up to one log period before the trigger: 1.42 N.)
  EXPECT_GE(start.ft_n, 1.3);
  EXPECT_LT(start.press_mm, 2.9);  // ended by the force, not the limit
  EXPECT_GT(start.press_mm, 1.0);  // deeper than the segment lip's 1.0 mm: a softer lip
  const SkirtLanding centre = LandOnTheSkirt(flex.get(), DiskLanding::kAtCentre);
  EXPECT_LT(centre.ft_n, 1.5);
  EXPECT_GT(centre.press_mm, 2.99);
}

// What each control iteration of a trial read from the F/T, recorded around the control callback.
struct IterationReads {
  const ContourTrial* trial = nullptr;
  int ft_adr = 0;
  std::vector<std::pair<double, double>> reads{};  // (time, F/T z) at each iteration
  int follow_steps = 0, new_readings = 0;          // while following
  double last_ft = 0;
};
IterationReads* g_reads = nullptr;
mjfGeneric g_dispatch = nullptr;
void RecordingControl(const mjModel* m, mjData* d) {
  IterationReads& r = *g_reads;
  const int before = r.trial->result().iterations;
  const bool following = r.trial->phase() == TrialPhase::kFollow;
  const double ft = d->sensordata[r.ft_adr + 2];
  g_dispatch(m, d);
  if (r.trial->result().iterations != before) r.reads.emplace_back(d->time, ft);
  if (following) {
    ++r.follow_steps;
    if (ft != r.last_ft) ++r.new_readings;
  }
  r.last_ft = ft;
}

// A trial run for its result only evaluates the F/T on few steps, yet every control iteration
// reads what mj_step would have given it, and the row, the path and the final state are the
// same to the bit (iterations every 0.15 s with jitter and a pose delay, and at every step).
TEST(DeferredSensorStepTest, AResultOnlyRunReadsTheSameFtAtEveryIteration) {
  std::string error;
  ModelPtr light = LoadModel(SourceDir() + "/scenes/disk_benchmark_light.xml", &error);
  ASSERT_TRUE(light) << error;
  TrialConfig jittered = SharedApproachConfig(100, 2, 5, 4);
  ASSERT_TRUE(ParseRobotEffects("jitter_s=0.02,pose_delay_s=0.03,slip_mm=1,drift_pa=1",
                                &jittered.effects, &error))
      << error;
  TrialConfig every_step = SharedApproachConfig(100, 2, 5, 5);
  every_step.effects = RobotEffectsParams();
  every_step.control_period_s = 0.002;
  every_step.timeout_s = 0.5;
  for (const mjModel* m : {Scene(), static_cast<const mjModel*>(light.get())}) {
    for (const TrialConfig& c : {jittered, every_step}) {
      DataPtr da = MakeData(m, &error), db = MakeData(m, &error);
      auto a = ContourTrial::Create(m, da.get(), c, false, &error);
      auto b = ContourTrial::Create(m, db.get(), c, false, &error);
      ASSERT_TRUE(a && b) << error;
      b->SetResultOnly(true);
      const int ft = m->sensor_adr[mj_name2id(m, mjOBJ_SENSOR, kToolForceSensorName)];
      IterationReads ra{a.get(), ft}, rb{b.get(), ft};
      g_dispatch = mjcb_control;
      mjcb_control = RecordingControl;
      g_reads = &ra;
      const TrialResult result_a = a->Run();
      g_reads = &rb;
      const TrialResult result_b = b->Run();
      mjcb_control = g_dispatch;
      ASSERT_FALSE(ra.reads.empty());
      EXPECT_EQ(ra.reads, rb.reads);
      EXPECT_EQ(SweepCsvRow("s", c, 0, result_a), SweepCsvRow("s", c, 0, result_b));
      EXPECT_EQ(a->path(), b->path());
      ExpectSameData(m, da.get(), db.get());
      // While following, the F/T was evaluated on few steps (on every one when iterating at
      // every step); mj_step gives a new reading at nearly every step.
      EXPECT_GT(ra.new_readings, ra.follow_steps * 9 / 10);
      if (c.control_period_s > 0.1) {
        EXPECT_LT(rb.new_readings, rb.follow_steps / 10)
            << rb.new_readings << " new readings in " << rb.follow_steps << " steps";
      } else {
        EXPECT_EQ(rb.new_readings, ra.new_readings);
      }
    }
  }
}

// Our handler leaves out only MuJoCo's note that a flex M+K solve ran out of iterations and the
// inertia warning raised right after it for that solve.
TEST(MuJoCoMessagesTest, OnlyTheFlexSolveNoteAndItsInertiaWarningAreLeftOut) {
  bool after = false;
  EXPECT_TRUE(PrintsMuJoCoWarning("Nan, Inf or huge value in QACC at DOF 3.", &after));
  EXPECT_FALSE(PrintsMuJoCoWarning(
      "Flex stiffness is too ill-conditioned for the effective-metric block preconditioner: the "
      "M+K solve ran out of iterations at a relative residual of 2.46e-01",
      &after));
  EXPECT_FALSE(PrintsMuJoCoWarning(
      "Inertia matrix is too close to singular, or the effective-metric solve failed to "
      "converge, at DOF 2. Check model. Time = 0.0000.",
      &after));
  // The same inertia warning on its own (a singular mass matrix) is printed.
  EXPECT_TRUE(PrintsMuJoCoWarning(
      "Inertia matrix is too close to singular, or the effective-metric solve failed to "
      "converge, at DOF 2. Check model. Time = 0.0000.",
      &after));
  EXPECT_FALSE(PrintsMuJoCoWarning(
      "Flex stiffness is too ill-conditioned for the effective-metric block preconditioner",
      &after));
  EXPECT_TRUE(PrintsMuJoCoWarning("Pre-allocated constraint buffer is full.", &after));
  EXPECT_TRUE(PrintsMuJoCoWarning(
      "Inertia matrix is too close to singular, or the effective-metric solve failed to "
      "converge, at DOF 5. Check model.",
      &after));
}

// The flex scene caps opt.iterations below what its M+K solve needs (docs/flex_cost.md, "Cost of
// the flex tier"): its trial steps without printing that note.
TEST(TrialEndsTest, TheFlexSceneStepsWithoutTheFlexSolveNote) {
  std::string error;
  ModelPtr flex = LoadModel(SourceDir() + "/scenes/disk_benchmark_flex.xml", &error);
  ASSERT_TRUE(flex) << error;
  DataPtr d = MakeData(flex.get(), &error);
  ASSERT_TRUE(d) << error;
  testing::internal::CaptureStderr();  // MuJoCo prints a warning at its first raise: the reset
  auto trial = ContourTrial::Create(flex.get(), d.get(), TrialConfig{}, false, &error);
  if (trial) trial->Run(0.3);
  const std::string printed = testing::internal::GetCapturedStderr();
  ASSERT_TRUE(trial) << error;
  if (d->warning[mjWARN_INERTIA].number == 0)
    GTEST_SKIP() << "the scene's M+K solve no longer caps";
  EXPECT_EQ(printed.find("ill-conditioned"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("too close to singular"), std::string::npos) << printed;
  EXPECT_NE(trial->result().outcome, Outcome::kUnstable) << trial->result().detail;
}

TEST(TrialEndsTest, DivergingSimulationIsUnstableNotAControllerResult) {
  // A copy of the scene with a time step far beyond what the lip springs tolerate.
  mjModel* m = mj_copyModel(nullptr, Scene());
  m->opt.timestep = 0.2;
  m->opt.integrator = mjINT_EULER;
  std::string error;
  const TrialResult r = RunTrial(m, TrialConfig{}, false, &error);
  EXPECT_EQ(r.outcome, Outcome::kUnstable) << r.detail;
  mj_deleteModel(m);
}

}  // namespace
}  // namespace ssc
