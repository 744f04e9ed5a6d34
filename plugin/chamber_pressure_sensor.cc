#include "plugin/chamber_pressure_sensor.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <utility>

#include "plugin/lip_body.h"
#include "plugin/pneumatics/lip_rim.h"

namespace ssc {
namespace {

static_assert(kNumGeomGroups == mjNGROUP, "ray_groups is sized for MuJoCo's geom groups");
static_assert(sizeof(mjtByte) == sizeof(unsigned char), "ray_groups is passed to mj_ray");
constexpr int kWarmStartSize = kNumChambers + 1;
// Vertical-ray bisections that locate an edge the horizontal rays missed: 5.5 mm / 2^6 = 0.09 mm.
constexpr int kRimBisections = 6;
// A lobe's vertices count across a wedge's mouth within this angle of its bisector (or half the
// wedge, if wider): about the skirt's sector spacing, so a lobe between two columns is seen.
constexpr double kLobeSectorHalfRad = 7.5 * M_PI / 180.0;
// Per-mjData noise seed (set by the application after a reset), after the warm start.
constexpr int kSeedSlot = kSensorChainStateSize + kWarmStartSize;
// The chamber vacuums' moment about the tool site and force on the tool at the last passive
// evaluation (world, N m and N; 3 values each, the force last): the F/T transducer carries them
// (runtime/tool_force.h).
constexpr int kVacuumTorqueSlot = kSeedSlot + 1;
constexpr int kVacuumForceSlot = kVacuumTorqueSlot + 3;

// World-frame axis `col` of a row-major 3x3 rotation.
void Axis(const mjtNum* mat, int col, mjtNum out[3]) {
  out[0] = mat[col];
  out[1] = mat[3 + col];
  out[2] = mat[6 + col];
}

SensorChainState* StateOf(mjData* d, const mjModel* m, int instance) {
  return reinterpret_cast<SensorChainState*>(d->plugin_state + m->plugin_stateadr[instance]);
}

// The sensor behind a plugin instance (its plugin_data). Private to this file: tools see it
// through ChamberPressureDiagnostics.
class ChamberPressureSensor final : public ChamberPressureDiagnostics {
 public:
  // Returns nullptr with *error when the config or model is invalid.
  static std::unique_ptr<ChamberPressureSensor> Create(const mjModel* m, int instance,
                                                       std::string* error);

  void Reset(mjtNum* plugin_state) const;
  void Compute(const mjModel* m, mjData* d, int instance);
  void Visualize(const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn) const;

  int instance() const override { return instance_; }
  int site_id() const override { return site_id_; }
  int sensor_adr() const override { return sensor_adr_; }
  int num_lip_segments() const override { return lip_.num_rim_points(); }
  const ChamberPressureConfig& config() const override { return config_; }
  const ChamberPressureSample& last_sample() const override { return sample_; }
  std::array<double, 3> lip_vacuum_force_n(const mjModel* m, const mjData* d) const override {
    const mjtNum* f = d->plugin_state + m->plugin_stateadr[instance_] + kVacuumForceSlot;
    return {f[0], f[1], f[2]};
  }
  std::array<double, 3> lip_vacuum_torque_nm(const mjModel* m, const mjData* d) const override {
    const mjtNum* t = d->plugin_state + m->plugin_stateadr[instance_] + kVacuumTorqueSlot;
    return {t[0], t[1], t[2]};
  }
  void Measure(const mjModel* m, const mjData* d, ChamberPressureSample* sample) const override;
  void CopyDiagnosticsFrom(const ChamberPressureSensor& other) { sample_ = other.sample_; }
  // The sensor chain's parameters with the run seed kept in the plugin state.
  SensorChainParams RunSensorParams(const mjtNum* raw_state) const;
  // The filtered output of the state into sensordata.
  void WriteOutput(mjData* d, const SensorChainState& state) const;

