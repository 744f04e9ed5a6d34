#include "plugin/chamber_pressure_sensor.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>

namespace ssc {
namespace {

static_assert(kNumGeomGroups == mjNGROUP, "ray_groups is sized for MuJoCo's geom groups");
static_assert(sizeof(mjtByte) == sizeof(unsigned char), "ray_groups is passed to mj_ray");
constexpr int kWarmStartSize = kNumChambers + 1;
// Vertical-ray bisections that locate an edge the horizontal rays missed: 5.5 mm / 2^6 = 0.09 mm.
constexpr int kRimBisections = 6;
// Per-mjData noise seed (set by the application after a reset), after the warm start.
constexpr int kSeedSlot = kSensorChainStateSize + kWarmStartSize;

// World-frame axis `col` of a row-major 3x3 rotation.
void Axis(const mjtNum* mat, int col, mjtNum out[3]) {
  out[0] = mat[col];
  out[1] = mat[3 + col];
  out[2] = mat[6 + col];
}

bool IsInSubtree(const mjModel* m, int body, int root) {
  while (body > 0 && body != root) body = m->body_parentid[body];
  return body == root;
}

SensorChainState* StateOf(mjData* d, const mjModel* m, int instance) {
  return reinterpret_cast<SensorChainState*>(d->plugin_state + m->plugin_stateadr[instance]);
}

// The sensor behind a plugin instance (its plugin_data). Private to this file: tools see it
// through ChamberPressureDiagnostics.
class ChamberPressureSensor final : public ChamberPressureDiagnostics {
 public:
  // Returns nullptr with *error when the config or model is invalid.
  static ChamberPressureSensor* Create(const mjModel* m, int instance, std::string* error);

  void Reset(mjtNum* plugin_state) const;
  void Compute(const mjModel* m, mjData* d, int instance);
  void Visualize(const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn) const;

  int instance() const override { return instance_; }
  int site_id() const override { return site_id_; }
  int sensor_adr() const override { return sensor_adr_; }
  int num_lip_segments() const override { return static_cast<int>(lip_geoms_.size()); }
  const ChamberPressureConfig& config() const override { return config_; }
  const ChamberPressureSample& last_sample() const override { return sample_; }
  void Measure(const mjModel* m, const mjData* d, ChamberPressureSample* sample) const override;
  void CopyDiagnosticsFrom(const ChamberPressureSensor& other) { sample_ = other.sample_; }
  // The sensor chain's parameters with the run seed kept in the plugin state.
  SensorChainParams RunSensorParams(const mjtNum* raw_state) const;
  // The filtered output of the state into sensordata.
  void WriteOutput(mjData* d, const SensorChainState& state) const;

  // Passive forces of the lip (ring bending, shear and tilt springs) into d->qfrc_passive, and
  // the carrier's locks switched to match the config.
  void ApplyLipForces(const mjModel* m, mjData* d) const;

 private:
  ChamberPressureSensor(ChamberPressureConfig config, int instance, int site_id, int sensor_adr);
  // Finds the lip's carrier, the segments' joints and the carrier's shear/tilt joints; checks
  // the lip stiffnesses against the time step. False with *error on a bad model or config.
  bool BindLip(const mjModel* m, std::string* error);
  // World pose of the opening's frame (the tool frame carried by the lip).
  void OpeningFrame(const mjData* d, mjtNum pos[3], mjtNum mat[9]) const;
  // Lists the geoms the rays can see now (ray_geoms_), once per sample.
  void ListRayGeoms(const mjModel* m) const;
  // Distance along `dir` (a unit vector) from `start` to the first of ray_geoms_ it hits, -1 when
  // none: what mj_ray(m, d, start, dir, ray_groups, 1, -1, ...) returns, without its pass over
  // every geom of the model per ray.
  mjtNum CastRay(const mjModel* m, const mjData* d, const mjtNum start[3],
                 const mjtNum dir[3]) const;

