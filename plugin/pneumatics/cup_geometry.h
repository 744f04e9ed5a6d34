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
  double opening_radius_m = 5.5e-3;    // internal (opening) radius, published 11 mm diameter
  double open_depth_m = 2.75e-3;       // a surface this much deeper than the air's path lets the
                                       // air across freely; shallower layers throttle it in
                                       // proportion (opening radius / 2: then a layer of gap g
                                       // over the whole opening passes what the lip curtain at
                                       // gap g does)
  double lip_roughness_gap_m = 18e-6;  // leak gap of a lip segment lying on a surface
  int rays_per_chamber = 4;            // radial rays (wedges) sampling each chamber's opening

  std::string Validate() const;
  double ChamberOpeningArea() const;  // one quadrant of the opening, m^2
};

// Chamber index (0..3) of a direction at `angle_rad` in the tool xy-plane.
int ChamberOfAngle(double angle_rad);

// Angle of radial ray j (0 <= j < rays_per_chamber) of chamber c: the rays split each quadrant
// into equal wedges and run along their bisectors.
double RayAngle(int chamber, int j, int rays_per_chamber);

// Gap recorded where no surface is within reach below a point.
inline constexpr double kNoSurfaceGapM = 1.0;
// Each stretch of a wedge between two surface crossings is sampled at this many radii.
inline constexpr int kSamplesPerStretch = 2;
inline constexpr int kMaxWedgeSamples = kSamplesPerStretch * (kMaxCrossings + 2);

// A piece of one wedge of the opening (plan area) and the gap from the lip tips' plane down to
// the surface below it (kNoSurfaceGapM when none).
struct GapSample {
  double area_m2 = 0.0;
  double gap_m = 0.0;
};

// One wedge of a chamber's opening: what the leak model needs to know about it.
struct OpeningWedge {
  int chamber = 0;
  double dtheta_rad = 0.0;
  double rim_gap_m = kNoSurfaceGapM;  // lip tip to the surface at the wedge's rim; 0 = touching
  // Where the lip's rim stands across this wedge, from the axis; <= 0 = on the opening's edge.
  // A lip folded inward stands inside the opening: the part of the wedge beyond it is covered by
  // lip material (no air path), and the curtain under the rim is that much shorter.
  double rim_radius_m = 0.0;
  std::array<GapSample, kMaxWedgeSamples> samples{};
  int n_samples = 0;
};

// Radii at which a stretch [r0, r1] of a wedge is sampled: the middles of equal-area parts, so
// every sample stands for the same area, (dtheta / 2)(r1^2 - r0^2) / kSamplesPerStretch.
void StretchSampleRadii(double r0_m, double r1_m, double radius_out_m[kSamplesPerStretch]);
// Appends the samples of a stretch to `wedge` given the gaps at StretchSampleRadii.
void AddStretch(double r0_m, double r1_m, const double gap_m[kSamplesPerStretch],
                OpeningWedge* wedge);

// Leak of one wedge. Air reaches the chamber by passing under the lip at the wedge's rim and
// then rising through the opening over the layer of air between the lip tips' plane and the
// surface. Split that path at a depth z below the tips' plane: air above z has crossed the lip
// curtain R dtheta z; air below z must rise through the opening where the surface lies deeper
// than z, a layer of thickness (gap - z) passing its area times min(1, (gap - z) / open_depth).
// The leak is the smallest such cut (a min-cut over z in [0, rim_gap]):
//   A = min_z [ R dtheta (z + roughness) + sum_k a_k w(gap_k - z) ],  w(h) = clamp(h / open_depth).
// A sharp edge (gaps 0 or far) gives the uncovered opening; a lip hovering at g over a plate
// gives the curtain R dtheta g; slopes and fillets give everything in between, continuously.
// `jet_area_m2` is the opening through which air rises as a jet past the sensor tap: open
// opening counts fully, thin layers by w^2 (their air arrives as a sheet along the surface, as
// does the curtain flow under a hovering lip); never more than the leak itself.
struct WedgeLeak {
  double area_m2 = 0.0;
  double jet_area_m2 = 0.0;
  double sealed_area_m2 = 0.0;  // diagnostics: the opening the surface closes, sum a_k (1 - w)
};
WedgeLeak WedgeLeakArea(const CupGeometry& geometry, const OpeningWedge& wedge);

// Per-chamber sums of the wedges' leaks.
struct ChamberLeaks {
  std::array<double, kNumChambers> area_m2{};
  std::array<double, kNumChambers> jet_area_m2{};
  std::array<double, kNumChambers> sealed_area_m2{};
};
ChamberLeaks LeakAreas(const CupGeometry& geometry, const OpeningWedge* wedges, int n_wedges);

// State of one lip segment for one sample (diagnostics and the rim gaps).
struct LipSegmentState {
  int chamber = 0;          // 0..3
  double arc_m = 0.0;       // length of lip this segment stands for
  bool in_contact = false;  // touching a surface (from the simulator's contacts)
  double gap_m = 1.0;       // if not in contact: from the segment's tip to the surface below
};

// Analytic probes used for calibration and tests; they fill the wedges as the MuJoCo adapter
// would, with the lip tips on the plane z = 0 (rigid lip).
struct EdgeProbe {
  std::array<OpeningWedge, kNumChambers * kMaxRaysPerChamber> wedges{};
  int n_wedges = 0;
};
// A flat surface at the lip plane covering {p : n . p <= edge_offset_m}, n = (cos normal_angle,
// sin normal_angle) pointing from the covered side to the open side, ending in a sharp edge with
// nothing below; edge_offset_m > 0 means the cup centre sits that far inside the edge.
EdgeProbe ProbeStraightEdge(const CupGeometry& geometry, double edge_offset_m,
                            double normal_angle_rad);
// The same edge rounded by a fillet of radius fillet_radius_m (quarter circle from the flat top
// to a vertical face); edge_offset_m is measured from where the rounding starts.
EdgeProbe ProbeRoundedEdge(const CupGeometry& geometry, double edge_offset_m,
                           double normal_angle_rad, double fillet_radius_m);
// A plate through the cup centre at the lip plane, sloping down by `slope` (rise over run)
// along the direction normal_angle_rad; the lip rests on the plate where it is highest.
EdgeProbe ProbeSlopedPlate(const CupGeometry& geometry, double slope, double normal_angle_rad);
// A plate parallel to the lip plane, gap_m below the lip tips.
EdgeProbe ProbeFlatPlate(const CupGeometry& geometry, double gap_m);

// Static pressures for a probe's leaks.
FlowSolution SolveProbe(const CupGeometry& geometry, const PneumaticParams& params,
                        const EdgeProbe& probe);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_CUP_GEOMETRY_H_
