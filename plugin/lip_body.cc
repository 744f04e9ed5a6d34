#include "plugin/lip_body.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/strict_number.h"
#include "plugin/body_tree.h"
#include "plugin/chamber_pressure_config.h"
#include "plugin/pneumatics/lip_rim.h"

namespace ssc {
namespace {

// A skirt vertex within this much of the deepest one belongs to the rim.
constexpr double kRimToleranceM = 0.1e-3;
// Depth below the lip plane of the point on the axis that every skirt triangle's underside faces
// at rest.
constexpr double kCavityDepthM = 10e-3;

// Point `p` given in body `b`'s frame, in the frame of its ancestor `root`, at the model's
// reference pose (body offsets only: init has no mjData).
void ToRootFrame(const mjModel* m, int b, int root, mjtNum p[3]) {
  for (; b != root && b > 0; b = m->body_parentid[b]) {
    mjtNum rotated[3];
    mju_rotVecQuat(rotated, p, m->body_quat + 4 * b);
    for (int k = 0; k < 3; ++k) p[k] = rotated[k] + m->body_pos[3 * b + k];
  }
}

// `p` (root frame) in the site's frame.
void ToSiteFrame(const mjModel* m, int site_id, const mjtNum p[3], mjtNum local[3]) {
  mjtNum site_quat_inv[4];
  mju_negQuat(site_quat_inv, m->site_quat + 4 * site_id);
  const mjtNum rel[3] = {p[0] - m->site_pos[3 * site_id], p[1] - m->site_pos[3 * site_id + 1],
                         p[2] - m->site_pos[3 * site_id + 2]};
  mju_rotVecQuat(local, rel, site_quat_inv);
}

// How far geom g reaches below the lip plane (site frame, +z toward the object) at the reference
// pose: the deepest corner of its bounding box; negative when it ends above the plane.
double GeomDepth(const mjModel* m, int g, int root, int site_id) {
  const mjtNum* aabb = m->geom_aabb + 6 * g;
  double deepest = -1e9;
  for (int corner = 0; corner < 8; ++corner) {
    const mjtNum in_geom[3] = {aabb[0] + ((corner & 1) ? aabb[3] : -aabb[3]),
                               aabb[1] + ((corner & 2) ? aabb[4] : -aabb[4]),
                               aabb[2] + ((corner & 4) ? aabb[5] : -aabb[5])};
    mjtNum p[3];
    mju_rotVecQuat(p, in_geom, m->geom_quat + 4 * g);
    for (int k = 0; k < 3; ++k) p[k] += m->geom_pos[3 * g + k];
    ToRootFrame(m, m->geom_bodyid[g], root, p);
    mjtNum local[3];
    ToSiteFrame(m, site_id, p, local);
    deepest = std::max(deepest, static_cast<double>(local[2]));
  }
  return deepest;
}

// The body that carries a flex's pinned vertices: the one body several vertices share (MuJoCo
// gives each free vertex a body of its own).
int PinnedBody(const mjModel* m, int flex) {
  const int adr = m->flex_vertadr[flex], n = m->flex_vertnum[flex];
  int best = m->flex_vertbodyid[adr], best_count = 0;
  for (int v = 0; v < n; ++v) {
    const int b = m->flex_vertbodyid[adr + v];
    const int count =
        static_cast<int>(std::count(m->flex_vertbodyid + adr, m->flex_vertbodyid + adr + n, b));
    if (count > best_count) {
      best = b;
      best_count = count;
    }
  }
  return best;
}

std::string FormatMm(double m) { return FormatNumber(m * 1e3) + " mm"; }

std::string Fail(const std::string& what) {
  return std::string(kChamberPressurePluginName) + ": " + what;
}

}  // namespace

bool LipBody::Bind(const mjModel* m, int site_id, int lip_geom_group, const LipMechanics& mechanics,
                   std::string* error) {
  site_id_ = site_id;
  mechanics_ = mechanics;
  const int root = m->site_bodyid[site_id];
  segment_of_geom_.assign(m->ngeom, -1);
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_group[g] == lip_geom_group && IsInSubtree(m, m->geom_bodyid[g], root)) {
      segment_of_geom_[g] = static_cast<int>(segment_geom_.size());
      segment_geom_.push_back(g);
    }
  }
  if (!segment_geom_.empty()) return BindSegments(m, root, lip_geom_group, error);
  if (!BindSkirt(m, root, error)) {
    if (flex_ < 0) {
      *error = Fail("found 0 lip segment geoms (group " + std::to_string(lip_geom_group) +
                    ") and no 2-D flex skirt under the site's body");
    }
    return false;
  }
  return true;
}