  ChamberPressureConfig config_;
  int instance_;
  int site_id_;
  int sensor_adr_;
  std::vector<int> lip_geoms_;          // geom id of each lip segment
  std::vector<int> lip_of_geom_;        // segment index of each geom id, -1 if not lip
  std::vector<double> lip_tip_radius_;  // tip below the segment geom's centre (capsule radius)
  mutable std::vector<double> lip_tip_depth_;  // per sample: tip depth below the lip plane
  // The body carrying the lip segments and the site's pose relative to it.
  int carrier_body_ = 0;
  mjtNum opening_offset_pos_[3] = {0, 0, 0};
  mjtNum opening_offset_mat_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  // The lip segments either side of each wedge's bisector and the weight of the second.
  struct WedgeRim {
    int segment[2] = {0, 0};
    double weight1 = 0.0;
  };
  std::vector<WedgeRim> wedge_rim_;
  // Ring bending: each segment's slide joint, its angle, the ring radius and the mode cap.
  std::vector<int> segment_dof_, segment_qpos_;
  std::vector<double> segment_angle_;
  RingModeShapes ring_shapes_;  // at segment_angle_, made once
  mutable std::vector<double> ring_u_, ring_force_;
  double lip_radius_m_ = 5.5e-3;
  double ring_mode_cap_n_per_m_ = kNoModeCap;
  struct CarrierJoint {
    int dof = 0, qpos = 0, lock = -1;  // lock: equality constraint that pins it, -1 if none
    bool is_tilt = false;              // hinge (tilt) or slide (shear)
  };
  std::vector<CarrierJoint> carrier_joints_;
  // The geoms mj_ray would test with ray_groups (in a group of ray_groups, not invisible: alpha
  // of the geom or its material not 0), in id order; capacity ngeom, made at each sample.
  mutable std::vector<int> ray_geoms_;
  mutable bool ray_geoms_need_mj_ray_ = false;  // an SDF geom among them: mj_ray casts each ray
  std::vector<mjtNum> ray_dirs_local_;  // unit radial directions in the site frame, 3 per ray
  ChamberPressureSample sample_;
};

ChamberPressureSensor* SensorOf(const mjData* d, int instance) {
  return reinterpret_cast<ChamberPressureSensor*>(d->plugin_data[instance]);
}

int StateSize() { return kSeedSlot + 1; }

}  // namespace

ChamberPressureSensor::ChamberPressureSensor(ChamberPressureConfig config, int instance,
                                             int site_id, int sensor_adr)
    : config_(std::move(config)), instance_(instance), site_id_(site_id), sensor_adr_(sensor_adr) {}

ChamberPressureSensor* ChamberPressureSensor::Create(const mjModel* m, int instance,
                                                     std::string* error) {
  std::optional<ChamberPressureConfig> config = ParseChamberPressureConfig(
      [m, instance](const char* key) { return mj_getPluginConfig(m, instance, key); }, error);
  if (!config) return nullptr;

  // Find the sensor that uses this instance and its site.
  int sensor_id = -1;
  for (int i = 0; i < m->nsensor; ++i) {
    if (m->sensor_type[i] == mjSENS_PLUGIN && m->sensor_plugin[i] == instance) {
      sensor_id = i;
      break;
    }
  }
  if (sensor_id < 0) {
    *error = std::string(kChamberPressurePluginName) +
             ": no <sensor><plugin> element uses this instance";
    return nullptr;
  }
  if (m->sensor_objtype[sensor_id] != mjOBJ_SITE || m->sensor_objid[sensor_id] < 0 ||
      m->sensor_objid[sensor_id] >= m->nsite) {
    *error = std::string(kChamberPressurePluginName) +
             ": the sensor must name its tool site with objtype=\"site\" objname=\"...\"";
    return nullptr;
  }
  const int site_id = m->sensor_objid[sensor_id];
  auto* sensor =
      new ChamberPressureSensor(std::move(*config), instance, site_id, m->sensor_adr[sensor_id]);

  // Lip segments: geoms of the lip group in the site body's subtree.
  const int root = m->site_bodyid[site_id];
  sensor->lip_of_geom_.assign(m->ngeom, -1);
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_group[g] == sensor->config_.lip_geom_group &&
        IsInSubtree(m, m->geom_bodyid[g], root)) {
      sensor->lip_of_geom_[g] = static_cast<int>(sensor->lip_geoms_.size());
      sensor->lip_geoms_.push_back(g);
    }
  }
  if (sensor->lip_geoms_.empty() || sensor->lip_geoms_.size() > kMaxLipSegments) {
    *error = std::string(kChamberPressurePluginName) + ": found " +
             std::to_string(sensor->lip_geoms_.size()) + " lip segment geoms (group " +
             std::to_string(sensor->config_.lip_geom_group) +
             ") under the site's body; need 1 to " + std::to_string(kMaxLipSegments);
    delete sensor;
    return nullptr;
  }
  sensor->sample_.lip.resize(sensor->lip_geoms_.size());

  // Assign each segment to the chamber its direction falls in, using the model's reference pose
  // (body and geom offsets up to the site's body; no mjData here, init must not recurse into
  // mj_makeData); arcs split the lip circumference evenly.
  mjtNum site_quat_inv[4];
  mju_negQuat(site_quat_inv, m->site_quat + 4 * site_id);
  double radius_sum = 0.0;
  const int n_seg = static_cast<int>(sensor->lip_geoms_.size());
  for (int i = 0; i < n_seg; ++i) {
    const int g = sensor->lip_geoms_[i];
    mjtNum p[3] = {m->geom_pos[3 * g], m->geom_pos[3 * g + 1], m->geom_pos[3 * g + 2]};
    for (int b = m->geom_bodyid[g]; b != root; b = m->body_parentid[b]) {
      mjtNum rotated[3];
      mju_rotVecQuat(rotated, p, m->body_quat + 4 * b);
      for (int k = 0; k < 3; ++k) p[k] = rotated[k] + m->body_pos[3 * b + k];
    }
    mjtNum rel[3] = {p[0] - m->site_pos[3 * site_id], p[1] - m->site_pos[3 * site_id + 1],
                     p[2] - m->site_pos[3 * site_id + 2]};
    mjtNum local[3];
    mju_rotVecQuat(local, rel, site_quat_inv);
    const double angle = std::atan2(local[1], local[0]);
    sensor->sample_.lip[i].chamber = ChamberOfAngle(angle);
    sensor->segment_angle_.push_back(angle);
    radius_sum += std::hypot(local[0], local[1]);
    const int type = m->geom_type[g];
    sensor->lip_tip_radius_.push_back(type == mjGEOM_CAPSULE || type == mjGEOM_SPHERE
                                          ? m->geom_size[3 * g]
                                          : m->geom_size[3 * g + 2]);
  }
  sensor->lip_radius_m_ = radius_sum / n_seg;
  const double arc = 2.0 * M_PI * sensor->lip_radius_m_ / n_seg;
  for (LipSegmentState& s : sensor->sample_.lip) s.arc_m = arc;
  sensor->lip_tip_depth_.assign(n_seg, 0.0);
  if (!sensor->BindLip(m, error)) {
    delete sensor;
    return nullptr;
  }

  // Radial ray directions in the site frame.
  const int per = sensor->config_.geometry.rays_per_chamber;
  const int n_rays = per * kNumChambers;
  sensor->ray_dirs_local_.resize(3 * n_rays);
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < per; ++j) {
      const double a = RayAngle(c, j, per);
      mjtNum* dir = sensor->ray_dirs_local_.data() + 3 * (c * per + j);
      dir[0] = std::cos(a);
      dir[1] = std::sin(a);
      dir[2] = 0.0;
    }
  }
  sensor->ray_geoms_.reserve(m->ngeom);
  sensor->sample_.wedges.resize(n_rays);
  // Each wedge's rim lies between the two lip segments either side of its bisector.
  sensor->wedge_rim_.resize(n_rays);
  for (int c = 0; c < kNumChambers; ++c) {
    for (int j = 0; j < per; ++j) {
      const int r = c * per + j;
      const double a = RayAngle(c, j, per);
      OpeningWedge& w = sensor->sample_.wedges[r];
      w.chamber = c;
      w.dtheta_rad = 0.5 * M_PI / per;
      double before = 1e9, after = 1e9;
      WedgeRim& rim = sensor->wedge_rim_[r];
      for (int i = 0; i < n_seg; ++i) {
        const double delta = std::remainder(a - sensor->segment_angle_[i], 2.0 * M_PI);
        if (delta >= 0 && delta < before) {
          before = delta;
          rim.segment[0] = i;
        }
        if (delta < 0 && -delta < after) {
          after = -delta;
          rim.segment[1] = i;
        }
      }
      if (after >= 1e9) rim.segment[1] = rim.segment[0];
      if (before >= 1e9) rim.segment[0] = rim.segment[1];
      rim.weight1 = (before < 1e9 && after < 1e9) ? before / (before + after) : 0.0;
    }
  }
  return sensor;
}

