// Test objects: the exact edges (hand-computed distances and arc positions), the registry and
// trial set-ups, the fillet profile, the written MJCF against the analytic shapes (rays from
// above), rays against contacts on concave objects, the per-scene cost, and trials on a few
// objects through the set-up data.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "geometry/dimensions.h"
#include "objects/object_mjcf.h"
#include "objects/object_spec.h"
#include "runtime/mujoco_model.h"
#include "studies/object_step_cost.h"
#include "studies/object_trials.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;
constexpr double kMm = 1e-3;

fs::path SceneDirPath() {
  return fs::temp_directory_path() / ("ssc_objects_test_" + std::to_string(::getpid()));
}

// Every object's files, written once per test process.
const fs::path& SceneDir() {
  static const fs::path dir = [] {
    const fs::path d = SceneDirPath();
    std::string error;
    EXPECT_EQ(WriteAllObjectScenes(d.string(), SourceDir(), RigObjectSceneTemplates(), &error), 42)
        << error;
    return d;
  }();
  return dir;
}

// Removes the written files when the test process ends.
class SceneDirCleanup : public testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(SceneDirPath(), ec);
  }
};
[[maybe_unused]] testing::Environment* const kCleanup =
    testing::AddGlobalTestEnvironment(new SceneDirCleanup);

std::string FileOf(const std::string& name) {
  return (SceneDir() / ObjectFileNames(name).object).string();
}

struct Loaded {
  ModelPtr m;
  DataPtr d;
};

Loaded Load(const std::string& path) {
  Loaded l;
  std::string error;
  l.m = LoadModel(path, &error);
  EXPECT_TRUE(l.m) << error;
  if (l.m) {
    l.d = MakeData(l.m.get(), &error);
    EXPECT_TRUE(l.d) << error;
    mj_forward(l.m.get(), l.d.get());
  }
  return l;
}

// Height of the first surface in geom groups 0 and 2 under (x, y), by a ray from 0.1 m; NaN if
// there is none.
double SurfaceZ(const Loaded& l, double x, double y) {
  const mjtNum start[3] = {x, y, 0.1}, down[3] = {0, 0, -1};
  const mjtByte groups[mjNGROUP] = {1, 0, 1, 0, 0, 0};
  int geom = -1;
  const mjtNum t = mj_ray(l.m.get(), l.d.get(), start, down, groups, 1, -1, &geom, nullptr);
  return t < 0 ? NAN : 0.1 - t;
}

bool AtTop(double z) { return std::isfinite(z) && std::fabs(z - kObjectTopZ) < 5e-5; }

// ---------------------------------------------------------------------------------------------
// Exact edges.

TEST(ContourPathTest, LengthsOfArcsSpiralsAndSegments) {
  EXPECT_NEAR(MakeDisk(10).edge.Length(), 2 * kPi * 5 * kMm, 1e-12);
  EXPECT_NEAR(MakeHole(6).edge.Length(), 2 * kPi * 3 * kMm, 1e-12);
  EXPECT_NEAR(MakeCorner(90).edge.Length(), 120 * kMm, 1e-12);
  EXPECT_NEAR(MakeFillet().edge.Length(), 180 * kMm, 1e-12);
  // The spiral's closed-form length against a fine polyline (chord sum from below).
  const ContourPath& volute = MakeVolute().edge;
  const PathPiece& spiral = volute.pieces()[0];
  double chords = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double t0 = 2 * kPi * i / n, t1 = 2 * kPi * (i + 1) / n;
    const double r0 = 0.025 + 0.035 * t0 / (2 * kPi), r1 = 0.025 + 0.035 * t1 / (2 * kPi);
    chords +=
        std::hypot(r1 * std::cos(t1) - r0 * std::cos(t0), r1 * std::sin(t1) - r0 * std::sin(t0));
  }
  EXPECT_NEAR(spiral.Length(), chords, 1e-8);
  EXPECT_NEAR(volute.Length(), chords + 0.035, 1e-8);
  // Semicircle strip: flats 14 + 4 x 4 + 10 mm and semicircles pi d / 2.
  EXPECT_NEAR(MakeSemicircleStrip().edge.Length(), (40 + kPi / 2 * (44 + 28 + 18 + 11 + 7)) * kMm,
              1e-12);
  // Semi-square strip: flats, plus each d wide and twice d/2 tall.
  EXPECT_NEAR(MakeSemisquareStrip().edge.Length(), (40 + 2 * (44 + 28 + 18 + 11 + 7)) * kMm, 1e-12);
}