bool LipBody::BindSegments(const mjModel* m, int root, int lip_geom_group, std::string* error) {
  kind_ = Kind::kSegments;
  const int n_seg = static_cast<int>(segment_geom_.size());
  if (n_seg > kMaxLipSegments) {
    *error = Fail("found " + std::to_string(n_seg) + " lip segment geoms (group " +
                  std::to_string(lip_geom_group) + ") under the site's body; need 1 to " +
                  std::to_string(kMaxLipSegments));
    return false;
  }
  // Each segment's direction at the reference pose; arcs split the circumference evenly.
  double radius_sum = 0.0;
  for (int g : segment_geom_) {
    mjtNum p[3] = {m->geom_pos[3 * g], m->geom_pos[3 * g + 1], m->geom_pos[3 * g + 2]};
    ToRootFrame(m, m->geom_bodyid[g], root, p);
    mjtNum local[3];
    ToSiteFrame(m, site_id_, p, local);
    rim_angle_rad_.push_back(std::atan2(local[1], local[0]));
    radius_sum += std::hypot(local[0], local[1]);
    const int type = m->geom_type[g];
    rim_tip_radius_m_.push_back(type == mjGEOM_CAPSULE || type == mjGEOM_SPHERE
                                    ? m->geom_size[3 * g]
                                    : m->geom_size[3 * g + 2]);
  }
  rim_radius_m_ = radius_sum / n_seg;
  // The carrier: the common parent of the segments' bodies (the site's body in a rigid cup).
  int carrier = -1;
  for (int g : segment_geom_) {
    const int b = m->geom_bodyid[g];
    const int parent = b == root ? root : m->body_parentid[b];
    if (carrier < 0) carrier = parent;
    if (parent != carrier) {
      carrier = root;
      break;
    }
  }
  if (carrier != root && m->body_parentid[carrier] != root) {
    *error = Fail("the lip segments' parent body must be the tool site's body or its child");
    return false;
  }
  carrier_body_ = carrier;
  return BindCarrier(m, error);
}

