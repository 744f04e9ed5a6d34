// The test objects of the published experiments, generated from a few parameters: their true
// contour, how a trial starts and succeeds on them, and the convex pieces (or height field) that
// build them in MuJoCo. Pure C++; objects/object_mjcf.h writes them as MJCF.
//
// World convention (all scenes): z up, north = +y, east = +x; every object's top face is at
// z = top_z_m (10 mm) and its reference point (disk/hole centre, corner apex, edge start) sits at
// the workspace point W = (0.65, 0) m. Objects are static geoms in group 2 that collide with the
// lip (contype/conaffinity 1).
#ifndef SSC_OBJECTS_OBJECT_SPEC_H_
#define SSC_OBJECTS_OBJECT_SPEC_H_

#include <string>
#include <vector>

#include "objects/contour.h"

namespace ssc {

inline constexpr double kWorkspaceX = 0.65, kWorkspaceY = 0.0;
inline constexpr double kObjectTopZ = 0.010;     // top face of every object, m
inline constexpr double kObjectBottomZ = -0.040; // objects extend down to here, m
inline constexpr double kTableZ = -0.050;        // table plane under generated scenes, m

enum class ObjectKind { kDisk, kHole, kCorner, kVolute, kSemicircleStrip, kSemisquareStrip, kFillet };
const char* ObjectKindName(ObjectKind kind);

// A convex piece: a vertical prism over a convex polygon (world x/y, m, counter-clockwise)
// from bottom_z to top_z, a cylinder (centre, radius), or the convex hull of free 3-D points
// (world, m; the fillet's slices).
struct ConvexPiece {
  bool cylinder = false;
  Point2 centre{};
  double radius_m = 0;
  std::vector<Point2> polygon;
  std::vector<std::array<double, 3>> hull_points;
  double bottom_z = kObjectBottomZ, top_z = kObjectTopZ;
};

// A height field over a rectangle: elevation(x, y) sampled on a grid.
struct HeightField {
  Point2 centre{};           // world x/y of the grid centre
  double half_x_m = 0, half_y_m = 0;
  int nrow = 0, ncol = 0;    // rows along y, columns along x (MuJoCo's order)
  std::vector<double> z_m;   // nrow * ncol heights, row-major, row 0 at -y
  double base_z_m = kObjectBottomZ;
};

struct ObjectSpec {
  std::string name;   // e.g. disk_d06, hole_d10, corner_a090, volute, fillet
  ObjectKind kind = ObjectKind::kDisk;
  double param = 0;   // diameter (mm), corner angle (deg), or 0
  Polyline contour;   // the true edge; walking it keeps the object on the left
  double top_z_m = kObjectTopZ;
  // Trial set-up: the cup lands at `start` (cup centre inside the object near the edge) and
  // follows with the object on its left. Closed contours succeed after sweeping
  // `success_sweep_deg` about `sweep_centre`; open ones when the arc position along the contour
  // passes `end_arc_m`.
  Point2 start{};
  Point2 sweep_centre{};
  double success_sweep_deg = 355;
  double end_arc_m = 0;
  std::vector<ConvexPiece> pieces;
  std::vector<HeightField> heightfields;
  std::string description;  // dimensions in words, for docs and tables

  bool closed() const { return contour.closed; }
};

ObjectSpec MakeDisk(double diameter_mm);
ObjectSpec MakeHole(double diameter_mm);
ObjectSpec MakeCorner(double alpha_deg);  // 0 < alpha < 360; convex below 180
ObjectSpec MakeVolute();
ObjectSpec MakeSemicircleStrip();
ObjectSpec MakeSemisquareStrip();
ObjectSpec MakeFillet();

// Fillet radius (m) at position x_m along the 180 mm edge: monotone cubic through the published
// cross-sections 0, 4.7, 10.4, 14.5, 16.0 mm at 0, 45, 90, 135, 180 mm.
double FilletRadius(double x_m);

// The published set: disks and holes 2..14 mm, the 35 mm-radius disk, corners every 15 deg from
// 15 to 345, the three compound shapes and the fillet.
std::vector<ObjectSpec> AllObjects();
// One object by name (as in AllObjects(), or corner_aNNN for any angle); empty name if unknown.
ObjectSpec ObjectByName(const std::string& name);

}  // namespace ssc

#endif  // SSC_OBJECTS_OBJECT_SPEC_H_
