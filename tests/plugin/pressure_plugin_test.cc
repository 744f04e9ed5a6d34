// The pressure sensor plugin inside MuJoCo: the cup held by a mocap body over a plate edge
// (scenes/probe_edge.xml).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "geometry/dimensions.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "studies/edge_probe.h"
#include "studies/tool_variants.h"

namespace ssc {
namespace {

constexpr double kSurfaceZ = 0.010;      // plate top, m
constexpr double kCompression = 1.0e-3;  // lip plane below the plate top, m
constexpr double kSettle = 0.08;         // s

std::string ProbeScene() { return SourceDir() + "/scenes/probe_edge.xml"; }

std::unique_ptr<EdgeProbe3d> MakeProbe() {
  std::string error;
  auto probe = EdgeProbe3d::Create(ProbeScene(), &error);
  EXPECT_TRUE(probe) << error;
  return probe;
}

// Cup centre `offset_m` inside the plate's edge (the plate covers world x < 0).
ProbeReading AtOffset(EdgeProbe3d& probe, double offset_m, double yaw = 0) {
  return probe.Read(-offset_m, 0.0, yaw, kSurfaceZ, kCompression, kSettle);
}

// The sensor noise band of a filtered reading: 5 sigma of the mean of the 7-sample window
// (6 Pa per sample): 5 * 6 / sqrt(7) = 11.3 Pa per chamber, half that for the mean of four.
constexpr double kChamberNoiseBandPa = 11.3;
constexpr double kMeanNoiseBandPa = 5.7;

TEST(PressurePluginTest, CupInAirReadsTheOpenCupValue) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  const ProbeReading r = probe->Read(0.0, 0.0, 0.0, 0.2, 0.0, 0.2);  // 20 cm above the table
  EXPECT_EQ(r.lip_contacts, 0);
  const double quadrant_mm2 = 0.25 * M_PI * 5.5 * 5.5;
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(r.sealed_area_mm2[c], 0.0, 1e-9) << "chamber " << c + 1;
    // The open quadrant plus the lip's roughness gap, counted all round by the leak model.
    const double rough_mm2 = 0.5 * M_PI * 5.5 * 18e-3;
    EXPECT_NEAR(r.leak_area_mm2[c], quadrant_mm2 + rough_mm2, 1e-6) << "chamber " << c + 1;
    // The network's reading for these four open quadrants (flow_network_test: OpenCup).
    EXPECT_NEAR(r.static_pa[c], 0.2527, 0.0005) << "chamber " << c + 1;
  }
  EXPECT_NEAR(r.pbar_pa, r.static_pbar_pa, kMeanNoiseBandPa);
}

// Every probe tier's scene has the study's layout: the check looks through the tool, including
// a flex tool held to its mocap body by a constraint (it stays over the plate when lifted).
TEST(PressurePluginTest, EveryProbeTiersSceneHasTheStudysLayout) {
  int probes = 0;
  for (const RigTier& tier : RigTiers()) {
    if (tier.kind != RigKind::kProbe) continue;
    ++probes;
    std::string error;
    auto probe =
        EdgeProbe3d::Create(SourceDir() + "/scenes/" + std::string(tier.scene) + ".xml", &error);
    ASSERT_TRUE(probe) << tier.scene << ": " << error;
    EXPECT_EQ(probe->CheckStudyLayout(), "") << tier.scene;
  }
  EXPECT_GE(probes, 2);  // the segment lip's and the flex skirt's
}

TEST(PressurePluginTest, CupOnPlateReadsTheSealedValueInEveryChamber) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  const ProbeReading r = AtOffset(*probe, 0.03);
  EXPECT_EQ(r.lip_contacts, 16);
  // Every segment on the plate: each quadrant leaks through a quarter of the lip times the
  // 18 um roughness gap; that air enters as a sheet (no tap recovery), so the taps read the
  // chamber vacuum, 25644 Pa (flow_network_test: SealedCupOnAPlate).
  const double rough_mm2 = 0.5 * M_PI * 5.5 * 18e-3;
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(r.leak_area_mm2[c], rough_mm2, 1e-3 * rough_mm2) << "chamber " << c + 1;
    EXPECT_NEAR(r.static_pa[c], 25644, 1) << "chamber " << c + 1;
    EXPECT_NEAR(r.filtered_pa[c], r.static_pa[c], kChamberNoiseBandPa) << "chamber " << c + 1;
  }
}