bool LipBody::BindCarrier(const mjModel* m, std::string* error) {
  const int root = m->site_bodyid[site_id_];
  const int carrier = carrier_body_;
  const double dt = m->opt.timestep;
  // The site's pose in the carrier's frame at the reference configuration.
  mjtNum site_mat[9];
  mju_quat2Mat(site_mat, m->site_quat + 4 * site_id_);
  if (carrier == root) {
    mju_copy3(opening_offset_pos_, m->site_pos + 3 * site_id_);
    mju_copy(opening_offset_mat_, site_mat, 9);
  } else {
    mjtNum carrier_mat[9], rel[3];
    mju_quat2Mat(carrier_mat, m->body_quat + 4 * carrier);
    mju_sub3(rel, m->site_pos + 3 * site_id_, m->body_pos + 3 * carrier);
    mju_mulMatTVec3(opening_offset_pos_, carrier_mat, rel);
    mju_mulMatTMat(opening_offset_mat_, carrier_mat, site_mat, 3, 3, 3);
  }

  if (kind_ == Kind::kSkirt) return true;  // the skirt's own elasticity bends and shears it
  // Ring bending acts on each segment's slide joint.
  double min_mass = 1e9, travel_m = max_press_m_;
  for (int g : segment_geom_) {
    const int b = m->geom_bodyid[g];
    const int j = m->body_jntadr[b];
    if (m->body_jntnum[b] < 1 || m->jnt_type[j] != mjJNT_SLIDE) {
      segment_dof_.clear();
      segment_qpos_.clear();
      break;
    }
    segment_dof_.push_back(m->jnt_dofadr[j]);
    segment_qpos_.push_back(m->jnt_qposadr[j]);
    min_mass = std::min(min_mass, m->dof_M0[m->jnt_dofadr[j]]);
    if (m->jnt_limited[j])
      travel_m = std::min(travel_m, m->jnt_range[2 * j + 1] - m->jnt_range[2 * j]);
  }
  if (!segment_dof_.empty() && travel_m < max_press_m_) {
    max_press_m_ = travel_m;
    max_press_why_ = "the lip segments' slide joints travel " + FormatMm(travel_m);
  }
  if (mechanics_.bending_stiffness_nm2 > 0 && segment_dof_.empty()) {
    *error = Fail("lip_bending_nmm2 > 0 needs a slide joint on every lip segment's body");
    return false;
  }
  // Explicit springs stay stable while omega * dt <= 1: modes stiffer than that are capped.
  if (!segment_dof_.empty()) ring_mode_cap_n_per_m_ = min_mass / (dt * dt);
  const int n_seg = num_rim_points();
  ring_u_.assign(n_seg, 0.0);
  ring_force_.assign(n_seg, 0.0);
  ring_shapes_ = MakeRingModeShapes(rim_angle_rad_.data(), n_seg);

  // Carrier joints: slides shear, hinges tilt; each may be pinned by a joint equality.
  bool has_shear = false, has_tilt = false;
  if (carrier != root) {
    for (int j = m->body_jntadr[carrier]; j < m->body_jntadr[carrier] + m->body_jntnum[carrier];
         ++j) {
      if (m->jnt_type[j] != mjJNT_SLIDE && m->jnt_type[j] != mjJNT_HINGE) continue;
      CarrierJoint cj;
      cj.dof = m->jnt_dofadr[j];
      cj.qpos = m->jnt_qposadr[j];
      cj.is_tilt = m->jnt_type[j] == mjJNT_HINGE;
      for (int e = 0; e < m->neq; ++e) {
        if (m->eq_type[e] == mjEQ_JOINT && m->eq_obj1id[e] == j && m->eq_obj2id[e] < 0) cj.lock = e;
      }
      const double k =
          cj.is_tilt ? mechanics_.tilt_stiffness_nm_per_rad : mechanics_.shear_stiffness_n_per_m;
      const double k_max = m->dof_M0[cj.dof] / (dt * dt);
      if (k > k_max) {
        std::ostringstream os;
        if (cj.is_tilt) {
          os << "lip_tilt_nmm_per_deg = " << k * 1e3 * M_PI / 180
             << " is too stiff for the time step " << dt << " s: stable up to "
             << k_max * 1e3 * M_PI / 180 << " N mm/deg (or make the tilt hinge's armature larger)";
        } else {
          os << "lip_shear_n_per_mm = " << k * 1e-3 << " is too stiff for the time step " << dt
             << " s: stable up to " << k_max * 1e-3
             << " N/mm (or make the shear slides' armature larger)";
        }
        *error = Fail(os.str());
        return false;
      }
      (cj.is_tilt ? has_tilt : has_shear) = true;
      carrier_joints_.push_back(cj);
    }
  }
  if (mechanics_.shear_stiffness_n_per_m > 0 && !has_shear) {
    *error = Fail(
        "lip_shear_n_per_mm > 0 needs slide joints on the lip carrier body (models/ssc_tool.xml)");
    return false;
  }
  if (mechanics_.tilt_stiffness_nm_per_rad > 0 && !has_tilt) {
    *error = Fail(
        "lip_tilt_nmm_per_deg > 0 needs hinge joints on the lip carrier body "
        "(models/ssc_tool.xml)");
    return false;
  }
  return true;
}

