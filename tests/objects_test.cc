// Test objects: generated geometry against the analytic shapes, rays against contacts on
// concave objects, and trials on a representative subset (stable across seeds).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>
#include <unistd.h>

#include "controller/sim/mujoco_model.h"
#include "objects/object_mjcf.h"
#include "objects/object_trials.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

fs::path SceneDir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("ssc_objects_" + std::to_string(::getpid()));
    std::string error;
    for (const char* name : {"disk_r35", "disk_d06", "hole_d10", "corner_a090", "corner_a270",
                             "volute", "semicircle_strip", "semisquare_strip", "fillet"}) {
      EXPECT_TRUE(WriteObjectScenes(ObjectByName(name), d.string(), SourceDir(), &error)) << error;
    }
    return d;
  }();
  return dir;
}

// Signed side of (x, y) relative to the contour's nearest segment: > 0 on the object's side
// (the left of the walking direction).
double SideOfContour(const Polyline& c, double x, double y) {
  const double s = c.ArcPosition(x, y);
  const Point2 p = c.PointAt(s), t = c.TangentAt(s);
  return t[0] * (y - p[1]) - t[1] * (x - p[0]);
}

TEST(ObjectsTest, ContoursMatchTheirAnalyticShapes) {
  const ObjectSpec disk = MakeDisk(10);
  for (const Point2& p : disk.contour.points) {
    EXPECT_NEAR(std::hypot(p[0] - kWorkspaceX, p[1] - kWorkspaceY), 0.005, 1e-12);
  }
  EXPECT_NEAR(disk.contour.Length(), 2 * M_PI * 0.005, 1e-6);
  const ObjectSpec corner = MakeCorner(120);
  EXPECT_NEAR(corner.contour.points[1][0], kWorkspaceX, 1e-12);  // apex at W
  const Point2 d2 = {corner.contour.points[2][0] - kWorkspaceX, corner.contour.points[2][1]};
  EXPECT_NEAR(std::atan2(d2[1], d2[0]) * 180 / M_PI, 60.0, 1e-9);  // pi - alpha
  // Walking keeps the object on the left: a point inside the disk is on the left.
  EXPECT_GT(SideOfContour(disk.contour, kWorkspaceX, kWorkspaceY + 0.001), 0);
  const ObjectSpec hole = MakeHole(10);
  EXPECT_LT(SideOfContour(hole.contour, kWorkspaceX + 0.001, kWorkspaceY), 0);  // in the hole
}