  // A skirt's lobe across wedge `w`'s mouth (LipBody::MouthCover) covers it from where it
  // reaches out (ray `ray_in_chamber` of its chamber; the opening's frame at `origin`).
  void CoverByLobe(const mjData* d, const mjtNum origin[3], const mjtNum frame[9],
                   int ray_in_chamber, OpeningWedge* w) const;
  // Passive forces of the lip (LipBody::ApplyForces) with the chamber vacuums of the newest
  // sample (kept in the plugin state, so a reset run starts from none).
  void ApplyLipForces(const mjModel* m, mjData* d, int instance) const;

 private:
  ChamberPressureSensor(ChamberPressureConfig config, int instance, int site_id, int sensor_adr);
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
  LipBody lip_;
  mutable std::vector<double> lip_tip_depth_;  // per sample: each rim point's tip depth
  mutable std::vector<double>
      lip_rim_radius_;  // per sample: each rim point's distance from the axis
  mutable std::vector<unsigned char> lip_touching_;  // per sample: rim point in contact
  // The rim points either side of each wedge's bisector and the weight of the second.
  std::vector<WedgeRim> wedge_rim_;
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

int StateSize() { return kVacuumForceSlot + 3; }

}  // namespace

ChamberPressureSensor::ChamberPressureSensor(ChamberPressureConfig config, int instance,
                                             int site_id, int sensor_adr)
    : config_(std::move(config)), instance_(instance), site_id_(site_id), sensor_adr_(sensor_adr) {}

std::unique_ptr<ChamberPressureSensor> ChamberPressureSensor::Create(const mjModel* m, int instance,
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
  std::unique_ptr<ChamberPressureSensor> sensor(
      new ChamberPressureSensor(std::move(*config), instance, site_id, m->sensor_adr[sensor_id]));
  const ChamberPressureConfig& c = sensor->config_;
  if (!sensor->lip_.Bind(m, site_id, c.lip_geom_group, c.lip, error)) return nullptr;
  if (c.lip_max_press_m > sensor->lip_.max_press_m() + 1e-9) {
    std::ostringstream os;
    os << kChamberPressurePluginName << ": lip_max_press_mm = " << c.lip_max_press_m * 1e3
       << " is deeper than this tool's lip can be pressed: " << sensor->lip_.max_press_why()
       << ", so at most " << sensor->lip_.max_press_m() * 1e3 << " mm for this tool";
    *error = os.str();
    return nullptr;
  }

  // Each rim point belongs to the chamber its direction falls in; arcs split the rim evenly.
  const int n_rim = sensor->lip_.num_rim_points();
  const std::vector<double>& angles = sensor->lip_.rim_angles_rad();
  sensor->sample_.lip.resize(n_rim);
  const double arc = 2.0 * M_PI * sensor->lip_.rim_radius_m() / n_rim;
  for (int i = 0; i < n_rim; ++i) {
    sensor->sample_.lip[i].chamber = ChamberOfAngle(angles[i]);
    sensor->sample_.lip[i].arc_m = arc;
  }
  sensor->lip_tip_depth_.assign(n_rim, 0.0);
  sensor->lip_rim_radius_.assign(n_rim, 0.0);
  sensor->lip_touching_.assign(n_rim, 0);

  // Radial ray directions in the site frame; each wedge's rim between the rim points either
  // side of its bisector.
  const int per = c.geometry.rays_per_chamber;
  const int n_rays = per * kNumChambers;
  sensor->ray_dirs_local_.resize(3 * n_rays);
  sensor->sample_.wedges.resize(n_rays);
  for (int ch = 0; ch < kNumChambers; ++ch) {
    for (int j = 0; j < per; ++j) {
      const double a = RayAngle(ch, j, per);
      mjtNum* dir = sensor->ray_dirs_local_.data() + 3 * (ch * per + j);
      dir[0] = std::cos(a);
      dir[1] = std::sin(a);
      dir[2] = 0.0;
      OpeningWedge& w = sensor->sample_.wedges[ch * per + j];
      w.chamber = ch;
      w.dtheta_rad = 0.5 * M_PI / per;
    }
  }
  sensor->wedge_rim_ = AssignWedgeRims(angles, per);
  sensor->ray_geoms_.reserve(m->ngeom);
  return sensor;
}

void ChamberPressureSensor::Reset(mjtNum* plugin_state) const {
  ResetSensorChain(reinterpret_cast<SensorChainState*>(plugin_state));
  for (int i = 0; i < kWarmStartSize; ++i) plugin_state[kSensorChainStateSize + i] = 0.0;
  plugin_state[kSeedSlot] = 0.0;
  for (int k = 0; k < 3; ++k) plugin_state[kVacuumTorqueSlot + k] = 0.0;
  for (int k = 0; k < 3; ++k) plugin_state[kVacuumForceSlot + k] = 0.0;
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
  const mjtNum* cpos = d->xpos + 3 * lip_.carrier_body();
  const mjtNum* cmat = d->xmat + 9 * lip_.carrier_body();
  mju_mulMatVec3(pos, cmat, lip_.opening_offset_pos());
  for (int k = 0; k < 3; ++k) pos[k] += cpos[k];
  mju_mulMatMat(mat, cmat, lip_.opening_offset_mat(), 3, 3, 3);
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

  // The lip's rim: contacts first, rays for the rest. Gaps are from each rim point's tip (a
  // skirt's: its column's seal point, the rim or a crease).
  const int n_rim = lip_.num_rim_points();
  lip_.FindSealPoints(d, origin_lip, axis_z);
  std::fill(lip_touching_.begin(), lip_touching_.end(), 0);
  lip_.MarkContacts(m, d, lip_touching_.data());
  double tip_sum = 0.0;
  for (int i = 0; i < n_rim; ++i) {
    LipSegmentState& s = sample->lip[i];
    s.in_contact = lip_touching_[i] != 0;
    const mjtNum* gp = lip_.RimPos(d, i);
    mjtNum rel[3] = {gp[0] - origin_lip[0], gp[1] - origin_lip[1], gp[2] - origin_lip[2]};
    const mjtNum along = mju_dot3(rel, axis_z);
    lip_tip_depth_[i] = along + lip_.rim_tip_radius_m(i);
    tip_sum += lip_tip_depth_[i];
    mjtNum on_plane[3];
    for (int k = 0; k < 3; ++k) on_plane[k] = gp[k] - along * axis_z[k];
    if (lip_.rim_moves_radially()) {
      lip_rim_radius_[i] = std::sqrt(std::max(0.0, mju_dot3(rel, rel) - along * along));
    }
    if (s.in_contact) {
      s.gap_m = 0.0;
      continue;
    }
    if (lip_.kind() == LipBody::Kind::kSkirt) {
      // Air that enters under the skirt's rim reaches the throat through the narrowest gap
      // under its column.
      auto depth_fn = [](const mjtNum point[3], void* ctx) {
        return (*static_cast<decltype(surface_depth_at)*>(ctx))(point);
      };
      s.gap_m = lip_.ColumnGap(i, d, origin_lip, axis_z, depth_fn, &surface_depth_at);
      continue;
    }
    const double depth = surface_depth_at(on_plane);
    s.gap_m = depth >= kNoSurfaceGapM ? kNoSurfaceGapM : std::max(0.0, depth - lip_tip_depth_[i]);
  }
  const double tip_mean = tip_sum / std::max(1, n_rim);

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
    // The wedge's rim: the rim points either side of its bisector. A skirt folded inward stands
    // inside the opening and covers the wedge beyond it.
    OpeningWedge& w = sample->wedges[r];
    const WedgeRim& rim = wedge_rim_[r];
    w.rim_gap_m = (1.0 - rim.weight1) * sample->lip[rim.point[0]].gap_m +
                  rim.weight1 * sample->lip[rim.point[1]].gap_m;
    const double tip = AtWedge(rim, lip_tip_depth_.data());
    w.rim_radius_m = lip_.rim_moves_radially()
                         ? std::clamp(AtWedge(rim, lip_rim_radius_.data()), 0.1 * radius, radius)
                         : 0.0;
    if (lip_.rim_moves_radially()) CoverByLobe(d, origin_lip, frame, r % per, &w);
    const double wedge_radius = w.rim_radius_m > 0.0 ? w.rim_radius_m : radius;
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
    for (int k = 0; t >= 0 && t < wedge_radius && k < kMaxCrossings; ++k) {
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
      if ((depth_along(wedge_radius) <= plane_depth) != centre) {
        double inside = 0, outside = wedge_radius;
        for (int b = 0; b < kRimBisections; ++b) {
          const double mid = 0.5 * (inside + outside);
          ((depth_along(mid) <= plane_depth) == centre ? inside : outside) = mid;
        }
        cuts[n++] = 0.5 * (inside + outside);
      }
    }
    cuts[n++] = wedge_radius;
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

void ChamberPressureSensor::CoverByLobe(const mjData* d, const mjtNum origin[3],
                                        const mjtNum frame[9], int ray_in_chamber,
                                        OpeningWedge* w) const {
  // A lobe folded in under the cup across the wedge's mouth covers it from where it reaches out,
  // held against the throat: no curtain under it.
  const CupGeometry& geo = config_.geometry;
  const double radius = geo.opening_radius_m;
  const double half_width = std::max(0.5 * w->dtheta_rad, kLobeSectorHalfRad);
  const double angle = RayAngle(w->chamber, ray_in_chamber, geo.rays_per_chamber);
  const double cover = lip_.MouthCover(d, origin, frame, angle, half_width, radius);
  if (cover < w->rim_radius_m) {
    w->rim_radius_m = std::max(cover, 0.1 * radius);
    w->rim_gap_m = 0.0;
  }
}

void ChamberPressureSensor::ApplyLipForces(const mjModel* m, mjData* d, int instance) const {
  const mjtNum* warm = d->plugin_state + m->plugin_stateadr[instance] + kSensorChainStateSize;
  std::array<double, kNumChambers> vacuum_pa{};
  for (int i = 0; i < kNumChambers; ++i) vacuum_pa[i] = std::max(0.0, warm[i]);
  lip_.ApplyForces(m, d, vacuum_pa, config_.lip_vacuum_load != 0,
                   d->plugin_state + m->plugin_stateadr[instance] + kVacuumForceSlot,
                   d->plugin_state + m->plugin_stateadr[instance] + kVacuumTorqueSlot);
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
  for (int i = 0; i < lip_.num_rim_points() && i < static_cast<int>(sample_.lip.size()); ++i) {
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
    const mjtNum size[3] = {0.0012, 0.0012, 0.0012};
    mjvGeom* geom = scn->geoms + scn->ngeom;
    mjv_initGeom(geom, mjGEOM_SPHERE, size, lip_.RimPos(d, i), nullptr, rgba);
    geom->category = mjCAT_DECOR;
    ++scn->ngeom;
  }
  (void)m;
}

const ChamberPressureDiagnostics* FindChamberPressureDiagnostics(const mjModel* m, const mjData* d,
                                                                 std::string* why) {
  // Called in the step (the F/T reader): counts, allocates nothing.
  int slot = -1, first = -1, found = 0;
  const mjpPlugin* plugin = mjp_getPlugin(kChamberPressurePluginName, &slot);
  for (int i = 0; plugin != nullptr && i < m->nplugin; ++i) {
    if (m->plugin[i] == slot && d->plugin_data[i] != 0 && found++ == 0) first = i;
  }
  if (found == 1) return SensorOf(d, first);
  if (why != nullptr) {
    *why = found == 0 ? std::string("scene has no ") + kChamberPressurePluginName + " sensor"
                      : "scene has " + std::to_string(found) + " " + kChamberPressurePluginName +
                            " sensors (a cup each): a trial follows with one cup; remove the "
                            "others";
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
    std::unique_ptr<ChamberPressureSensor> sensor =
        ChamberPressureSensor::Create(m, instance, &error);
    if (sensor == nullptr) {
      mju_warning("%s", error.c_str());
      return -1;
    }
    sensor->Reset(d->plugin_state + m->plugin_stateadr[instance]);
    d->plugin_data[instance] = reinterpret_cast<uintptr_t>(sensor.release());
    return 0;
  };
  plugin.destroy = +[](mjData* d, int instance) {
    // Owned by plugin_data since init released it there.
    std::unique_ptr<ChamberPressureSensor> owned(SensorOf(d, instance));
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
      sensor->ApplyLipForces(m, d, instance);
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
