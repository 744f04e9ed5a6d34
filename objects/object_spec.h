// The test objects of the published experiments, each generated from a few parameters: its
// exact edge (geometry/contour_path.h), how a trial starts and succeeds on it, and the convex
// pieces that build it in MuJoCo. Pure C++; objects/object_mjcf.h writes them as MJCF.
//
// World convention (all scenes): z up, north = +y, east = +x, the table a plane at z = 0. Every
// object stands on the table with its top face at z = 10 mm, and its reference point (disk or
// hole centre, corner apex, start of an edge) sits at the workspace point W = (0.65, 0) m.
// Objects are static geoms in group 2 with contype/conaffinity 1 (the lip collides with them,
// the pressure sensor's rays see them).
//
// Why convex pieces: MuJoCo collides a mesh as its convex hull but rays hit its triangles, so a
// concave mesh would seal the lip where the sensor sees air. Every piece here is convex (box,
// cylinder, prism over a convex polygon, or convex hull of points), so contacts and rays see the
// same surface; neighbouring pieces overlap by kSeamOverlapM so no ray slips down a seam.
#ifndef SSC_OBJECTS_OBJECT_SPEC_H_
#define SSC_OBJECTS_OBJECT_SPEC_H_

#include <array>
#include <string>
#include <vector>

#include "geometry/contour_path.h"
#include "geometry/dimensions.h"
#include "objects/fillet_profile.h"
#include "trial/trial_goal.h"

namespace ssc {

inline constexpr double kTableZ = 0.0;         // table plane, m
inline constexpr double kObjectTopZ = 0.010;   // top face of every object, m
inline constexpr double kStartInsetM = 0.003;  // cup centre inside the edge at the start
inline constexpr double kSeamOverlapM = 1e-4;  // neighbouring convex pieces overlap this much

enum class ObjectKind {
  kDisk,
  kHole,
  kCorner,
  kVolute,
  kSemicircleStrip,
  kSemisquareStrip,
  kFillet
};
const char* ObjectKindName(ObjectKind kind);

// One convex piece, in world coordinates (m).
struct ConvexPiece {
  enum class Shape { kBox, kCylinder, kPrism, kHull };
  Shape shape = Shape::kBox;
  Point2 centre{};                                 // box, cylinder: axis through (x, y)
  double half_x_m = 0, half_y_m = 0;               // box (axis-aligned)
  double radius_m = 0;                             // cylinder
  std::vector<Point2> polygon;                     // prism: a convex polygon (either orientation)
  std::vector<std::array<double, 3>> hull_points;  // hull: the piece is their convex hull
  double bottom_z_m = kTableZ, top_z_m = kObjectTopZ;  // box, cylinder, prism

  static ConvexPiece Box(double x_min, double x_max, double y_min, double y_max);
  static ConvexPiece Cylinder(const Point2& centre, double radius_m);
  static ConvexPiece Prism(std::vector<Point2> polygon);
  static ConvexPiece Hull(std::vector<std::array<double, 3>> points);
};

// How the trial runner starts a contour-following trial on an object, and its goal.
struct ObjectTrialSetup {
  Point2 landing_xy_m{};                // the cup descends here to the start-up compression (world)
  Point2 start_xy_m{};                  // cup centre when following starts
  double start_arc_m = 0;               // arc position of the edge point next to the start
  double start_inset_m = kStartInsetM;  // start lies this far inside the edge (object side)
  Point2 follow_direction{1, 0};        // unit: the edge's walking direction at the start
  bool object_on_left = true;           // the published sense: ccw round a disk, cw round a hole
  // Closed contours: the swept angle about the object's centre (signed: > 0 counter-clockwise);
  // open contours: the goal point's arc position along the edge.
  TrialGoal goal;
  double surface_top_z_m = kObjectTopZ;
};

struct ObjectSpec {
  std::string name;  // e.g. disk_d06, disk_r35, hole_d10, corner_a090, volute, fillet
  ObjectKind kind = ObjectKind::kDisk;
  double param = 0;         // diameter (mm) for disks and holes, angle (deg) for corners, else 0
  std::string description;  // dimensions in words, for the files and docs
  ContourPath edge;         // the exact followed edge, object on its left
  std::vector<Point2> outline;  // the edge as polyline vertices (chords within 0.02 mm), for plots
  double top_z_m = kObjectTopZ;
  ObjectTrialSetup trial;
  std::vector<ConvexPiece> pieces;

  bool closed() const { return edge.closed(); }
  // Signed distance from (x, y) to the edge in the top-face plane, m: negative on the object.
  double DistanceToContour(double x, double y) const { return edge.SignedDistance(x, y); }
  // Where along the edge (x, y) is: arc position of the closest edge point, m from its start.
  double ArcPosition(double x, double y) const { return edge.ArcPosition(x, y); }
};

// Builders. Diameters in mm (disks 2..14 and the benchmark's 70, holes 2..14; any positive value
// is accepted); corner angle alpha in deg, 0 < alpha < 360 (convex below 180, concave above).
ObjectSpec MakeDisk(double diameter_mm);
ObjectSpec MakeBenchmarkDisk();  // the 35 mm-radius disk
ObjectSpec MakeHole(double diameter_mm);
ObjectSpec MakeCorner(double alpha_deg);
ObjectSpec MakeVolute();
ObjectSpec MakeSemicircleStrip();
ObjectSpec MakeSemisquareStrip();
ObjectSpec MakeFillet();

// Surface height of the fillet bar (m, world) above world (x, y): the analytic shape the slices
// approximate (top face, rounded edge of radius FilletRadius, table beyond the edge).
double FilletSurfaceZ(double x_m, double y_m);

// The published set: disks and holes 2, 4, ..., 14 mm, the 35 mm-radius disk, corners every
// 15 deg from 15 to 345, the volute, the two strips and the fillet (42 objects).
std::vector<ObjectSpec> AllObjects();
// One object by name: a name of AllObjects(), or corner_a<deg> / disk_d<mm> / hole_d<mm> for
// any value (e.g. corner_a100, corner_a97.5). An empty name when unknown.
ObjectSpec ObjectByName(const std::string& name);

}  // namespace ssc

#endif  // SSC_OBJECTS_OBJECT_SPEC_H_
