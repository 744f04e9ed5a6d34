// The lip as the pressure plugin binds it in a model: what carries the rim, where the rim points
// are at a sample, which touch a surface, and the lip's passive forces. Two kinds of lip:
//   - segments: geoms of lip_geom_group under the sensor site's body, each on a slide joint
//     (models/ssc_tool.xml): ring bending couples the slides; the carrier body's shear slides
//     and tilt hinges get springs from the lip_* keys;
//   - skirt: a 2-D MuJoCo flex whose vertices hang under the site's body, pinned along its
//     throat to the site's body or a body on it (a chamber body on its bellows,
//     models/ssc_tool_flex.xml): the engine's own elasticity deforms it; its deepest vertices
//     at rest are the rim points; each rim point's column runs from its stretch of the throat out
//     to it; the column's seal point is its deepest vertex now (the rim, or the crease of a lobe
//     folded in under the cup), and its passage the narrowest gap under it (air entering at the
//     rim reaches the throat only through it); each chamber's vacuum loads the skirt's
//     triangles on their rest underside and the ceiling inside the throat.
// A model with lip geoms uses them; otherwise the first 2-D flex under the site's body.
// MuJoCo adapter: the physics it calls lives in pneumatics/ (lip_ring.h, lip_rim.h).
#ifndef SSC_PLUGIN_LIP_BODY_H_
#define SSC_PLUGIN_LIP_BODY_H_

#include <mujoco/mujoco.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/lip_ring.h"

namespace ssc {

class LipBody {
 public:
  enum class Kind { kSegments, kSkirt };

  // Finds the lip under site `site_id`; false + *error (naming what is missing) on a bad model.
  bool Bind(const mjModel* m, int site_id, int lip_geom_group, const LipMechanics& mechanics,
            std::string* error);

  Kind kind() const { return kind_; }
  int num_rim_points() const { return static_cast<int>(rim_angle_rad_.size()); }
  // Angle of each rim point in the site's xy-plane at the reference pose.
  const std::vector<double>& rim_angles_rad() const { return rim_angle_rad_; }
  // Mean distance of the rim points from the site's axis at the reference pose.
  double rim_radius_m() const { return rim_radius_m_; }
  // The body whose frame carries the opening, and the site's pose in it.
  int carrier_body() const { return carrier_body_; }
  const mjtNum* opening_offset_pos() const { return opening_offset_pos_; }
  const mjtNum* opening_offset_mat() const { return opening_offset_mat_; }

  // A skirt's seal points now: each column's deepest vertex along `axis_z` below `origin` (the
  // opening's frame, world). Call once per sample before RimPos and MarkContacts; segments
  // have none (a no-op). Allocates nothing.
  void FindSealPoints(const mjData* d, const mjtNum origin[3], const mjtNum axis_z[3]) const;
  // World position of rim point i now (a skirt's: its column's seal point), and how far its
  // surface reaches beyond that point.
  const mjtNum* RimPos(const mjData* d, int i) const;
  double rim_tip_radius_m(int i) const { return rim_tip_radius_m_[i]; }
  // Sets touching[i] to 1 for each rim point that MuJoCo reports in contact with a non-lip geom
  // (a skirt's: its seal point touching a geom that is not the tool's own, e.g. a wall).
  void MarkContacts(const mjModel* m, const mjData* d, unsigned char* touching) const;
  // A skirt's passage from rim point i's rim in to the throat: air that enters under the rim
  // reaches the opening through the narrowest gap under the column (0 where a vertex touches an
  // object, per the last MarkContacts; kNoSurfaceGapM when no surface lies under any). Depths
  // from `surface_depth_at(point on the lip plane, ctx)`. Allocates nothing.
  double ColumnGap(int i, const mjData* d, const mjtNum origin[3], const mjtNum axis_z[3],
                   double (*surface_depth_at)(const mjtNum[3], void*), void* ctx) const;
  // A skirt's lobe in the throat's mouth along one radial direction (`angle_rad` in the frame
  // `frame`, the opening's, at `origin`): the innermost distance from the axis of the skirt's
  // vertices within `half_width_rad` of it, inside `radius_m` and no more than one skirt
  // thickness below the throat (folded in under the cup and held against the throat and the
  // walls' ends); `radius_m` when none. Allocates nothing.
  double MouthCover(const mjData* d, const mjtNum origin[3], const mjtNum frame[9],
                    double angle_rad, double half_width_rad, double radius_m) const;
  // The deepest the lip can be pressed below a surface before a rigid part of the tool lands or
  // its travel ends (the segments' slide range; the skirt's clearance under the chamber walls),
  // and why; infinite with an empty reason when nothing bounds it (rigid segments).
  double max_press_m() const { return max_press_m_; }
  const std::string& max_press_why() const { return max_press_why_; }
  // Whether the skirt's fold can move the rim across the opening (the sensor then follows the
  // rim's radius per wedge); segments stay on their circle by construction.
  bool rim_moves_radially() const { return kind_ == Kind::kSkirt; }