bool ChamberPressureSensor::BindLip(const mjModel* m, std::string* error) {
  const int root = m->site_bodyid[site_id_];
  const int n_seg = static_cast<int>(lip_geoms_.size());
  const double dt = m->opt.timestep;
  auto fail = [&](const std::string& what) {
    *error = std::string(kChamberPressurePluginName) + ": " + what;
    return false;
  };
  // The carrier: the common parent of the segments' bodies (the site's body in a rigid cup).
  int carrier = -1;
  for (int g : lip_geoms_) {
    const int b = m->geom_bodyid[g];
    const int parent = b == root ? root : m->body_parentid[b];
    if (carrier < 0) carrier = parent;
    if (parent != carrier) {
      carrier = root;
      break;
    }
  }
  if (carrier != root && m->body_parentid[carrier] != root) {
    return fail("the lip segments' parent body must be the tool site's body or its child");
  }
  carrier_body_ = carrier;
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

  // Ring bending acts on each segment's slide joint.
  const LipMechanics& lip = config_.lip;
  double min_mass = 1e9;
  for (int g : lip_geoms_) {
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
  }
  if (lip.bending_stiffness_nm2 > 0 && segment_dof_.empty()) {
    return fail("lip_bending_nmm2 > 0 needs a slide joint on every lip segment's body");
  }
  // Explicit springs stay stable while omega * dt <= 1: modes stiffer than that are capped.
  if (!segment_dof_.empty()) ring_mode_cap_n_per_m_ = min_mass / (dt * dt);
  ring_u_.assign(n_seg, 0.0);
  ring_force_.assign(n_seg, 0.0);
  ring_shapes_ = MakeRingModeShapes(segment_angle_.data(), n_seg);

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
      const double k = cj.is_tilt ? lip.tilt_stiffness_nm_per_rad : lip.shear_stiffness_n_per_m;
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
        return fail(os.str());
      }
      (cj.is_tilt ? has_tilt : has_shear) = true;
      carrier_joints_.push_back(cj);
    }
  }
  if (lip.shear_stiffness_n_per_m > 0 && !has_shear) {
    return fail(
        "lip_shear_n_per_mm > 0 needs slide joints on the lip carrier body (models/ssc_tool.xml)");
  }
  if (lip.tilt_stiffness_nm_per_rad > 0 && !has_tilt) {
    return fail(
        "lip_tilt_nmm_per_deg > 0 needs hinge joints on the lip carrier body "
        "(models/ssc_tool.xml)");
  }
  return true;
}