bool LipBody::BindSkirt(const mjModel* m, int root, std::string* error) {
  kind_ = Kind::kSkirt;
  for (int f = 0; f < m->nflex && flex_ < 0; ++f) {
    if (m->flex_dim[f] != 2 || m->flex_vertnum[f] < 3) continue;
    const int body = m->flex_vertbodyid[m->flex_vertadr[f]];
    if (IsInSubtree(m, body, root)) flex_ = f;
  }
  if (flex_ < 0) {
    *error = Fail(
        "no lip under the tool site's body: neither lip segment geoms (lip_geom_group) "
        "nor a 2-D flex skirt");
    return false;
  }
  if (mechanics_.shear_stiffness_n_per_m > 0 || mechanics_.tilt_stiffness_nm_per_rad > 0) {
    *error = Fail(
        "lip_shear_n_per_mm and lip_tilt_nmm_per_deg act on a segment lip's carrier; a "
        "flex skirt shears and tilts by its own elasticity (set them to 0)");
    return false;
  }
  const int adr = m->flex_vertadr[flex_];
  const int n = m->flex_vertnum[flex_];
  std::vector<double> depth(n);
  std::vector<std::array<mjtNum, 3>> local(n);
  for (int v = 0; v < n; ++v) {
    mjtNum p[3] = {m->flex_vert[3 * (adr + v)], m->flex_vert[3 * (adr + v) + 1],
                   m->flex_vert[3 * (adr + v) + 2]};
    ToRootFrame(m, m->flex_vertbodyid[adr + v], root, p);
    ToSiteFrame(m, site_id_, p, local[v].data());
    depth[v] = local[v][2];
  }
  // The pinned ring: the vertices that share one body (each free vertex has its own), the cup
  // or a body on the cup (a chamber body on its bellows); it bounds the cup's ceiling.
  const int carrier = PinnedBody(m, flex_);
  if (carrier != root && m->body_parentid[carrier] != root) {
    *error = Fail("the flex skirt's pinned ring must hang from the tool site's body or its child");
    return false;
  }
  double pinned_radius_sum = 0.0, pinned_depth_sum = 0.0;
  int pinned = 0;
  for (int v = 0; v < n; ++v) {
    if (m->flex_vertbodyid[adr + v] != carrier) continue;
    pinned_radius_sum += std::hypot(local[v][0], local[v][1]);
    pinned_depth_sum += local[v][2];
    ++pinned;
  }
  if (pinned < 3) {
    *error = Fail("the flex skirt has " + std::to_string(pinned) +
                  " vertices pinned to its carrier body; need its top ring (3 or more)");
    return false;
  }
  const double ceiling_radius_m = pinned_radius_sum / pinned;
  throat_depth_m_ = pinned_depth_sum / pinned;
  ceiling_area_m2_ = 0.25 * M_PI * ceiling_radius_m * ceiling_radius_m;
  double radius_sum = 0.0;
  for (int v : RimVertices(depth, kRimToleranceM)) {
    rim_vertex_.push_back(adr + v);
    rim_angle_rad_.push_back(std::atan2(local[v][1], local[v][0]));
    radius_sum += std::hypot(local[v][0], local[v][1]);
    rim_tip_radius_m_.push_back(m->flex_radius[flex_]);
  }
  if (rim_vertex_.size() < 4 || rim_vertex_.size() > static_cast<size_t>(kMaxLipSegments)) {
    *error = Fail("the flex skirt's rim has " + std::to_string(rim_vertex_.size()) +
                  " vertices; need 4 to " + std::to_string(kMaxLipSegments));
    return false;
  }
  // Each rim point's column: the vertices above it, from its stretch of the throat (pinned) out.
  std::vector<int> column_vertex;
  std::vector<double> column_angle;
  for (int v = 0; v < n; ++v) {
    column_vertex.push_back(adr + v);
    column_angle.push_back(std::atan2(local[v][1], local[v][0]));
  }
  size_t longest = 0;
  column_start_.assign(1, 0);
  for (const std::vector<int>& column : SkirtColumns(column_angle, rim_angle_rad_)) {
    for (int k : column) column_vertex_.push_back(column_vertex[k]);
    column_start_.push_back(static_cast<int>(column_vertex_.size()));
    longest = std::max(longest, column.size());
  }
  seal_vertex_ = rim_vertex_;
  vertex_touching_.assign(n, 0);
  // Each triangle's side toward the cavity at rest, as a sign on its winding's normal: the cavity
  // lies under the skirt (a point on the axis well below the lip plane sees every triangle's
  // underside, however flat the skirt's flare).
  const double below[3] = {0.0, 0.0, kCavityDepthM};
  const int* elems = m->flex_elem + m->flex_elemdataadr[flex_];
  element_cavity_side_.assign(m->flex_elemnum[flex_], 1.0);
  for (int e = 0; e < m->flex_elemnum[flex_]; ++e) {
    const double* p[3] = {local[elems[3 * e]].data(), local[elems[3 * e + 1]].data(),
                          local[elems[3 * e + 2]].data()};
    const std::array<double, 3> a = TriangleAreaVector(p[0], p[1], p[2]);
    const std::array<double, 3> f = TrianglePressureForce(p[0], p[1], p[2], 1.0, below);
    element_cavity_side_[e] = a[0] * f[0] + a[1] * f[1] + a[2] * f[2] < 0 ? -1.0 : 1.0;
  }
  column_adr_ = adr;
  column_radius_m_ = m->flex_radius[flex_];
  column_depth_.assign(longest, 0.0);
  column_radius_.assign(longest, 0.0);
  tool_geom_.assign(m->ngeom, 0);
  for (int g = 0; g < m->ngeom; ++g) tool_geom_[g] = IsInSubtree(m, m->geom_bodyid[g], root);
  // Pressed deeper than the clearance of the tool's own colliding geoms (the chamber walls) less
  // the skirt's thickness, the skirt lies flat between them and the object: the walls land.
  for (int g = 0; g < m->ngeom; ++g) {
    if (!tool_geom_[g] || (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0)) continue;
    const double clearance_m = -GeomDepth(m, g, root, site_id_);
    if (clearance_m <= 0) continue;  // reaches past the lip plane: not a floor to the press
    const double press_m = clearance_m - 2.0 * column_radius_m_;
    if (press_m < max_press_m_) {
      max_press_m_ = press_m;
      const char* name = mj_id2name(m, mjOBJ_GEOM, g);
      max_press_why_ = "the tool's geom '" + std::string(name != nullptr ? name : "?") + "' ends " +
                       FormatMm(clearance_m) + " above the lip plane, less the skirt's thickness " +
                       FormatMm(2.0 * column_radius_m_);
    }
  }
  rim_radius_m_ = radius_sum / static_cast<double>(rim_vertex_.size());
  carrier_body_ = carrier;
  return BindCarrier(m, error);
}

