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

// The force (N) of a pressure difference on a flat triangle p0 p1 p2 (world, m): `vacuum_pa`
// (positive: the cavity side is at lower pressure) times the triangle's area, along its normal
// turned toward `cavity_point` (a point inside the cavity, e.g. on the cup axis). Each vertex
// takes a third. Zero for a degenerate triangle.
std::array<double, 3> TrianglePressureForce(const double p0[3], const double p1[3],
                                            const double p2[3], double vacuum_pa,
                                            const double cavity_point[3]);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_LIP_RIM_H_