TEST(ContourPathTest, ArcPositionInvertsPointAt) {
  for (const char* name : {"disk_d06", "hole_d14", "corner_a045", "corner_a300", "volute",
                           "semicircle_strip", "semisquare_strip", "fillet"}) {
    const ObjectSpec spec = ObjectByName(name);
    const double length = spec.edge.Length();
    std::vector<double> junctions = {0};
    for (const PathPiece& piece : spec.edge.pieces()) {
      junctions.push_back(junctions.back() + piece.Length());
    }
    for (int i = 1; i < 50; ++i) {
      const double s = length * i / 50.0;
      // Near a corner an offset point may be closer to the next piece: not this check's case.
      bool near_corner = false;
      for (double j : junctions) near_corner |= std::fabs(s - j) < 0.5 * kMm;
      if (near_corner) continue;
      const Point2 p = spec.edge.PointAt(s), n = spec.edge.LeftNormalAt(s);
      EXPECT_NEAR(spec.ArcPosition(p[0], p[1]), s, 1e-8) << name << " s " << s;
      // Off the edge along its normal the arc position stays, the distance is the offset.
      const double off = 0.2 * kMm;
      const Point2 q = {p[0] + off * n[0], p[1] + off * n[1]};
      EXPECT_NEAR(spec.DistanceToContour(q[0], q[1]), -off, 1e-8) << name << " s " << s;
      const ContourProjection pr = spec.edge.ProjectWithin(q[0], q[1], s - 0.005, s + 0.005);
      EXPECT_NEAR(pr.arc_m, s, 1e-7) << name << " s " << s;
      const Point2 t = spec.edge.TangentAt(s);
      EXPECT_NEAR(std::hypot(t[0], t[1]), 1.0, 1e-12);
    }
  }
}