void ChamberPressureSensor::Reset(mjtNum* plugin_state) const {
  ResetSensorChain(reinterpret_cast<SensorChainState*>(plugin_state));
  for (int i = 0; i < kWarmStartSize; ++i) plugin_state[kSensorChainStateSize + i] = 0.0;
  plugin_state[kSeedSlot] = 0.0;
}

void SetChamberPressureRunSeed(const mjModel* m, mjData* d, int instance, std::uint64_t seed) {
  // Doubles hold integers exactly up to 2^53 - 1 (the config range).
  d->plugin_state[m->plugin_stateadr[instance] + kSeedSlot] =
      static_cast<double>(seed & ((std::uint64_t{1} << 53) - 1));
}

void ReseedChamberPressure(const mjModel* m, mjData* d, int instance, std::uint64_t seed) {
  SetChamberPressureRunSeed(m, d, instance, seed);
  const ChamberPressureSensor* sensor = SensorOf(d, instance);
  if (sensor == nullptr) return;
  const mjtNum* raw_state = d->plugin_state + m->plugin_stateadr[instance];
  SensorChainState* state = StateOf(d, m, instance);
  ReseedSensorChain(sensor->RunSensorParams(raw_state), state);
  sensor->WriteOutput(d, *state);
}

SensorChainParams ChamberPressureSensor::RunSensorParams(const mjtNum* raw_state) const {
  SensorChainParams sensor = config_.sensor;
  sensor.seed ^= static_cast<std::uint64_t>(raw_state[kSeedSlot]) * 0x9E3779B97F4A7C15ULL;
  return sensor;
}