TEST(ObjectsTest, FilletRadiusPassesThePublishedCrossSections) {
  const double x_mm[] = {0, 45, 90, 135, 180};
  const double r_mm[] = {0, 4.7, 10.4, 14.5, 16.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(FilletRadius(x_mm[i] * 1e-3) * 1e3, r_mm[i], 1e-9);
  double previous = -1;
  for (double x = 0; x <= 0.18; x += 0.001) {
    EXPECT_GE(FilletRadius(x), previous - 1e-15) << x;  // grows smoothly, never back
    previous = FilletRadius(x);
  }
}

// Height of the first surface under (x, y) by a ray from above (NaN if none within 0.1 m).
double SurfaceZ(const mjModel* m, mjData* d, double x, double y) {
  const mjtNum start[3] = {x, y, 0.1}, down[3] = {0, 0, -1};
  const mjtByte groups[mjNGROUP] = {0, 0, 1, 0, 0, 0};
  int geom = -1;
  const mjtNum t = mj_ray(m, d, start, down, groups, 1, -1, &geom, nullptr);
  return t < 0 ? NAN : 0.1 - t;
}

TEST(ObjectsTest, GeneratedGeometryMatchesTheContour) {
  // Away from a 0.2 mm band around the contour, rays from above find the top face exactly on
  // the object's side and nothing at the top height on the other side.
  for (const char* name : {"disk_d06", "hole_d10", "corner_a090", "corner_a270", "volute",
                           "semicircle_strip", "semisquare_strip"}) {
    const ObjectSpec spec = ObjectByName(name);
    std::string error;
    ModelPtr m = LoadModel((SceneDir() / (std::string(name) + "_object.xml")).string(), &error);
    ASSERT_TRUE(m) << error;
    DataPtr d = MakeData(m.get(), &error);
    mj_forward(m.get(), d.get());
    int checked = 0;
    const double length = spec.contour.Length();
    for (double s = 0; s < length; s += 0.0013) {
      const Point2 p = spec.contour.PointAt(s), t = spec.contour.TangentAt(s);
      for (double off : {-0.004, -0.0012, 0.0012, 0.004}) {
        const double x = p[0] - t[1] * off, y = p[1] + t[0] * off;  // off > 0: left (object)
        if (spec.contour.Distance(x, y) < 0.001) continue;  // near a corner of the contour
        const bool object_side = SideOfContour(spec.contour, x, y) > 0;
        const double z = SurfaceZ(m.get(), d.get(), x, y);
        const bool at_top = std::isfinite(z) && std::fabs(z - kObjectTopZ) < 2e-4;
        EXPECT_EQ(at_top, object_side) << name << " at arc " << s * 1e3 << " mm, offset "
                                       << off * 1e3 << " mm, surface z " << z;
        ++checked;
      }
    }
    EXPECT_GT(checked, 20) << name;
  }
}

TEST(ObjectsTest, FilletSurfaceFollowsTheRadiusProfile) {
  std::string error;
  ModelPtr m = LoadModel((SceneDir() / "fillet_object.xml").string(), &error);
  ASSERT_TRUE(m) << error;
  DataPtr d = MakeData(m.get(), &error);
  mj_forward(m.get(), d.get());
  for (double x_mm : {5.0, 45.0, 90.0, 135.0, 175.0, 44.97, 90.02}) {
    const double r = FilletRadius(x_mm * 1e-3);
    for (double u : {0.25, 0.5, 0.75}) {  // across the rounded part
      const double y = u * r;
      const double want = kObjectTopZ - r + std::sqrt(r * r - (r - y) * (r - y));
      const double z = SurfaceZ(m.get(), d.get(), kWorkspaceX + x_mm * 1e-3, kWorkspaceY + y);
      // Slices interpolate the radius linearly over 10 mm and chord the arc with 10 segments.
      EXPECT_NEAR(z, want, 0.35e-3) << "x " << x_mm << " mm, y " << y * 1e3 << " mm";
    }
    EXPECT_NEAR(SurfaceZ(m.get(), d.get(), kWorkspaceX + x_mm * 1e-3, kWorkspaceY + 0.03),
                kObjectTopZ, 1e-6);
  }
}

TEST(ObjectsTest, RaysAndContactsSeeTheSameSurfaceOnConcaveObjects) {
  // A lip-like sphere (contype 1, conaffinity 0) on a free body placed 0.4 mm above the top
  // height: it touches exactly where a ray finds the top face.
  for (const char* name : {"hole_d10", "corner_a270", "volute", "semicircle_strip"}) {
    const fs::path scene = SceneDir() / (std::string(name) + "_contact_probe.xml");
    std::ofstream(scene) << "<mujoco><include file=\"" << name << "_object.xml\"/><worldbody>"
                         << "<body name=\"probe\"><freejoint/><geom type=\"sphere\" "
                            "size=\"0.0005\" contype=\"1\" conaffinity=\"0\"/></body>"
                         << "</worldbody></mujoco>";
    std::string error;
    ModelPtr m = LoadModel(scene.string(), &error);
    ASSERT_TRUE(m) << error;
    DataPtr d = MakeData(m.get(), &error);
    const ObjectSpec spec = ObjectByName(name);
    int agree = 0, total = 0;
    for (double s = 0; s < spec.contour.Length(); s += 0.0021) {
      const Point2 p = spec.contour.PointAt(s), t = spec.contour.TangentAt(s);
      for (double off : {-0.003, -0.001, 0.001, 0.003}) {
        const double x = p[0] - t[1] * off, y = p[1] + t[0] * off;
        if (spec.contour.Distance(x, y) < 0.0008) continue;
        d->qpos[0] = x;
        d->qpos[1] = y;
        d->qpos[2] = kObjectTopZ + 0.0004;
        mj_forward(m.get(), d.get());
        const bool contact = d->ncon > 0;
        const double z = SurfaceZ(m.get(), d.get(), x, y);
        const bool ray_top = std::isfinite(z) && std::fabs(z - kObjectTopZ) < 2e-4;
        agree += contact == ray_top;
        ++total;
        EXPECT_EQ(contact, ray_top) << name << " at arc " << s * 1e3 << " mm, offset "
                                    << off * 1e3 << " mm";
      }
    }
    EXPECT_GT(total, 40) << name;
  }
}

// Representative trials with the published primitive controller (P_ref 100, beta 2,
// dL 0.5 mm): the twin's predicted outcome, the same for three seeds.
void ExpectOutcome(const char* name, const char* expected, double end_arc_m = -1) {
  ObjectSpec spec = ObjectByName(name);
  if (end_arc_m > 0) spec.end_arc_m = end_arc_m;
  std::string error;
  ModelPtr m = LoadModel((SceneDir() / (std::string(name) + "_gantry.xml")).string(), &error);
  ASSERT_TRUE(m) << error;
  ContourLawParams law;
  law.step_mm = 0.5;
  for (std::uint64_t seed : {1, 2, 3}) {
    const ObjectTrialRow row = RunObjectTrial(m.get(), spec, law, seed, false);
    EXPECT_EQ(row.result.outcome, expected) << name << " seed " << seed << ": " << row.result.detail;
    EXPECT_LT(row.result.metrics.contour_mean_mm, 5.0) << name;
  }
}

TEST(ObjectTrialsTest, LargeDisk) { ExpectOutcome("disk_r35", "success"); }
TEST(ObjectTrialsTest, Hole) { ExpectOutcome("hole_d10", "success"); }
TEST(ObjectTrialsTest, ConvexCorner) { ExpectOutcome("corner_a090", "success"); }
TEST(ObjectTrialsTest, ConcaveCorner) { ExpectOutcome("corner_a270", "success"); }
TEST(ObjectTrialsTest, CompoundShape) { ExpectOutcome("semisquare_strip", "success"); }
TEST(ObjectTrialsTest, FilletSharpEnd) { ExpectOutcome("fillet", "success", 0.040); }

}  // namespace
}  // namespace ssc
