// The lip's rim as the pressure model sees it, whatever carries it (rigid segments on slides or
// the rim of a deformable skirt): points on a ring at known angles, each with a gap to the
// surface below. Pure C++: no MuJoCo types.
#ifndef SSC_PLUGIN_PNEUMATICS_LIP_RIM_H_
#define SSC_PLUGIN_PNEUMATICS_LIP_RIM_H_

#include <array>
#include <vector>

namespace ssc {

// The rim points either side of a wedge's bisector and the weight of the second: the wedge's rim
// gap, depth and radius interpolate between them.
struct WedgeRim {
  int point[2] = {0, 0};
  double weight1 = 0.0;
};

// For each wedge (chamber c, ray j, in the order c * rays_per_chamber + j) the rim points either
// side of its bisector, from the points' angles (radians, any order, at least one point).
std::vector<WedgeRim> AssignWedgeRims(const std::vector<double>& rim_angles_rad,
                                      int rays_per_chamber);

// Where a value held by the rim points stands at a wedge: the weighted mean of its two points.
inline double AtWedge(const WedgeRim& rim, const double* per_point) {
  return (1.0 - rim.weight1) * per_point[rim.point[0]] + rim.weight1 * per_point[rim.point[1]];
}

// The vertices of a skirt mesh that form its free rim: those within `tolerance_m` of the deepest
// vertex along the cup axis (depth_m[i] = vertex i's depth below the lip plane, + into the
// object). Indices in ascending order.
std::vector<int> RimVertices(const std::vector<double>& depth_m, double tolerance_m);

// A skirt's columns: the vertices that hang above each rim point, from the axis down to the rim.
// A vertex joins the rim point(s) nearest to it in angle (two when it lies midway between them).
// `vertex_angles_rad` are the skirt's free vertices' angles, `rim_angles_rad` the rim points'
// (any order, at least one); column i lists indices into vertex_angles_rad, ascending.
std::vector<std::vector<int>> SkirtColumns(const std::vector<double>& vertex_angles_rad,
                                           const std::vector<double>& rim_angles_rad);

// Where a skirt column meets the surface first: its deepest vertex along the cup axis (depth_m,
// + into the object), whichever ring it belongs to: the rim on an unfolded skirt, the crease of
// one folded in on itself. Vertices within `tolerance_m` of the deepest are a stretch lying flat
// at that depth; the innermost of them (smallest radius_m from the axis) is the seal point, the
// lip covering the opening beyond it. Returns an index into the n values, -1 when n is 0.
int ColumnSealPoint(const double* depth_m, const double* radius_m, int n, double tolerance_m);

// Half the cross product of a triangle's edges p1 - p0 and p2 - p0: its area along its normal,
// the side set by the winding.
std::array<double, 3> TriangleAreaVector(const double p0[3], const double p1[3],
                                         const double p2[3]);

// The force (N) of a pressure difference on a flat triangle p0 p1 p2 (world, m): `vacuum_pa`
// (positive: the cavity side is at lower pressure) times the triangle's area, along its normal
// turned toward `cavity_point` (a point inside the cavity, e.g. on the cup axis). Each vertex
// takes a third. Zero for a degenerate triangle.
std::array<double, 3> TrianglePressureForce(const double p0[3], const double p1[3],
                                            const double p2[3], double vacuum_pa,
                                            const double cavity_point[3]);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_LIP_RIM_H_