void ChamberPressureSensor::WriteOutput(mjData* d, const SensorChainState& state) const {
  const std::array<double, kNumChambers> out = FilteredOutput(state);
  for (int i = 0; i < kNumChambers; ++i) d->sensordata[sensor_adr_ + i] = out[i];
}

void ChamberPressureSensor::OpeningFrame(const mjData* d, mjtNum pos[3], mjtNum mat[9]) const {
  const mjtNum* cpos = d->xpos + 3 * carrier_body_;
  const mjtNum* cmat = d->xmat + 9 * carrier_body_;
  mju_mulMatVec3(pos, cmat, opening_offset_pos_);
  for (int k = 0; k < 3; ++k) pos[k] += cpos[k];
  mju_mulMatMat(mat, cmat, opening_offset_mat_, 3, 3, 3);
}

void ChamberPressureSensor::ListRayGeoms(const mjModel* m) const {
  // mj_ray's own test of each geom (engine_ray.c, ray_eliminate) with flg_static = 1 and no body
  // excluded: the geom's group is among ray_groups and it is not invisible.
  ray_geoms_.clear();
  ray_geoms_need_mj_ray_ = false;
  for (int g = 0; g < m->ngeom; ++g) {
    const int mat = m->geom_matid[g];
    const float alpha = mat < 0 ? m->geom_rgba[4 * g + 3] : m->mat_rgba[4 * mat + 3];
    if (alpha == 0) continue;
    const int group = std::min(mjNGROUP - 1, std::max(0, m->geom_group[g]));
    if (!config_.ray_groups[group]) continue;
    ray_geoms_.push_back(g);
    if (m->geom_type[g] == mjGEOM_SDF) ray_geoms_need_mj_ray_ = true;
  }
}

mjtNum ChamberPressureSensor::CastRay(const mjModel* m, const mjData* d, const mjtNum start[3],
                                      const mjtNum dir[3]) const {
  if (ray_geoms_need_mj_ray_) {
    return mj_ray(m, d, start, dir, config_.ray_groups.data(), 1, -1, nullptr, nullptr);
  }
  // mj_ray's loop over the geoms it keeps: the same functions, the nearest hit, ties to the
  // lower id; bit for bit its answer.
  mjtNum dist = -1;
  for (const int g : ray_geoms_) {
    const int type = m->geom_type[g];
    mjtNum x;
    if (type == mjGEOM_MESH) {
      x = mj_rayMesh(m, d, g, start, dir, nullptr);
    } else if (type == mjGEOM_HFIELD) {
      x = mj_rayHfield(m, d, g, start, dir, nullptr);
    } else {
      x = mju_rayGeom(d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_size + 3 * g, start, dir,
                      type, nullptr);
    }
    if (x >= 0 && (x < dist || dist < 0)) dist = x;
  }
  return dist;
}