TEST(PressurePluginTest, AcrossAStraightEdgeMeanRisesAndPointsAtThePlate) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  double previous = -1;
  for (double mm = -5.0; mm <= 5.0 + 1e-9; mm += 0.5) {
    const ProbeReading r = AtOffset(*probe, mm * 1e-3);
    EXPECT_GE(r.static_pbar_pa, previous - 0.5) << "offset " << mm << " mm";
    previous = r.static_pbar_pa;
    if (std::hypot(r.dpx_pa, r.dpy_pa) > 30) {
      // g points toward the covered side: the plate lies toward world -x (180 deg).
      const double err = std::remainder(r.g_world_rad - M_PI, 2 * M_PI);
      EXPECT_LT(std::fabs(err), 10 * M_PI / 180) << "offset " << mm << " mm";
    }
  }
  EXPECT_GT(previous, 1000.0);
}

TEST(PressurePluginTest, DirectionFollowsTheEdgeTangentAtEveryRotation) {
  // The tool turns in 15 degree steps relative to the edge; travel (object on the left) must
  // follow the edge tangent (world +y, 90 deg) within 20 degrees.
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  for (int k = 0; k < 24; ++k) {
    const double yaw = k * 15.0 * M_PI / 180;
    const ProbeReading r = AtOffset(*probe, 2.5e-3, yaw);
    const double err = std::remainder(r.travel_world_rad - M_PI / 2, 2 * M_PI) * 180 / M_PI;
    EXPECT_LT(std::fabs(err), 20.0) << "tool yaw " << k * 15 << " deg";
  }
}