TEST(ContourPathTest, SignedDistanceByHand) {
  const double x = kWorkspaceX, y = kWorkspaceY;
  const ObjectSpec disk = MakeDisk(10);
  EXPECT_NEAR(disk.DistanceToContour(x + 7 * kMm, y), 2 * kMm, 1e-12);
  EXPECT_NEAR(disk.DistanceToContour(x, y), -5 * kMm, 1e-12);
  const ObjectSpec hole = MakeHole(10);  // the plate is the object
  EXPECT_NEAR(hole.DistanceToContour(x, y), 5 * kMm, 1e-12);
  EXPECT_NEAR(hole.DistanceToContour(x, y - 8 * kMm), -3 * kMm, 1e-12);
  // Convex corner (90 deg: the object is the north-west quadrant of the apex).
  const ObjectSpec convex = MakeCorner(90);
  EXPECT_NEAR(convex.DistanceToContour(x - 1 * kMm, y + 2 * kMm), -1 * kMm, 1e-12);
  EXPECT_NEAR(convex.DistanceToContour(x + 1 * kMm, y - 1 * kMm), std::sqrt(2.0) * kMm, 1e-12);
  EXPECT_NEAR(convex.DistanceToContour(x + 1 * kMm, y + 1 * kMm), 1 * kMm, 1e-12);
  // Concave corner (270 deg: everything but the south-west quadrant).
  const ObjectSpec concave = MakeCorner(270);
  EXPECT_NEAR(concave.DistanceToContour(x - 1 * kMm, y - 2 * kMm), 1 * kMm, 1e-12);
  EXPECT_NEAR(concave.DistanceToContour(x + 1 * kMm, y + 1 * kMm), -std::sqrt(2.0) * kMm, 1e-12);
  EXPECT_NEAR(concave.DistanceToContour(x + 1 * kMm, y - 3 * kMm), -1 * kMm, 1e-12);
  // Volute: either side of the straight step (x from 25 to 60 mm on the axis).
  const ObjectSpec volute = MakeVolute();
  EXPECT_NEAR(volute.DistanceToContour(x + 40 * kMm, y + 0.5 * kMm), 0.5 * kMm, 1e-9);
  EXPECT_NEAR(volute.DistanceToContour(x + 40 * kMm, y - 0.5 * kMm), -0.5 * kMm, 1e-9);
  // 1 mm radially outside at theta = pi: the spiral leans by atan(k / r) = 7.5 deg there.
  EXPECT_NEAR(volute.DistanceToContour(x - 43.5 * kMm, y), 0.9915 * kMm, 0.001 * kMm);
  // Strips: the first semicircle (44 mm) from its centre 36 mm west of W, and a point on the flat.
  const ObjectSpec strip = MakeSemicircleStrip();
  EXPECT_NEAR(strip.DistanceToContour(x - 36 * kMm, y + 25 * kMm), 3 * kMm, 1e-9);
  EXPECT_NEAR(strip.DistanceToContour(x - 5 * kMm, y - 2 * kMm), -2 * kMm, 1e-12);
  EXPECT_NEAR(strip.ArcPosition(x - 5 * kMm, y - 2 * kMm), 5 * kMm, 1e-12);
  const ObjectSpec fillet = MakeFillet();
  EXPECT_NEAR(fillet.DistanceToContour(x + 90 * kMm, y + 4 * kMm), -4 * kMm, 1e-12);
  EXPECT_NEAR(fillet.ArcPosition(x + 90 * kMm, y + 4 * kMm), 90 * kMm, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Registry and trial set-ups.

TEST(ObjectRegistryTest, PublishedSetWithStartsOnTheEdge) {
  const std::vector<ObjectSpec> all = AllObjects();
  ASSERT_EQ(all.size(), 42u);
  std::set<std::string> names;
  for (const ObjectSpec& spec : all) {
    SCOPED_TRACE(spec.name);
    EXPECT_TRUE(names.insert(spec.name).second);
    EXPECT_EQ(ObjectByName(spec.name).name, spec.name);
    EXPECT_FALSE(spec.pieces.empty());
    EXPECT_FALSE(spec.description.empty());
    const ObjectTrialSetup& t = spec.trial;
    EXPECT_TRUE(t.object_on_left);
    EXPECT_NEAR(std::hypot(t.follow_direction[0], t.follow_direction[1]), 1.0, 1e-12);
    // The start lies inside the edge by the inset (the small disks: over their centre).
    EXPECT_NEAR(spec.DistanceToContour(t.start_xy_m[0], t.start_xy_m[1]), -t.start_inset_m, 1e-9);
    const bool over_centre =
        spec.kind == ObjectKind::kDisk && t.start_inset_m >= 0.5e-3 * spec.param;
    if (!over_centre) {  // (over a disk's centre every edge point is closest)
      EXPECT_NEAR(spec.ArcPosition(t.start_xy_m[0], t.start_xy_m[1]), t.start_arc_m, 1e-7);
    }
    if (spec.closed()) {
      EXPECT_EQ(t.goal.kind, TrialGoal::Kind::kSweptAngle);
      // Counter-clockwise round disks and the volute, clockwise round holes.
      EXPECT_EQ(t.goal.sweep_deg, spec.kind == ObjectKind::kHole ? -355.0 : 355.0);
    } else {
      EXPECT_EQ(t.goal.kind, TrialGoal::Kind::kGoalPoint);
      EXPECT_GT(t.goal.goal_arc_m, t.start_arc_m + 0.05);
      EXPECT_LE(t.goal.goal_arc_m, spec.edge.Length());
    }
    // Following: every object's goal holds the cup within its body radius of the edge; only
    // disks narrower than the 11 mm opening can never count as followed.
    EXPECT_DOUBLE_EQ(t.goal.band_m, 0.0115) << spec.name;
    EXPECT_EQ(!t.goal.never_followed.empty(),
              spec.kind == ObjectKind::kDisk && spec.param < kCupOpeningDiameterMm)
        << spec.name;
    if (spec.kind == ObjectKind::kCorner) {
      // A corner passes one body diameter past its apex, on the second edge (60 mm each).
      EXPECT_NEAR(t.goal.goal_arc_m - 0.060, 0.023, 1e-12) << spec.name;
    }
  }
  // The benchmark disk starts 32 mm east of its centre (as published); every object, the
  // benchmark disk too, lands where it starts (as the lab's script does).
  const ObjectTrialSetup benchmark = MakeBenchmarkDisk().trial;
  EXPECT_NEAR(benchmark.start_xy_m[0] - kWorkspaceX, 32 * kMm, 1e-12);
  EXPECT_EQ(benchmark.landing_xy_m, benchmark.start_xy_m);
  for (const char* name : {"disk_d14", "hole_d02", "corner_a090", "volute", "fillet"}) {
    EXPECT_EQ(ObjectByName(name).trial.landing_xy_m, ObjectByName(name).trial.start_xy_m) << name;
  }
  const ObjectTrialSetup hole = MakeHole(10).trial;
  EXPECT_NEAR(hole.start_xy_m[0] - kWorkspaceX, 8 * kMm, 1e-12);
  EXPECT_NEAR(hole.follow_direction[1], -1.0, 1e-12);  // clockwise: south at the east side
  EXPECT_EQ(ObjectByName("corner_a97.5").param, 97.5);
  EXPECT_EQ(ObjectByName("corner_a97.5").name, "corner_a097.5");
  EXPECT_EQ(ObjectByName("disk_d5").param, 5);
  EXPECT_TRUE(ObjectByName("corner_a400").name.empty());
  EXPECT_TRUE(ObjectByName("teapot").name.empty());
  // The number after the prefix is read strictly: no hex, nan, trailing text.
  EXPECT_TRUE(ObjectByName("corner_a0x5a").name.empty());
  EXPECT_TRUE(ObjectByName("disk_dnan").name.empty());
  EXPECT_TRUE(ObjectByName("disk_d6mm").name.empty());
}

// ---------------------------------------------------------------------------------------------
// Fillet profile.

TEST(FilletProfileTest, PassesThePublishedCrossSectionsSmoothlyAndMonotonically) {
  const double x_mm[] = {0, 45, 90, 135, 180};
  const double r_mm[] = {0, 4.7, 10.4, 14.5, 16.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(FilletRadius(x_mm[i] * kMm) / kMm, r_mm[i], 1e-12);
  double previous = 0;
  for (double x = 0; x <= 0.180 + 1e-12; x += 1e-4) {
    EXPECT_GE(FilletRadius(x), previous - 1e-15) << x;
    previous = FilletRadius(x);
  }
  // C1 at the inner stations: slopes from both sides agree.
  const double h = 1e-7;
  for (int i = 1; i < 4; ++i) {
    const double x = x_mm[i] * kMm;
    const double left = (FilletRadius(x) - FilletRadius(x - h)) / h;
    const double right = (FilletRadius(x + h) - FilletRadius(x)) / h;
    EXPECT_NEAR(left, right, 1e-4) << x_mm[i];
  }
}

// ---------------------------------------------------------------------------------------------
// Written files.

TEST(ObjectTierTest, AutoRunsTheFlexLipOnlyWhereTheTiersDisagree) {
  ObjectSceneKind kind = ObjectSceneKind::kGantry;
  std::string error;
  ASSERT_TRUE(ObjectSceneKindByName("auto", &kind, &error)) << error;
  EXPECT_EQ(kind, ObjectSceneKind::kAuto);
  const double law_step_mm = ContourLawParams{}.step_mm;
  for (double step_mm : {0.5, law_step_mm, 10.0}) {
    int flex = 0;
    for (const ObjectSpec& spec : AllObjects()) {
      const ObjectSceneKind tier = ObjectTier(ObjectSceneKind::kAuto, spec, step_mm);
      EXPECT_EQ(tier, FlexTierDisagrees(spec, step_mm) ? ObjectSceneKind::kFlex
                                                       : ObjectSceneKind::kGantry)
          << spec.name;
      flex += tier == ObjectSceneKind::kFlex;
      const ObjectFiles f = ObjectFileNames(spec.name);
      EXPECT_EQ(ObjectSceneFile(spec, ObjectSceneKind::kAuto, step_mm),
                tier == ObjectSceneKind::kFlex ? f.flex_scene : f.gantry_scene)
          << spec.name;
      // A named tier is every object's.
      for (ObjectSceneKind named :
           {ObjectSceneKind::kGantry, ObjectSceneKind::kArm, ObjectSceneKind::kFlex}) {
        EXPECT_EQ(ObjectTier(named, spec, step_mm), named) << spec.name;
      }
    }
    // Up to the crimp-free step only the semi-square strip; past it the 11 concave corners too.
    EXPECT_EQ(flex, step_mm > kCrimpFreeStepMm ? 12 : 1) << step_mm;
  }
  // The measured objects (docs/flex_objects.md): the same outcomes in both tiers at the published
  // 0.5 mm, so the segment lip runs them; the crimp is never met under the law there.
  for (const char* name : {"corner_a090", "corner_a270", "corner_a015", "disk_d02", "hole_d02",
                           "fillet", "volute", "semicircle_strip"}) {
    EXPECT_EQ(ObjectTier(ObjectSceneKind::kAuto, ObjectByName(name), 0.5), ObjectSceneKind::kGantry)
        << name;
  }
  // The skirt stalls on the semi-square strip's 18 mm half-square; the segment lip goes on.
  EXPECT_EQ(ObjectTier(ObjectSceneKind::kAuto, ObjectByName("semisquare_strip"), 0.5),
            ObjectSceneKind::kFlex);
  // At 7.5 mm no concave corner crimped (30 of 30); at 10 mm the 330 degree one folds.
  EXPECT_EQ(ObjectTier(ObjectSceneKind::kAuto, ObjectByName("corner_a330"), 7.5),
            ObjectSceneKind::kGantry);
  EXPECT_EQ(ObjectTier(ObjectSceneKind::kAuto, ObjectByName("corner_a330"), 10.0),
            ObjectSceneKind::kFlex);
  EXPECT_EQ(ObjectTier(ObjectSceneKind::kAuto, ObjectByName("corner_a090"), 10.0),
            ObjectSceneKind::kGantry);
}

TEST(ObjectFilesTest, EveryFileLoadsAndOutputIsDeterministic) {
  for (const ObjectSpec& spec : AllObjects()) {
    const ObjectFiles f = ObjectFileNames(spec.name);
    for (const std::string& file : {f.object, f.arm_scene, f.gantry_scene, f.probe_scene}) {
      EXPECT_TRUE(fs::exists(SceneDir() / file)) << file;
    }
  }
  // A sample of each kind loads; the object file alone holds only the object's geoms.
  for (const char* name :
       {"disk_r35", "hole_d04", "corner_a300", "volute", "semisquare_strip", "fillet"}) {
    const ObjectFiles f = ObjectFileNames(name);
    const Loaded object = Load(FileOf(name));
    ASSERT_TRUE(object.m);
    EXPECT_EQ(object.m->ngeom, static_cast<int>(ObjectByName(name).pieces.size())) << name;
    for (const std::string& file : {f.arm_scene, f.gantry_scene, f.probe_scene}) {
      const Loaded scene = Load((SceneDir() / file).string());
      ASSERT_TRUE(scene.m) << file;
      EXPECT_GE(mj_name2id(scene.m.get(), mjOBJ_SITE, "ssc_tool_site"), 0) << file;
      EXPECT_EQ(mj_name2id(scene.m.get(), mjOBJ_GEOM, "disk"), -1) << file;
      EXPECT_GE(mj_name2id(scene.m.get(), mjOBJ_GEOM, "table"), 0) << file;
    }
  }
  // Same bytes when written again elsewhere (at the same depth: the model paths are relative).
  const fs::path again = SceneDir().string() + "_again";
  std::string error;
  ASSERT_EQ(WriteAllObjectScenes(again.string(), SourceDir(), RigObjectSceneTemplates(), &error),
            42)
      << error;
  auto read = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  for (const auto& entry : fs::directory_iterator(SceneDir())) {
    EXPECT_EQ(read(entry.path()), read(again / entry.path().filename())) << entry.path();
  }
  fs::remove_all(again);
}

// A template's disk is a geom in it or an <include> of a file that holds the disk alone
// (scenes/parts/disk.xml); an included file that holds the disk among other elements cannot
// lose the disk alone and is refused, naming the file.
TEST(ObjectFilesTest, AnIncludeThatHoldsTheDiskAmongOtherElementsIsRefused) {
  const fs::path repo = fs::temp_directory_path() / ("ssc_templates_" + std::to_string(::getpid()));
  fs::create_directories(repo / "scenes" / "parts");
  std::ofstream(repo / "scenes" / "bench.xml")
      << "<mujoco><include file=\"parts/world.xml\"/></mujoco>";
  std::ofstream(repo / "scenes" / "parts" / "world.xml")
      << "<mujoco><worldbody><geom name=\"table\" type=\"plane\" size=\"1 1 0.01\"/>"
         "<geom name=\"disk\" type=\"cylinder\" size=\"0.035 0.005\"/></worldbody></mujoco>";
  std::string error;
  EXPECT_FALSE(WriteObjectFiles(ObjectByName("disk_d06"), (repo / "out").string(), repo.string(),
                                {"bench", "bench", "bench"}, &error));
  EXPECT_NE(error.find("parts/world.xml"), std::string::npos) << error;
  EXPECT_NE(error.find("'disk' among other elements"), std::string::npos) << error;
  fs::remove_all(repo);
}

// ---------------------------------------------------------------------------------------------
// Written geometry against the analytic shapes.

// Away from a band of kBandM round the edge, rays from above find the top face exactly on the
// object's side (signed distance < 0). Then, across the edge along its normal, the edge found by
// bisection with rays lies within kEdgeTolM of the exact one.
constexpr double kBandM = 0.1 * kMm;
constexpr double kEdgeTolM = 0.04 * kMm;

TEST(ObjectGeometryTest, WrittenGeometryMatchesTheExactEdge) {
  for (const ObjectSpec& spec : AllObjects()) {
    if (spec.kind == ObjectKind::kFillet) continue;  // its own test below
    SCOPED_TRACE(spec.name);
    const Loaded l = Load(FileOf(spec.name));
    ASSERT_TRUE(l.m);
    const double length = spec.edge.Length();
    const double ds = std::min(0.7 * kMm, length / 60);
    int checked = 0, wrong = 0, edges = 0;
    double worst_edge_m = 0;
    for (double s = 0.5 * ds; s < length; s += ds) {
      const Point2 p = spec.edge.PointAt(s), n = spec.edge.LeftNormalAt(s);
      for (double off_mm : {-6.0, -3.0, -1.0, -0.3, -0.12, 0.12, 0.3, 1.0, 3.0, 6.0}) {
        const double x = p[0] + off_mm * kMm * n[0], y = p[1] + off_mm * kMm * n[1];
        const double sd = spec.DistanceToContour(x, y);
        if (std::fabs(sd) < kBandM) continue;
        const bool top = AtTop(SurfaceZ(l, x, y));
        ++checked;
        if (top != (sd < 0)) {
          ++wrong;
          ADD_FAILURE() << "at arc " << s / kMm << " mm, offset " << off_mm << " mm: signed "
                        << "distance " << sd / kMm << " mm but ray top " << top;
        }
      }
      // Where the edge is locally a clean boundary (0.5 mm either side are 0.5 mm away).
      const double h = 0.5 * kMm;
      const Point2 in = {p[0] + h * n[0], p[1] + h * n[1]};
      const Point2 out = {p[0] - h * n[0], p[1] - h * n[1]};
      if (spec.DistanceToContour(in[0], in[1]) > -0.49 * kMm ||
          spec.DistanceToContour(out[0], out[1]) < 0.49 * kMm) {
        continue;
      }
      double lo = -h, hi = h;  // offsets: lo off the object, hi on it
      for (int i = 0; i < 30; ++i) {
        const double mid = 0.5 * (lo + hi);
        (AtTop(SurfaceZ(l, p[0] + mid * n[0], p[1] + mid * n[1])) ? hi : lo) = mid;
      }
      worst_edge_m = std::max(worst_edge_m, std::fabs(0.5 * (lo + hi)));
      ++edges;
    }
    EXPECT_GT(checked, 100);
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(edges, 20);
    EXPECT_LE(worst_edge_m, kEdgeTolM) << "edge found " << worst_edge_m / kMm << " mm off";
  }
}

TEST(ObjectGeometryTest, FilletSurfaceFollowsTheRadiusProfile) {
  const Loaded l = Load(FileOf("fillet"));
  ASSERT_TRUE(l.m);
  // The surface everywhere within 0.05 mm of the analytic one, measured along its normal (slices
  // interpolate the radius linearly over 10 mm; 16 chords per quarter circle).
  double worst = 0;
  for (double x_mm = -20; x_mm <= 200; x_mm += 2.5) {
    for (double y_mm = -2; y_mm <= 20; y_mm += 0.25) {
      const double x = kWorkspaceX + x_mm * kMm, y = kWorkspaceY + y_mm * kMm;
      if (y_mm > -0.05 && y_mm < 0.05) continue;  // the vertical wall of the sharp part
      const double z = SurfaceZ(l, x, y);
      const double want = FilletSurfaceZ(x, y);
      if (want <= kTableZ + 1e-9) {  // beyond the bar (no table in the object file)
        EXPECT_TRUE(!std::isfinite(z) || z < kTableZ + 0.05 * kMm) << x_mm << " " << y_mm;
        continue;
      }
      ASSERT_TRUE(std::isfinite(z)) << x_mm << " " << y_mm;
      // Vertical error times the normal's z component: the distance along the normal.
      const double r = FilletRadius(std::clamp(x_mm * kMm, 0.0, kFilletEdgeLengthM));
      const double nz = y_mm * kMm >= r ? 1.0 : (want - kObjectTopZ + r) / r;
      worst = std::max(worst, std::fabs(z - want) * nz);
    }
  }
  EXPECT_LT(worst, 0.05 * kMm) << worst / kMm << " mm";
  // The radius measured on the written surface at the published stations: from the depth d
  // below the top face at distance y from the edge, r = y + d + sqrt(2 y d).
  const double x_mm[] = {0, 45, 90, 135, 180};
  const double r_mm[] = {0, 4.7, 10.4, 14.5, 16.0};
  for (int i = 0; i < 5; ++i) {
    const double x = kWorkspaceX + x_mm[i] * kMm;
    if (r_mm[i] == 0) {  // sharp: top face right up to the edge, nothing beyond
      EXPECT_TRUE(AtTop(SurfaceZ(l, x, kWorkspaceY + 0.05 * kMm)));
      EXPECT_FALSE(std::isfinite(SurfaceZ(l, x, kWorkspaceY - 0.05 * kMm)));  // no table here
      continue;
    }
    for (double u : {0.3, 0.5}) {
      const double y = u * r_mm[i] * kMm;
      const double d = kObjectTopZ - SurfaceZ(l, x, kWorkspaceY + y);
      EXPECT_NEAR((y + d + std::sqrt(2 * y * d)) / kMm, r_mm[i], 0.1) << x_mm[i] << " mm, u " << u;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Rays and contacts on concave objects.

// A lip-like sphere (radius 0.5 mm, contype 1, conaffinity 0, on a free joint; group 3, unseen by
// the rays) placed with its bottom 0.1 mm below the top face: where the ray says "top face", it
// touches; where the ray finds no surface within the lip's 3 mm reach, it touches nothing.
// Returns the disagreements.
int RayContactDisagreements(const std::string& object_file, const ObjectSpec& spec, int* checked) {
  const fs::path scene = fs::path(object_file).parent_path() /
                         (fs::path(object_file).stem().string() + "_sphere_probe.xml");
  std::ofstream(scene) << "<mujoco><include file=\"" << fs::path(object_file).filename().string()
                       << "\"/><worldbody><body name=\"sphere\"><freejoint/><geom type=\"sphere\""
                       << " size=\"0.0005\" group=\"3\" contype=\"1\" conaffinity=\"0\"/>"
                       << "</body></worldbody></mujoco>";
  const Loaded l = Load(scene.string());
  if (!l.m) return -1;
  int disagree = 0;
  *checked = 0;
  const double length = spec.edge.Length();
  for (double s = 0.25 * kMm; s < length; s += 0.5 * kMm) {
    const Point2 p = spec.edge.PointAt(s), n = spec.edge.LeftNormalAt(s);
    for (double off_mm : {-4.0, -2.0, -1.0, -0.7, 0.7, 1.0, 2.0, 4.0}) {
      const double x = p[0] + off_mm * kMm * n[0], y = p[1] + off_mm * kMm * n[1];
      if (std::fabs(spec.DistanceToContour(x, y)) < 0.65 * kMm) continue;  // sphere on the edge
      l.d->qpos[0] = x;
      l.d->qpos[1] = y;
      l.d->qpos[2] = kObjectTopZ + 0.0005 - 0.0001;
      mj_forward(l.m.get(), l.d.get());
      const double z = SurfaceZ(l, x, y);
      const bool top = AtTop(z);
      const bool none_in_reach = !std::isfinite(z) || z < kObjectTopZ - 0.003;
      if (!top && !none_in_reach) continue;  // a slope: neither claim applies
      ++*checked;
      const bool contact = l.d->ncon > 0;
      if (contact != top) {
        ++disagree;
        ADD_FAILURE() << spec.name << " at arc " << s / kMm << " mm, offset " << off_mm
                      << " mm: ray " << (top ? "top face" : "nothing in reach") << ", contact "
                      << contact;
      }
    }
  }
  return disagree;
}

TEST(RaysAndContactsTest, AgreeOnConcaveObjects) {
  for (const char* name : {"hole_d02", "hole_d10", "hole_d14", "corner_a195", "corner_a270",
                           "corner_a345", "volute", "semicircle_strip", "semisquare_strip"}) {
    int checked = 0;
    EXPECT_EQ(RayContactDisagreements(FileOf(name), ObjectByName(name), &checked), 0) << name;
    EXPECT_GT(checked, 50) << name;
  }
}

TEST(RaysAndContactsTest, TheCheckCatchesAConcaveMesh) {
  // The hole plate as ONE mesh: MuJoCo collides its convex hull (no hole) while rays see the
  // hole; the same check must report it.
  const ObjectSpec hole = MakeHole(10);
  std::string vertex;
  for (const ConvexPiece& piece : hole.pieces) {
    if (piece.shape != ConvexPiece::Shape::kPrism) continue;
    for (const Point2& q : piece.polygon) {
      for (double z : {0.0, kObjectTopZ}) {
        vertex += std::to_string(q[0] - kWorkspaceX) + " " + std::to_string(q[1]) + " " +
                  std::to_string(z) + " ";
      }
    }
  }
  const fs::path file = SceneDir() / "concave_plate.xml";
  // Faces: every prism's top and bottom fan, so rays see the true (holed) ring.
  std::string face;
  int base = 0;
  for (const ConvexPiece& piece : hole.pieces) {
    if (piece.shape != ConvexPiece::Shape::kPrism) continue;
    const int k = static_cast<int>(piece.polygon.size());
    for (int i = 1; i + 1 < k; ++i) {
      for (int top : {0, 1}) {  // both windings: the fans face up and down
        const int a = base + top, b = base + 2 * i + top, c = base + 2 * (i + 1) + top;
        face += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " +
                std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + " ";
      }
    }
    base += 2 * k;
  }
  std::ofstream(file) << "<mujoco><asset><mesh name=\"plate\" vertex=\"" << vertex << "\" face=\""
                      << face << "\" inertia=\"convex\"/></asset>"
                      << "<worldbody><body pos=\"" << kWorkspaceX
                      << " 0 0\"><geom type=\"mesh\" mesh=\"plate\" group=\"2\"/>"
                      << "</body></worldbody></mujoco>";
  int checked = 0;
  int disagree = 0;
  {
    testing::TestPartResultArray swallowed;  // the expected disagreements are not failures
    testing::ScopedFakeTestPartResultReporter quiet(
        testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &swallowed);
    disagree = RayContactDisagreements(file.string(), hole, &checked);
  }
  EXPECT_GT(disagree, 10) << "checked " << checked;
}

// The real lip: the mocap cup pressed 0.5 mm below the top face over concave features; each lip
// segment whose footprint lies clear of the edge touches exactly when a ray at its centre finds
// the top face.
TEST(RaysAndContactsTest, LipSegmentsAgreeWithRays) {
  struct Case {
    const char* name;
    double arc_fraction;
  };
  for (const Case& c : {Case{"hole_d10", 0.1}, Case{"hole_d14", 0.6}, Case{"corner_a270", 0.5},
                        Case{"volute", 0.999}, Case{"semisquare_strip", 0.2}}) {
    const ObjectSpec spec = ObjectByName(c.name);
    const Loaded l = Load((SceneDir() / ObjectFileNames(c.name).probe_scene).string());
    ASSERT_TRUE(l.m);
    const int probe = mj_name2id(l.m.get(), mjOBJ_BODY, "probe");
    const int site = mj_name2id(l.m.get(), mjOBJ_SITE, "ssc_tool_site");
    mjtNum* mocap = l.d->mocap_pos + 3 * l.m->body_mocapid[probe];
    const double tool_length = mocap[2] - l.d->site_xpos[3 * site + 2];
    int checked = 0;
    for (double ds_mm = -6; ds_mm <= 6; ds_mm += 1.5) {
      for (double inset_mm : {-2.0, 0.0, 2.0}) {
        const double s = c.arc_fraction * spec.edge.Length() + ds_mm * kMm;
        const Point2 p = spec.edge.PointAt(s), n = spec.edge.LeftNormalAt(s);
        mocap[0] = p[0] + inset_mm * kMm * n[0];
        mocap[1] = p[1] + inset_mm * kMm * n[1];
        mocap[2] = kObjectTopZ - 0.0005 + tool_length;
        mj_forward(l.m.get(), l.d.get());
        for (int g = 0; g < l.m->ngeom; ++g) {
          if (l.m->geom_group[g] != 4) continue;  // lip segments
          const double x = l.d->geom_xpos[3 * g], y = l.d->geom_xpos[3 * g + 1];
          if (std::fabs(spec.DistanceToContour(x, y)) < 1.6 * kMm) continue;  // straddles
          bool contact = false;
          for (int i = 0; i < l.d->ncon; ++i) {
            contact |= l.d->contact[i].geom[0] == g || l.d->contact[i].geom[1] == g;
          }
          const double z = SurfaceZ(l, x, y);
          ++checked;
          EXPECT_EQ(contact, AtTop(z))
              << c.name << " segment " << g << " at (" << (x - kWorkspaceX) / kMm << ", " << y / kMm
              << ") mm, ray z " << z;
        }
      }
    }
    EXPECT_GT(checked, 100) << c.name;
  }
}

// ---------------------------------------------------------------------------------------------
// Cost and trials.

TEST(ObjectStepCostTest, MeasuresTheProbeScenes) {
  StepCostOptions options;
  options.warmup_steps = 20;
  options.steps = 100;
  for (const char* name : {"disk_r35", "hole_d10"}) {
    std::string error;
    const auto cost =
        MeasureStepCost(ObjectByName(name),
                        (SceneDir() / ObjectFileNames(name).probe_scene).string(), options, &error);
    ASSERT_TRUE(cost) << error;
    EXPECT_GT(cost->step_us, 0);
    EXPECT_GT(cost->contacts, 4) << name;  // the pressed lip touches
    EXPECT_NEAR(cost->sim_s, 0.2, 1e-9);
    EXPECT_EQ(cost->object_geoms, static_cast<int>(ObjectByName(name).pieces.size()));
  }
}

// Trials through ObjectTrialConfig with the published primitive controller (P_ref 100 Pa,
// beta 2, dL 0.5 mm) on the gantry scenes: the set-up data drives a real trial to its end.
void ExpectOutcome(const char* name, Outcome expected, double goal_arc_m = -1) {
  ObjectSpec spec = ObjectByName(name);
  if (goal_arc_m > 0) spec.trial.goal.goal_arc_m = goal_arc_m;
  const Loaded l = Load((SceneDir() / ObjectFileNames(name).gantry_scene).string());
  ASSERT_TRUE(l.m);
  ContourLawParams law;
  law.step_mm = 0.5;
  const ObjectTrialRow row = RunObjectTrial(l.m.get(), spec, law, FittedRobotEffects(), 1, false);
  EXPECT_EQ(row.result.outcome, expected)
      << name << ": " << OutcomeName(row.result.outcome) << ", " << row.result.detail;
  EXPECT_LT(row.result.metrics.contour_mean_mm, 5.0) << name;
}

TEST(ObjectTrialsTest, LargeDisk) { ExpectOutcome("disk_r35", Outcome::kSuccess); }
// A disk smaller than the 11 mm opening: the cup lands beside it (the lip would miss it), the
// opening hangs over it whole and no chamber seals against an edge: failure I, as documented.
TEST(ObjectTrialsTest, DiskSmallerThanTheOpeningFails) {
  ExpectOutcome("disk_d06", Outcome::kFailureOffEdge);
}
TEST(ObjectTrialsTest, Hole) { ExpectOutcome("hole_d10", Outcome::kSuccess); }
TEST(ObjectTrialsTest, ConcaveCorner) { ExpectOutcome("corner_a270", Outcome::kSuccess); }
// Issue 12: the cup covers a 10 mm disk (11 mm opening) and turns over it: never a success.
TEST(ObjectTrialsTest, DiskSmallerThanTheOpeningIsNotFollowed) {
  const ObjectSpec spec = ObjectByName("disk_d10");
  const Loaded l = Load((SceneDir() / ObjectFileNames("disk_d10").gantry_scene).string());
  ASSERT_TRUE(l.m);
  ContourLawParams law;
  law.step_mm = 0.5;
  const ObjectTrialRow row = RunObjectTrial(l.m.get(), spec, law, FittedRobotEffects(), 1, false);
  EXPECT_NE(row.result.outcome, Outcome::kSuccess) << row.result.detail;
}
TEST(ObjectTrialsTest, FilletSharpEnd) { ExpectOutcome("fillet", Outcome::kSuccess, 0.040); }

}  // namespace
}  // namespace ssc