void LipBody::FindSealPoints(const mjData* d, const mjtNum origin[3],
                             const mjtNum axis_z[3]) const {
  if (kind_ != Kind::kSkirt) return;
  for (int i = 0; i < num_rim_points(); ++i) {
    const int first = column_start_[i], n = column_start_[i + 1] - first;
    if (n == 0) continue;  // the rim vertex alone
    for (int k = 0; k < n; ++k) {
      const mjtNum* p = d->flexvert_xpos + 3 * column_vertex_[first + k];
      const mjtNum rel[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
      const mjtNum along = mju_dot3(rel, axis_z);
      column_depth_[k] = along;
      column_radius_[k] = std::sqrt(std::max(0.0, mju_dot3(rel, rel) - along * along));
    }
    seal_vertex_[i] =
        column_vertex_[first + ColumnSealPoint(column_depth_.data(), column_radius_.data(), n,
                                               kRimToleranceM)];
  }
}

const mjtNum* LipBody::RimPos(const mjData* d, int i) const {
  return kind_ == Kind::kSegments ? d->geom_xpos + 3 * segment_geom_[i]
                                  : d->flexvert_xpos + 3 * seal_vertex_[i];
}

void LipBody::MarkContacts(const mjModel* m, const mjData* d, unsigned char* touching) const {
  std::fill(vertex_touching_.begin(), vertex_touching_.end(), 0);
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.dist > 0) continue;
    if (kind_ == Kind::kSegments) {
      if (con.geom[0] < 0 || con.geom[1] < 0) continue;
      const int seg0 = segment_of_geom_[con.geom[0]];
      const int seg1 = segment_of_geom_[con.geom[1]];
      if ((seg0 >= 0) == (seg1 >= 0)) continue;  // lip against lip, or no lip at all
      touching[seg0 >= 0 ? seg0 : seg1] = 1;
      continue;
    }
    for (int side = 0; side < 2; ++side) {
      if (con.flex[side] != flex_ || con.flex[1 - side] == flex_) continue;
      const int other = con.geom[1 - side];
      if (other >= 0 && tool_geom_[other]) continue;  // the skirt on its own walls seals nothing
      // The seal point touching: the vertex itself, or an element's seal point nearest the
      // contact.
      const int adr = m->flex_vertadr[flex_];
      int vertex = -1;
      if (con.vert[side] >= 0) {
        vertex = adr + con.vert[side];
      } else if (con.elem[side] >= 0) {
        const int* elem = m->flex_elem + m->flex_elemdataadr[flex_] + 3 * con.elem[side];
        mjtNum best_d2 = 0;
        for (int k = 0; k < 3; ++k) {
          const int v = adr + elem[k];
          const mjtNum* p = d->flexvert_xpos + 3 * v;
          const mjtNum d2 = (p[0] - con.pos[0]) * (p[0] - con.pos[0]) +
                            (p[1] - con.pos[1]) * (p[1] - con.pos[1]) +
                            (p[2] - con.pos[2]) * (p[2] - con.pos[2]);
          if (vertex < 0 || d2 < best_d2) {
            vertex = v;
            best_d2 = d2;
          }
        }
      }
      if (vertex >= 0) vertex_touching_[vertex - adr] = 1;
      for (int r = 0; vertex >= 0 && r < num_rim_points(); ++r) {
        if (seal_vertex_[r] == vertex) touching[r] = 1;
      }
    }
  }
}