double OffsetForMean(EdgeProbe3d& probe, double target_pa) {
  double lo = -2e-3, hi = 5.5e-3;
  for (int i = 0; i < 16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (AtOffset(probe, mid).static_pbar_pa < target_pa ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(PressurePluginTest, CalibrationPointsOfThePublishedDiskResults) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  EXPECT_NEAR(OffsetForMean(*probe, 40) * 1e3, 0.7, 0.3);
  const double d100 = OffsetForMean(*probe, 100);
  EXPECT_NEAR(d100 * 1e3, 2.5, 0.3);
  EXPECT_NEAR(OffsetForMean(*probe, 200) * 1e3, 3.2, 0.3);
  // Differential near P = 100 Pa: about 200 Pa, the side over the edge near zero.
  const ProbeReading r = AtOffset(*probe, d100);
  EXPECT_NEAR(std::hypot(r.dpx_pa, r.dpy_pa), 200.0, 40.0);
  const auto& p = r.static_pa;  // the plate is to the west: chambers 3, 4 covered
  EXPECT_LT(0.5 * (p[0] + p[1]), 15.0);
  EXPECT_GT(0.5 * (p[2] + p[3]), 150.0);
}

TEST(PressurePluginTest, ForwardAtTheSameTimeChangesNothing) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  AtOffset(*probe, 2.5e-3);
  const mjModel* m = probe->model();
  mjData* d = probe->data();
  std::vector<double> before(d->sensordata, d->sensordata + 4);
  const std::vector<double> state(d->plugin_state, d->plugin_state + m->npluginstate);
  for (int i = 0; i < 5; ++i) mj_forward(m, d);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(d->sensordata[c], before[c]);
  for (int i = 0; i < m->npluginstate; ++i) EXPECT_EQ(d->plugin_state[i], state[i]);
}

std::vector<double> StepAndRecord(const mjModel* m, mjData* d, int steps) {
  std::vector<double> out;
  for (int i = 0; i < steps; ++i) {
    mj_step(m, d);
    out.insert(out.end(), d->sensordata, d->sensordata + 4);
  }
  return out;
}

TEST(PressurePluginTest, DeterministicAcrossResetAndCopy) {
  auto probe = MakeProbe();
  ASSERT_TRUE(probe);
  const mjModel* m = probe->model();
  mjData* d = probe->data();
  AtOffset(*probe, 2.0e-3);  // place the cup; then reset the dynamic state but keep the mocap
  mj_resetData(m, d);
  d->mocap_pos[0] = -2.0e-3;
  d->mocap_pos[2] = kSurfaceZ - kCompression + kToolCentreOffsetM;
  const auto first = StepAndRecord(m, d, 300);
  mj_resetData(m, d);
  d->mocap_pos[0] = -2.0e-3;
  d->mocap_pos[2] = kSurfaceZ - kCompression + kToolCentreOffsetM;
  const auto second = StepAndRecord(m, d, 150);
  mjData* copy = mj_copyData(nullptr, m, d);
  const auto tail_original = StepAndRecord(m, d, 150);
  const auto tail_copy = StepAndRecord(m, copy, 150);
  mj_deleteData(copy);
  for (size_t i = 0; i < second.size(); ++i) ASSERT_EQ(first[i], second[i]) << i;
  for (size_t i = 0; i < tail_original.size(); ++i) {
    ASSERT_EQ(tail_original[i], tail_copy[i]) << i;
    ASSERT_EQ(tail_original[i], first[second.size() + i]) << i;
  }
}

// The tool model with one config entry, compiled in memory: "" or the load error.
std::string LoadWithConfig(const std::string& key, const std::string& value) {
  std::string error;
  ModelPtr model = ToolModelVariant(SourceDir() + "/models/ssc_tool.xml", {{key, value}}, &error);
  return model ? "" : error;
}

TEST(PressurePluginTest, BadConfigFailsTheLoadNamingKeyValueAndRange) {
  struct Case {
    const char* key;
    const char* value;
    const char* expect;  // must appear in the message
  };
  const Case cases[] = {
      {"open_depth_mm", "-1", "[0.05, 10] mm"},    {"lip_shear_n_per_mm", "-0.5", "[0, 100] N/mm"},
      {"port_area_mm2", "-3", "(0, 10000] mm^2"},  {"noise_pa", "nan", "noise_pa"},
      {"rays_per_chamber", "2.5", "whole number"}, {"sample_rate_hz", "fast", "sample_rate_hz"},
      {"ray_groups", "0 9", "ray_groups"},         {"ray_groups", "4", "lip_geom_group"},
      {"unknown_key", "1", "unknown_key"},         {"noise_pa", "", "empty value"},
      {"noise_pa", "0x10", "[0, 10000] Pa"},       {"sample_rate_hz", "1e400", "sample_rate_hz"},
  };
  for (const Case& c : cases) {
    const std::string error = LoadWithConfig(c.key, c.value);
    ASSERT_FALSE(error.empty()) << c.key << "=" << c.value << " loaded";
    EXPECT_NE(error.find(c.key), std::string::npos) << error;
    EXPECT_NE(error.find(c.expect), std::string::npos) << error;
    EXPECT_NE(error.find("ssc_tool.xml"), std::string::npos) << "names the file: " << error;
  }
}

// Loads the tool model with `from` replaced by `to` in its text; the load error or "".
std::string LoadEdited(const std::string& from, const std::string& to) {
  std::ifstream in(SourceDir() + "/models/ssc_tool.xml");
  std::stringstream buf;
  buf << in.rdbuf();
  std::string xml = buf.str();
  const size_t at = xml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return "edit not applied";
  xml.replace(at, from.size(), to);
  const auto path = std::filesystem::temp_directory_path() /
                    ("ssc_bad_tool_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << xml;
  std::string error;
  ModelPtr model = LoadModel(path.string(), &error);
  std::filesystem::remove(path);
  return model ? "" : error;
}

TEST(PressurePluginTest, MissingSiteOrLipIsReported) {
  // The plugin's own checks, not MuJoCo's compiler: the messages carry the plugin's name.
  // A sensor on a body instead of the tool site (a valid MJCF that MuJoCo compiles).
  const std::string on_body =
      LoadEdited("objtype=\"site\" objname=\"tool_site\"", "objtype=\"body\" objname=\"cup\"");
  ASSERT_FALSE(on_body.empty()) << "a pressure sensor on a body loaded";
  EXPECT_NE(on_body.find(kChamberPressurePluginName), std::string::npos) << on_body;
  EXPECT_NE(on_body.find("objtype=\"site\""), std::string::npos) << on_body;
  // No lip: the lip group names a group without geoms under the tool site's body.
  const std::string no_lip = LoadWithConfig("lip_geom_group", "5");
  ASSERT_FALSE(no_lip.empty()) << "a cup without lip segments loaded";
  EXPECT_NE(no_lip.find(kChamberPressurePluginName), std::string::npos) << no_lip;
  EXPECT_NE(no_lip.find("found 0 lip segment geoms (group 5)"), std::string::npos) << no_lip;
  // A site that does not exist is MuJoCo's compiler error; it must still fail the load.
  const std::string no_site = LoadEdited("objname=\"tool_site\"/>", "objname=\"no_such_site\"/>");
  EXPECT_NE(no_site.find("no_such_site"), std::string::npos) << no_site;
}

// The lip carrier on the gantry scene, pressed 1.5 N onto the disk and dragged 12 mm along it at
// 20 mm/s: returns the carrier's shear along the motion (m) and tilt (rad) at the end.
std::pair<double, double> ShearAndTiltWhileSliding(const PluginConfig& config) {
  std::string error;
  ModelPtr m = ToolModelVariant(SourceDir() + "/scenes/disk_benchmark_gantry.xml", config, &error);
  EXPECT_TRUE(m) << error;
  if (!m) return {0, 0};
  DataPtr d = MakeData(m.get(), &error);
  EXPECT_TRUE(d) << error;
  if (!d) return {0, 0};
  mj_resetDataKeyframe(m.get(), d.get(), 0);
  auto qpos_of = [&](const char* joint) {
    return d->qpos[m->jnt_qposadr[mj_name2id(m.get(), mjOBJ_JOINT, joint)]];
  };
  // The home keyframe holds the lip plane 5 mm above the disk: lower it 6 mm (1 mm of lip
  // compression, 1.5 N) and let it settle.
  for (int i = 0; i < 3; ++i) d->ctrl[i] = d->qpos[i];  // gantry x, y, z servos
  d->ctrl[2] -= 6e-3;
  while (d->time < 0.8) mj_step(m.get(), d.get());
  const double dt = m->opt.timestep;
  for (double t = 0; t < 0.6; t += dt) {
    d->ctrl[0] += 0.02 * dt;  // world +x = tool -y
    mj_step(m.get(), d.get());
  }
  return {-qpos_of("ssc_flex_shear_y"), qpos_of("ssc_flex_tilt_x")};
}

TEST(PressurePluginTest, SoftLipShearsAndTiltsUnderFrictionOnlyWhenSwitchedOn) {
  const auto rigid = ShearAndTiltWhileSliding({});
  EXPECT_LT(std::fabs(rigid.first), 1e-5);  // locked: today's rigid cup
  EXPECT_LT(std::fabs(rigid.second), 1e-4);
  const auto soft =
      ShearAndTiltWhileSliding({{"lip_shear_n_per_mm", "1"}, {"lip_tilt_nmm_per_deg", "5"}});
  // The lip lags the cup (friction ~ mu F_n ~ 1.5 N on 1 N/mm) and tilts a degree or more.
  EXPECT_LT(soft.first, -0.5e-3);
  EXPECT_GT(std::fabs(soft.second), 1.0 * M_PI / 180);
}

TEST(PressurePluginTest, TooStiffALipForTheTimeStepIsAClearError) {
  std::string error;
  ModelPtr m = ToolModelVariant(SourceDir() + "/scenes/disk_benchmark_gantry.xml",
                                {{"lip_shear_n_per_mm", "90"}}, &error);
  if (m) {
    DataPtr d = MakeData(m.get(), &error);
    EXPECT_FALSE(d);
  }
  EXPECT_NE(error.find("lip_shear_n_per_mm"), std::string::npos) << error;
  EXPECT_NE(error.find("time step"), std::string::npos) << error;
}

// The plugin's error when the scene with `config` cannot make its data; "" when it can.
std::string MakeDataError(const std::string& scene, const PluginConfig& config) {
  std::string error;
  ModelPtr m = ToolModelVariant(SourceDir() + "/scenes/" + scene, config, &error);
  if (!m) return error;
  DataPtr d = MakeData(m.get(), &error);
  return d ? "" : error;
}

TEST(PressurePluginTest, APressDeeperThanTheLipCanTakeIsRefusedAgainstTheToolsGeometry) {
  // The skirt: the chamber walls end 3.5 mm above the lip plane, the skirt is 1 mm thick.
  EXPECT_EQ(MakeDataError("disk_benchmark_flex.xml", {{"lip_max_press_mm", "3"}}), "");
  const std::string flex = MakeDataError("disk_benchmark_flex.xml", {{"lip_max_press_mm", "3.2"}});
  EXPECT_NE(flex.find("lip_max_press_mm = 3.2"), std::string::npos) << flex;
  EXPECT_NE(flex.find("wall_"), std::string::npos) << "names what lands: " << flex;
  EXPECT_NE(flex.find("at most 3 mm"), std::string::npos) << flex;
  // The segments: their slide joints travel 3 mm.
  EXPECT_EQ(MakeDataError("disk_benchmark_gantry.xml", {{"lip_max_press_mm", "3"}}), "");
  const std::string segments =
      MakeDataError("disk_benchmark_gantry.xml", {{"lip_max_press_mm", "3.5"}});
  EXPECT_NE(segments.find("slide joints travel 3 mm"), std::string::npos) << segments;
}

}  // namespace
}  // namespace ssc