void ChamberPressureSensor::Measure(const mjModel* m, const mjData* d,
                                    ChamberPressureSample* sample) const {
  const CupGeometry& geo = config_.geometry;
  ListRayGeoms(m);
  // The opening moves with the lip (its carrier shears and tilts when the lip is soft).
  mjtNum origin_lip[3], frame[9];
  OpeningFrame(d, origin_lip, frame);
  mjtNum axis_z[3];
  Axis(frame, 2, axis_z);
  int rays = 0;
  // Depth below the lip plane of the first surface under a point of the lip plane (kNoSurfaceGapM
  // when none): a vertical ray from ray_start above it.
  auto surface_depth_at = [&](const mjtNum point[3]) {
    mjtNum start[3];
    for (int q = 0; q < 3; ++q) start[q] = point[q] - config_.ray_start_m * axis_z[q];
    const mjtNum t = CastRay(m, d, start, axis_z);
    ++rays;
    return t < 0 ? kNoSurfaceGapM : t - config_.ray_start_m;
  };

  // Lip segments: contacts first, rays for the rest. Gaps are from each segment's tip.
  for (LipSegmentState& s : sample->lip) s.in_contact = false;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.dist > 0 || con.geom[0] < 0 || con.geom[1] < 0) continue;
    const int seg0 = lip_of_geom_[con.geom[0]];
    const int seg1 = lip_of_geom_[con.geom[1]];
    if ((seg0 >= 0) == (seg1 >= 0)) continue;  // lip against lip, or no lip at all
    sample->lip[seg0 >= 0 ? seg0 : seg1].in_contact = true;
  }
  double tip_sum = 0.0;
  for (size_t i = 0; i < lip_geoms_.size(); ++i) {
    LipSegmentState& s = sample->lip[i];
    const mjtNum* gp = d->geom_xpos + 3 * lip_geoms_[i];
    mjtNum rel[3] = {gp[0] - origin_lip[0], gp[1] - origin_lip[1], gp[2] - origin_lip[2]};
    const mjtNum along = mju_dot3(rel, axis_z);
    lip_tip_depth_[i] = along + lip_tip_radius_[i];
    tip_sum += lip_tip_depth_[i];
    if (s.in_contact) {
      s.gap_m = 0.0;
      continue;
    }
    mjtNum on_plane[3];
    for (int k = 0; k < 3; ++k) on_plane[k] = gp[k] - along * axis_z[k];
    const double depth = surface_depth_at(on_plane);
    s.gap_m = depth >= kNoSurfaceGapM ? kNoSurfaceGapM : std::max(0.0, depth - lip_tip_depth_[i]);
  }
  const double tip_mean = tip_sum / std::max(1.0, static_cast<double>(lip_geoms_.size()));

  // Centre of the opening.
  const double plane_depth = tip_mean + geo.open_depth_m;
  sample->centre_covered = surface_depth_at(origin_lip) <= plane_depth;

  // Radial rays in a plane open_depth below the lip tips find where surfaces begin and end
  // (exactly); each stretch between them is sampled by vertical rays, so the seams between convex
  // pieces of one object, overlapping geoms and height fields all read right. (One CastRay per
  // radial ray: mj_multiRay's batch, which culls geoms per ray by bounding angles, cost more here
  // than it saves, and any hit it returns is the nearest one, which CastRay finds too.)
  mjtNum origin[3];
  for (int k = 0; k < 3; ++k) origin[k] = origin_lip[k] + plane_depth * axis_z[k];
  const int per = geo.rays_per_chamber;
  const int n_rays = per * kNumChambers;
  const double radius = geo.opening_radius_m;
  constexpr double kStepPast = 1e-6;  // restart just past a crossing, metres
  for (int r = 0; r < n_rays; ++r) {
    mjtNum dir[3];
    mju_mulMatVec3(dir, frame, ray_dirs_local_.data() + 3 * r);
    auto depth_along = [&](double along) {
      mjtNum point[3];
      for (int q = 0; q < 3; ++q) point[q] = origin_lip[q] + along * dir[q];
      return surface_depth_at(point);
    };
    // Where the wedge's surfaces begin and end.
    double cuts[kMaxCrossings + 2];
    int n = 0;
    cuts[n++] = 0.0;
    // A hit at or beyond the radius (or none, -1) is no crossing inside the opening.
    double t = CastRay(m, d, origin, dir);
    ++rays;
    for (int k = 0; t >= 0 && t < radius && k < kMaxCrossings; ++k) {
      cuts[n++] = t;
      const double from = t + kStepPast;
      mjtNum start[3];
      for (int q = 0; q < 3; ++q) start[q] = origin[q] + from * dir[q];
      const mjtNum next = CastRay(m, d, start, dir);
      ++rays;
      t = next >= 0 ? from + next : -1.0;
    }
    if (n == 1 && kRimBisections > 0) {
      // No boundary seen by the horizontal ray. A surface the ray plane misses (thinner than
      // the plane depth, or grazing that plane) can still end inside the opening: compare the
      // rim with the centre, and bisect with vertical rays if they differ.
      const bool centre = sample->centre_covered;
      if ((depth_along(radius) <= plane_depth) != centre) {
        double inside = 0, outside = radius;
        for (int b = 0; b < kRimBisections; ++b) {
          const double mid = 0.5 * (inside + outside);
          ((depth_along(mid) <= plane_depth) == centre ? inside : outside) = mid;
        }
        cuts[n++] = 0.5 * (inside + outside);
      }
    }
    cuts[n++] = radius;
    // The wedge's rim: the lip segments either side of its bisector.
    OpeningWedge& w = sample->wedges[r];
    const WedgeRim& rim = wedge_rim_[r];
    const LipSegmentState& s0 = sample->lip[rim.segment[0]];
    const LipSegmentState& s1 = sample->lip[rim.segment[1]];
    w.rim_gap_m = (1.0 - rim.weight1) * s0.gap_m + rim.weight1 * s1.gap_m;
    const double tip = (1.0 - rim.weight1) * lip_tip_depth_[rim.segment[0]] +
                       rim.weight1 * lip_tip_depth_[rim.segment[1]];
    w.n_samples = 0;
    for (int k = 0; k + 1 < n; ++k) {
      double radii[kSamplesPerStretch], gaps[kSamplesPerStretch];
      StretchSampleRadii(cuts[k], cuts[k + 1], radii);
      for (int q = 0; q < kSamplesPerStretch; ++q) {
        const double depth = depth_along(radii[q]);
        gaps[q] = depth >= kNoSurfaceGapM ? kNoSurfaceGapM : std::max(0.0, depth - tip);
      }
      AddStretch(cuts[k], cuts[k + 1], gaps, &w);
    }
  }

  const ChamberLeaks leaks = LeakAreas(geo, sample->wedges.data(), n_rays);
  sample->leak_area_m2 = leaks.area_m2;
  sample->jet_area_m2 = leaks.jet_area_m2;
  sample->sealed_area_m2 = leaks.sealed_area_m2;
  sample->rays_cast = rays;
  sample->time_s = d->time;
}

