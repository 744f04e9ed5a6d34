// Geometry of the cup's opening and lip: which chamber a direction belongs to, the sealed part
// of each chamber's opening, and each chamber's leak area. Pure C++: no MuJoCo types.
//
// Tool frame (the authors' implementation): +x points at the south chambers, +y at the west
// chambers, +z down into the object; the lip plane is z = 0. Angles are measured in the tool
// xy-plane from +x toward +y. Chamber indices 0..3 are the published chambers 1..4:
//   index 0 = chamber 1 = south-east = (+x, -y), angles [-90 deg, 0)
//   index 1 = chamber 2 = north-east = (-x, -y), angles [-180 deg, -90 deg)
//   index 2 = chamber 3 = north-west = (-x, +y), angles [90 deg, 180 deg)
//   index 3 = chamber 4 = south-west = (+x, +y), angles [0, 90 deg)
#ifndef SSC_PLUGIN_PNEUMATICS_CUP_GEOMETRY_H_
#define SSC_PLUGIN_PNEUMATICS_CUP_GEOMETRY_H_

#include <array>
#include <string>

#include "plugin/pneumatics/flow_network.h"

namespace ssc {

inline constexpr int kMaxRaysPerChamber = 64;
inline constexpr int kMaxLipSegments = 256;
inline constexpr int kMaxCrossings = 8;  // surface crossings followed along one radial ray

struct CupGeometry {
  double opening_radius_m = 5.5e-3;   // internal (opening) radius, published 11 mm diameter
  double seal_distance_m = 2.75e-3;   // a surface this far below the lip plane still seals
  double lip_roughness_gap_m = 18e-6; // leak gap of a lip segment lying on a surface
  int rays_per_chamber = 4;           // radial rays sampling each chamber's opening

  std::string Validate() const;
  double ChamberOpeningArea() const;  // one quadrant of the opening, m^2
};

// Chamber index (0..3) of a direction at `angle_rad` in the tool xy-plane.
int ChamberOfAngle(double angle_rad);

// Angle of radial ray j (0 <= j < rays_per_chamber) of chamber c: the rays split each quadrant
// into equal sub-sectors and run along their bisectors.
double RayAngle(int chamber, int j, int rays_per_chamber);

// Covered area of one sub-sector of angle dtheta_rad swept by a radial ray: the ray starts at the
// opening centre (covered or not) and toggles state at each crossing (sorted, metres from the
// centre); everything beyond radius_m is ignored.
double SubSectorCoveredArea(bool centre_covered, const double* crossings_m, int n_crossings,
                            double radius_m, double dtheta_rad);

// State of one lip segment for one sample.
struct LipSegmentState {
  int chamber = 0;         // 0..3
  double arc_m = 0.0;      // length of lip this segment stands for
  bool in_contact = false; // touching a surface (from the simulator's contacts)
  double gap_m = 1.0;      // if not in contact: distance from lip plane to the surface below
};

// Leak area of each chamber: its uncovered opening, plus lip gaps of segments hovering within the
// seal distance of a surface, plus the roughness leak of segments lying on a surface. Segments
// with no surface within the seal distance add nothing: the air they let in is already counted by
// the uncovered opening they sit over.
std::array<double, kNumChambers> LeakAreas(const CupGeometry& geometry,
                                           const std::array<double, kNumChambers>& sealed_area_m2,
                                           const LipSegmentState* segments, int n_segments);

// Analytic probe used for calibration and tests: a flat surface covering the half-plane
// {p : n . p <= edge_offset_m} of the lip plane, n = (cos normal_angle, sin normal_angle) pointing
// from the covered side to the open side; edge_offset_m > 0 means the cup centre sits that far
// inside the edge. Lip segments at lip_radius_m, evenly spaced, segment 0 centred on angle
// lip_phase_rad. Fills the sealed areas and segment states as the MuJoCo adapter would.
struct EdgeProbe {
  std::array<double, kNumChambers> sealed_area_m2{};
  std::array<LipSegmentState, kMaxLipSegments> segments{};
  int n_segments = 0;
};
EdgeProbe ProbeStraightEdge(const CupGeometry& geometry, double edge_offset_m,
                            double normal_angle_rad, double lip_radius_m, int n_lip_segments,
                            double lip_phase_rad);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_CUP_GEOMETRY_H_