  // Passive forces into d->qfrc_passive: ring bending and carrier springs (segments), or each
  // chamber's vacuum on the skirt's triangles and on the cup (skirt, when vacuum_load). Switches
  // the carrier's equality locks to match the config. `vacuum_force_n` gets the sum of the
  // vacuum forces applied (world frame; zero when none), `vacuum_torque_nm` their moment about
  // the tool site (world frame). Allocates nothing.
  void ApplyForces(const mjModel* m, mjData* d, const std::array<double, kNumChambers>& vacuum_pa,
                   bool vacuum_load, mjtNum vacuum_force_n[3], mjtNum vacuum_torque_nm[3]) const;
  // A skirt's ceiling over one chamber: a quarter of the disk inside its pinned ring (the rest of
  // the cavity's projected area is the skirt's own, loaded triangle by triangle).
  double ceiling_area_m2() const { return ceiling_area_m2_; }

 private:
  bool BindSegments(const mjModel* m, int root, int lip_geom_group, std::string* error);
  bool BindSkirt(const mjModel* m, int root, std::string* error);
  bool BindCarrier(const mjModel* m, std::string* error);
  void ApplySegmentForces(mjData* d) const;
  void ApplySkirtVacuum(const mjModel* m, mjData* d,
                        const std::array<double, kNumChambers>& vacuum_pa, mjtNum vacuum_force_n[3],
                        mjtNum vacuum_torque_nm[3]) const;

  Kind kind_ = Kind::kSegments;
  int site_id_ = -1;
  LipMechanics mechanics_;
  std::vector<double> rim_angle_rad_;
  std::vector<double> rim_tip_radius_m_;
  double rim_radius_m_ = 5.5e-3;
  int carrier_body_ = 0;
  mjtNum opening_offset_pos_[3] = {0, 0, 0};
  mjtNum opening_offset_mat_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double max_press_m_ = std::numeric_limits<double>::infinity();
  std::string max_press_why_;

  // Segments.
  std::vector<int> segment_geom_;     // geom of each rim point
  std::vector<int> segment_of_geom_;  // rim point of each geom id, -1 if none
  std::vector<int> segment_dof_, segment_qpos_;
  RingModeShapes ring_shapes_;
  mutable std::vector<double> ring_u_, ring_force_;
  double ring_mode_cap_n_per_m_ = kNoModeCap;
  struct CarrierJoint {
    int dof = 0, qpos = 0, lock = -1;  // lock: equality constraint that pins it, -1 if none
    bool is_tilt = false;              // hinge (tilt) or slide (shear)
  };
  std::vector<CarrierJoint> carrier_joints_;

  // Skirt.
  int flex_ = -1;
  std::vector<int> rim_vertex_;  // flex vertex (global id) of each rim point
  // The vertices (global ids) above each rim point, throat to rim, column i in
  // column_vertex_[column_start_[i] .. column_start_[i + 1]).
  std::vector<int> column_start_, column_vertex_;
  mutable std::vector<int> seal_vertex_;  // per sample: each column's seal point (global id)
  mutable std::vector<unsigned char> vertex_touching_;  // per sample, by the flex's vertex index
  std::vector<double> element_cavity_side_;             // +1 / -1 on each triangle's winding
  int column_adr_ = 0;                                  // the flex's first vertex (global id)
  double column_radius_m_ = 0.0;                        // the skirt's contact radius
  double throat_depth_m_ = 0.0;  // the pinned ring below the opening's origin (negative: above)
  mutable std::vector<double> column_depth_, column_radius_;  // scratch, longest column's size
  std::vector<unsigned char> tool_geom_;  // geoms carried by the tool (walls): never a seal
  double ceiling_area_m2_ = 0.0;
};

}  // namespace ssc

#endif  // SSC_PLUGIN_LIP_BODY_H_