void ChamberPressureSensor::ApplyLipForces(const mjModel* m, mjData* d) const {
  const LipMechanics& lip = config_.lip;
  if (lip.bending_stiffness_nm2 > 0 && !segment_dof_.empty()) {
    const int n = static_cast<int>(segment_dof_.size());
    for (int i = 0; i < n; ++i) {
      ring_u_[i] = d->qpos[segment_qpos_[i]];
      ring_force_[i] = 0.0;
    }
    AddRingBendingForce(ring_u_.data(), ring_shapes_, lip.bending_stiffness_nm2, lip_radius_m_,
                        ring_mode_cap_n_per_m_, ring_force_.data());
    for (int i = 0; i < n; ++i) d->qfrc_passive[segment_dof_[i]] += ring_force_[i];
  }
  // The carrier's shear slides and tilt hinges: springs when soft, locked by their equality
  // constraints when off (the model's default).
  for (const CarrierJoint& j : carrier_joints_) {
    const double k = j.is_tilt ? lip.tilt_stiffness_nm_per_rad : lip.shear_stiffness_n_per_m;
    if (j.lock >= 0) d->eq_active[j.lock] = k > 0 ? 0 : 1;
    if (k > 0) d->qfrc_passive[j.dof] -= k * d->qpos[j.qpos];
  }
  (void)m;
}

void ChamberPressureSensor::Compute(const mjModel* m, mjData* d, int instance) {
  mjtNum* raw_state = d->plugin_state + m->plugin_stateadr[instance];
  SensorChainState* state = StateOf(d, m, instance);
  const std::int64_t k = SampleIndexAt(config_.sensor, d->time);
  if (k > static_cast<std::int64_t>(state->last_sample_index)) {
    Measure(m, d, &sample_);
    mjtNum* warm = raw_state + kSensorChainStateSize;
    sample_.flow =
        SolveFlowNetwork(config_.pneumatics, sample_.leak_area_m2, warm, &sample_.jet_area_m2);
    for (int i = 0; i < kNumChambers; ++i) warm[i] = sample_.flow.chamber_pa[i];
    warm[kNumChambers] = sample_.flow.port_pa;
    TakeSamples(RunSensorParams(raw_state), k, sample_.flow.tap_pa, state);
  }
  WriteOutput(d, *state);
}