double LipBody::ColumnGap(int i, const mjData* d, const mjtNum origin[3], const mjtNum axis_z[3],
                          double (*surface_depth_at)(const mjtNum[3], void*), void* ctx) const {
  double gap = kNoSurfaceGapM;
  const int adr = column_adr_;
  for (int k = column_start_[i]; k < column_start_[i + 1] && gap > 0.0; ++k) {
    const int v = column_vertex_[k];
    if (vertex_touching_[v - adr]) return 0.0;
    const mjtNum* p = d->flexvert_xpos + 3 * v;
    const mjtNum rel[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
    const mjtNum along = mju_dot3(rel, axis_z);
    mjtNum on_plane[3];
    for (int q = 0; q < 3; ++q) on_plane[q] = p[q] - along * axis_z[q];
    const double depth = surface_depth_at(on_plane, ctx);
    if (depth >= kNoSurfaceGapM) continue;
    gap = std::min(gap, std::max(0.0, depth - along - column_radius_m_));
  }
  return gap;
}

double LipBody::MouthCover(const mjData* d, const mjtNum origin[3], const mjtNum frame[9],
                           double angle_rad, double half_width_rad, double radius_m) const {
  double cover = radius_m;
  const double reach = throat_depth_m_ + 4.0 * column_radius_m_;  // one thickness below
  const double inside = radius_m - column_radius_m_;  // the throat ring itself is no lobe
  for (int v = 0; v < static_cast<int>(vertex_touching_.size()); ++v) {
    const mjtNum* p = d->flexvert_xpos + 3 * (column_adr_ + v);
    const mjtNum rel[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
    mjtNum local[3];
    mju_mulMatTVec3(local, frame, rel);
    if (local[2] > reach) continue;
    const double r = std::hypot(local[0], local[1]);
    if (r >= inside || r >= cover) continue;
    if (std::abs(std::remainder(std::atan2(local[1], local[0]) - angle_rad, 2.0 * M_PI)) >
        half_width_rad) {
      continue;
    }
    cover = r;
  }
  return cover;
}

void LipBody::ApplyForces(const mjModel* m, mjData* d,
                          const std::array<double, kNumChambers>& vacuum_pa, bool vacuum_load,
                          mjtNum vacuum_force_n[3], mjtNum vacuum_torque_nm[3]) const {
  mju_zero3(vacuum_force_n);
  mju_zero3(vacuum_torque_nm);
  if (kind_ == Kind::kSegments) {
    ApplySegmentForces(d);
  } else if (vacuum_load) {
    ApplySkirtVacuum(m, d, vacuum_pa, vacuum_force_n, vacuum_torque_nm);
  }
}

void LipBody::ApplySegmentForces(mjData* d) const {
  if (mechanics_.bending_stiffness_nm2 > 0 && !segment_dof_.empty()) {
    const int n = static_cast<int>(segment_dof_.size());
    for (int i = 0; i < n; ++i) {
      ring_u_[i] = d->qpos[segment_qpos_[i]];
      ring_force_[i] = 0.0;
    }
    AddRingBendingForce(ring_u_.data(), ring_shapes_, mechanics_.bending_stiffness_nm2,
                        rim_radius_m_, ring_mode_cap_n_per_m_, ring_force_.data());
    for (int i = 0; i < n; ++i) d->qfrc_passive[segment_dof_[i]] += ring_force_[i];
  }
  // The carrier's shear slides and tilt hinges: springs when soft, locked by their equality
  // constraints when off (the model's default).
  for (const CarrierJoint& j : carrier_joints_) {
    const double k =
        j.is_tilt ? mechanics_.tilt_stiffness_nm_per_rad : mechanics_.shear_stiffness_n_per_m;
    if (j.lock >= 0) d->eq_active[j.lock] = k > 0 ? 0 : 1;
    if (k > 0) d->qfrc_passive[j.dof] -= k * d->qpos[j.qpos];
  }
}

void LipBody::ApplySkirtVacuum(const mjModel* m, mjData* d,
                               const std::array<double, kNumChambers>& vacuum_pa,
                               mjtNum vacuum_force_n[3], mjtNum vacuum_torque_nm[3]) const {
  const mjtNum* site_pos = d->site_xpos + 3 * site_id_;
  const mjtNum* site_mat = d->site_xmat + 9 * site_id_;
  const mjtNum axis_z[3] = {site_mat[2], site_mat[5], site_mat[8]};
  const int adr = m->flex_vertadr[flex_];
  const int* elems = m->flex_elem + m->flex_elemdataadr[flex_];
  const mjtNum zero[3] = {0, 0, 0};
  for (int e = 0; e < m->flex_elemnum[flex_]; ++e) {
    const int* v = elems + 3 * e;
    const mjtNum* p0 = d->flexvert_xpos + 3 * (adr + v[0]);
    const mjtNum* p1 = d->flexvert_xpos + 3 * (adr + v[1]);
    const mjtNum* p2 = d->flexvert_xpos + 3 * (adr + v[2]);
    // The chamber behind the triangle: its centroid's direction in the site's frame.
    mjtNum centroid[3], rel[3], local[3];
    for (int k = 0; k < 3; ++k) centroid[k] = (p0[k] + p1[k] + p2[k]) / 3.0;
    mju_sub3(rel, centroid, site_pos);
    mju_mulMatTVec3(local, site_mat, rel);
    const double vacuum = vacuum_pa[ChamberOfAngle(std::atan2(local[1], local[0]))];
    if (vacuum == 0.0) continue;
    // The side that faced the cavity at rest faces it still (a folded lobe's underside too).
    const std::array<double, 3> n = TriangleAreaVector(p0, p1, p2);
    const double f[3] = {element_cavity_side_[e] * vacuum * n[0],
                         element_cavity_side_[e] * vacuum * n[1],
                         element_cavity_side_[e] * vacuum * n[2]};
    mjtNum third[3] = {f[0] / 3.0, f[1] / 3.0, f[2] / 3.0};
    for (int k = 0; k < 3; ++k) vacuum_force_n[k] += f[k];
    // Thirds at the vertices: the moment of the whole at the centroid.
    mjtNum moment[3];
    mju_cross(moment, rel, f);
    mju_addTo3(vacuum_torque_nm, moment);
    for (int k = 0; k < 3; ++k) {
      mjtNum* point = d->flexvert_xpos + 3 * (adr + v[k]);
      mj_applyFT(m, d, third, zero, point, m->flex_vertbodyid[adr + v[k]], d->qfrc_passive);
    }
  }
  // The cup's ceiling over each chamber (inside the skirt's pinned ring): pulled toward the object.
  double pull_n = 0.0;
  for (double p : vacuum_pa) pull_n += p * ceiling_area_m2_;
  mjtNum force[3] = {pull_n * axis_z[0], pull_n * axis_z[1], pull_n * axis_z[2]};
  mju_addTo3(vacuum_force_n, force);
  mjtNum point[3];
  mju_copy3(point, site_pos);
  mj_applyFT(m, d, force, zero, point, m->site_bodyid[site_id_], d->qfrc_passive);
}

}  // namespace ssc