void ChamberPressureSensor::Visualize(const mjModel* m, mjData* d, const mjvOption* opt,
                                      mjvScene* scn) const {
  (void)opt;
  // Lip segments coloured by state: green = sealed (contact), amber = gap within the open depth,
  // red = open.
  const double seal = config_.geometry.open_depth_m;
  for (size_t i = 0; i < lip_geoms_.size() && i < sample_.lip.size(); ++i) {
    if (scn->ngeom >= scn->maxgeom) return;
    const LipSegmentState& s = sample_.lip[i];
    float rgba[4] = {0.9f, 0.15f, 0.1f, 1.0f};
    if (s.in_contact) {
      rgba[0] = 0.1f;
      rgba[1] = 0.85f;
      rgba[2] = 0.2f;
    } else if (s.gap_m <= seal) {
      rgba[0] = 1.0f;
      rgba[1] = 0.7f;
      rgba[2] = 0.0f;
    }
    const int g = lip_geoms_[i];
    const mjtNum size[3] = {0.0012, 0.0012, 0.0012};
    mjvGeom* geom = scn->geoms + scn->ngeom;
    mjv_initGeom(geom, mjGEOM_SPHERE, size, d->geom_xpos + 3 * g, nullptr, rgba);
    geom->category = mjCAT_DECOR;
    ++scn->ngeom;
  }
  (void)m;
}

const ChamberPressureDiagnostics* FindChamberPressureDiagnostics(const mjModel* m,
                                                                 const mjData* d) {
  int slot = -1;
  const mjpPlugin* plugin = mjp_getPlugin(kChamberPressurePluginName, &slot);
  if (plugin == nullptr) return nullptr;
  for (int i = 0; i < m->nplugin; ++i) {
    if (m->plugin[i] == slot && d->plugin_data[i] != 0) return SensorOf(d, i);
  }
  return nullptr;
}

void RegisterChamberPressurePlugin() {
  // MuJoCo keeps the pointers: the names live as long as the key table (static).
  static const std::vector<const char*> attributes = [] {
    std::vector<const char*> names;
    for (const ChamberPressureConfigKey& k : ChamberPressureConfigKeys()) names.push_back(k.key);
    return names;
  }();
  mjpPlugin plugin;
  mjp_defaultPlugin(&plugin);
  plugin.name = kChamberPressurePluginName;
  // Sensor: the chamber pressures. Passive: the lip's ring bending and its shear/tilt springs.
  plugin.capabilityflags |= mjPLUGIN_SENSOR | mjPLUGIN_PASSIVE;
  plugin.nattribute = static_cast<int>(attributes.size());
  plugin.attributes = attributes.data();
  // Position stage: a control callback in the same step sees this step's pressures.
  plugin.needstage = mjSTAGE_POS;
  plugin.nstate = +[](const mjModel*, int) { return StateSize(); };
  plugin.nsensordata = +[](const mjModel*, int, int) { return kNumChambers; };
  plugin.init = +[](const mjModel* m, mjData* d, int instance) {
    std::string error;
    ChamberPressureSensor* sensor = ChamberPressureSensor::Create(m, instance, &error);
    if (sensor == nullptr) {
      mju_warning("%s", error.c_str());
      return -1;
    }
    d->plugin_data[instance] = reinterpret_cast<uintptr_t>(sensor);
    sensor->Reset(d->plugin_state + m->plugin_stateadr[instance]);
    return 0;
  };
  plugin.destroy = +[](mjData* d, int instance) {
    delete SensorOf(d, instance);
    d->plugin_data[instance] = 0;
  };
  plugin.copy = +[](mjData* dest, const mjModel*, const mjData* src, int instance) {
    ChamberPressureSensor* to = SensorOf(dest, instance);
    const ChamberPressureSensor* from = SensorOf(src, instance);
    if (to && from) to->CopyDiagnosticsFrom(*from);
  };
  plugin.reset = +[](const mjModel*, mjtNum* plugin_state, void* plugin_data, int) {
    auto* sensor = reinterpret_cast<ChamberPressureSensor*>(plugin_data);
    if (sensor) sensor->Reset(plugin_state);
  };
  plugin.compute = +[](const mjModel* m, mjData* d, int instance, int capability) {
    ChamberPressureSensor* sensor = SensorOf(d, instance);
    if (sensor == nullptr) return;
    if (capability == mjPLUGIN_PASSIVE) {
      sensor->ApplyLipForces(m, d);
    } else {
      sensor->Compute(m, d, instance);
    }
  };
  plugin.visualize =
      +[](const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn, int instance) {
        if (const ChamberPressureSensor* sensor = SensorOf(d, instance)) {
          sensor->Visualize(m, d, opt, scn);
        }
      };
  mjp_registerPlugin(&plugin);
}

}  // namespace ssc
