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

 private:
  ChamberPressureSensor(ChamberPressureConfig config, int instance, int site_id, int sensor_adr);

  ChamberPressureConfig config_;
  int instance_;
  int site_id_;
  int sensor_adr_;
  std::vector<int> lip_geoms_;          // geom id of each lip segment
  std::vector<int> lip_of_geom_;        // segment index of each geom id, -1 if not lip
  std::vector<mjtNum> ray_dirs_local_;  // unit radial directions in the site frame, 3 per ray
  mutable std::vector<mjtNum> ray_dirs_world_;
  mutable std::vector<int> ray_geom_;
  mutable std::vector<mjtNum> ray_dist_;
  mutable mjtNum dir_scratch_[3] = {0, 0, 0};
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
  auto* sensor = new ChamberPressureSensor(std::move(*config), instance, site_id,
                                           m->sensor_adr[sensor_id]);

  // Lip segments: geoms of the lip group in the site body's subtree.
  const int root = m->site_bodyid[site_id];
  sensor->lip_of_geom_.assign(m->ngeom, -1);
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_group[g] == sensor->config_.lip_geom_group && IsInSubtree(m, m->geom_bodyid[g], root)) {
      sensor->lip_of_geom_[g] = static_cast<int>(sensor->lip_geoms_.size());
      sensor->lip_geoms_.push_back(g);
    }
  }
  if (sensor->lip_geoms_.empty() || sensor->lip_geoms_.size() > kMaxLipSegments) {
    *error = std::string(kChamberPressurePluginName) + ": found " +
             std::to_string(sensor->lip_geoms_.size()) + " lip segment geoms (group " +
             std::to_string(sensor->config_.lip_geom_group) + ") under the site's body; need 1 to " +
             std::to_string(kMaxLipSegments);
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
    sensor->sample_.lip[i].chamber = ChamberOfAngle(std::atan2(local[1], local[0]));
    radius_sum += std::hypot(local[0], local[1]);
  }
  const double arc = 2.0 * M_PI * (radius_sum / n_seg) / n_seg;
  for (LipSegmentState& s : sensor->sample_.lip) s.arc_m = arc;

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
  sensor->ray_dirs_world_.resize(3 * n_rays);
  sensor->ray_geom_.resize(n_rays);
  sensor->ray_dist_.resize(n_rays);
  return sensor;
}

void ChamberPressureSensor::Reset(mjtNum* plugin_state) const {
  ResetSensorChain(reinterpret_cast<SensorChainState*>(plugin_state));
  for (int i = 0; i < kWarmStartSize; ++i) plugin_state[kSensorChainStateSize + i] = 0.0;
  plugin_state[kSeedSlot] = 0.0;
}

void SetChamberPressureRunSeed(const mjModel* m, mjData* d, int instance, std::uint64_t seed) {
  // Doubles hold integers exactly up to 2^53.
  d->plugin_state[m->plugin_stateadr[instance] + kSeedSlot] =
      static_cast<double>(seed & ((std::uint64_t{1} << 53) - 1));
}

void ChamberPressureSensor::Measure(const mjModel* m, const mjData* d,
                                    ChamberPressureSample* sample) const {
  const CupGeometry& geo = config_.geometry;
  const mjtByte* groups = config_.ray_groups.data();
  const mjtNum* site_pos = d->site_xpos + 3 * site_id_;
  const mjtNum* site_mat = d->site_xmat + 9 * site_id_;
  mjtNum axis_z[3];
  Axis(site_mat, 2, axis_z);
  int geom_hit = -1;
  int rays = 0;

  // Lip segments: contacts first, rays for the rest.
  for (LipSegmentState& s : sample->lip) {
    s.in_contact = false;
    s.gap_m = 1.0;
  }
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.dist > 0 || con.geom[0] < 0 || con.geom[1] < 0) continue;
    const int seg0 = lip_of_geom_[con.geom[0]];
    const int seg1 = lip_of_geom_[con.geom[1]];
    if ((seg0 >= 0) == (seg1 >= 0)) continue;  // lip against lip, or no lip at all
    sample->lip[seg0 >= 0 ? seg0 : seg1].in_contact = true;
  }
  for (size_t i = 0; i < lip_geoms_.size(); ++i) {
    LipSegmentState& s = sample->lip[i];
    if (s.in_contact) {
      s.gap_m = 0.0;
      continue;
    }
    // Project the segment onto the lip plane, then look down the cup axis from above it.
    const mjtNum* gp = d->geom_xpos + 3 * lip_geoms_[i];
    mjtNum rel[3] = {gp[0] - site_pos[0], gp[1] - site_pos[1], gp[2] - site_pos[2]};
    const mjtNum along = mju_dot3(rel, axis_z);
    mjtNum start[3];
    for (int k = 0; k < 3; ++k) start[k] = gp[k] - (along + config_.ray_start_m) * axis_z[k];
    // Only gaps within the seal distance matter: the cutoff lets MuJoCo skip far geoms.
    const mjtNum t = mj_ray(m, d, start, axis_z, groups, 1, -1, &geom_hit, nullptr);
    ++rays;
    s.gap_m = t < 0 ? 1.0 : std::max(0.0, t - config_.ray_start_m);
  }

  // Centre of the opening.
  {
    mjtNum start[3];
    for (int k = 0; k < 3; ++k) start[k] = site_pos[k] - config_.ray_start_m * axis_z[k];
    const mjtNum t = mj_ray(m, d, start, axis_z, groups, 1, -1, &geom_hit, nullptr);
    ++rays;
    sample->centre_covered = t >= 0 && t - config_.ray_start_m <= geo.seal_distance_m;
  }

  // Radial rays in the plane seal_distance below the lip plane; each surface crossing toggles
  // covered/uncovered. The first hit of all rays comes from one batched call.
  mjtNum origin[3];
  for (int k = 0; k < 3; ++k) origin[k] = site_pos[k] + geo.seal_distance_m * axis_z[k];
  const int per = geo.rays_per_chamber;
  const int n_rays = per * kNumChambers;
  for (int r = 0; r < n_rays; ++r) {
    mju_mulMatVec3(ray_dirs_world_.data() + 3 * r, site_mat, ray_dirs_local_.data() + 3 * r);
  }
  const double radius = geo.opening_radius_m;
  mj_multiRay(m, const_cast<mjData*>(d), origin, ray_dirs_world_.data(), groups, 1, -1,
              ray_geom_.data(), ray_dist_.data(), nullptr, n_rays, radius);
  rays += n_rays;
  const double dtheta = 0.5 * M_PI / per;
  constexpr double kStepPast = 1e-6;  // restart just past a crossing, metres
  // The horizontal rays give where surfaces begin and end (exactly); whether the stretch between
  // two hits is covered is asked of a vertical ray at its middle, with the same seal-distance
  // rule as the centre. Hits then need no interpretation, so the seams between adjacent convex
  // pieces of one object, overlapping geoms and height fields all read right; the first stretch
  // contains the centre and takes its state.
  auto covered_at = [&](double along) {
    mjtNum start[3];
    for (int q = 0; q < 3; ++q) {
      start[q] = site_pos[q] + along * dir_scratch_[q] - config_.ray_start_m * axis_z[q];
    }
    const mjtNum tv = mj_ray(m, d, start, axis_z, groups, 1, -1, &geom_hit, nullptr);
    ++rays;
    return tv >= 0 && tv - config_.ray_start_m <= geo.seal_distance_m;
  };
  for (int c = 0; c < kNumChambers; ++c) {
    double area = 0.0;
    for (int j = 0; j < per; ++j) {
      const int r = c * per + j;
      const mjtNum* dir = ray_dirs_world_.data() + 3 * r;
      for (int q = 0; q < 3; ++q) dir_scratch_[q] = dir[q];
      double t = ray_dist_[r];
      bool covered = sample->centre_covered;
      double crossings[kMaxCrossings];
      int n = 0;
      for (int k = 0; t >= 0 && t < radius && k < kMaxCrossings; ++k) {
        const double from = t + kStepPast;
        mjtNum start[3];
        for (int q = 0; q < 3; ++q) start[q] = origin[q] + from * dir[q];
        const mjtNum next = mj_ray(m, d, start, dir, groups, 1, -1, &geom_hit, nullptr);
        ++rays;
        const double t_next = next >= 0 ? from + next : -1.0;
        const double stretch_end = (t_next >= 0 && t_next < radius) ? t_next : radius;
        const bool state = covered_at(0.5 * (t + stretch_end));
        if (state != covered) {
          crossings[n++] = t;
          covered = state;
        }
        t = t_next;
      }
      if (n == 0 && kRimBisections > 0) {
        // No boundary seen by the horizontal ray. A surface the ray plane misses (thinner than
        // the seal distance, or grazing that plane) can still end inside the opening: compare
        // the rim with the centre, and bisect with vertical rays if they differ.
        double inside = 0, outside = radius;
        if (covered_at(radius) != covered) {
          for (int b = 0; b < kRimBisections; ++b) {
            const double mid = 0.5 * (inside + outside);
            (covered_at(mid) == covered ? inside : outside) = mid;
          }
          crossings[n++] = 0.5 * (inside + outside);
        }
      }
      area += SubSectorCoveredArea(sample->centre_covered, crossings, n, radius, dtheta);
    }
    sample->sealed_area_m2[c] = area;
  }

  sample->leak_area_m2 = LeakAreas(geo, sample->sealed_area_m2, sample->lip.data(),
                                   static_cast<int>(sample->lip.size()));
  sample->rays_cast = rays;
  sample->time_s = d->time;
}

void ChamberPressureSensor::Compute(const mjModel* m, mjData* d, int instance) {
  mjtNum* raw_state = d->plugin_state + m->plugin_stateadr[instance];
  SensorChainState* state = StateOf(d, m, instance);
  const std::int64_t k = SampleIndexAt(config_.sensor, d->time);
  if (k > static_cast<std::int64_t>(state->last_sample_index)) {
    Measure(m, d, &sample_);
    mjtNum* warm = raw_state + kSensorChainStateSize;
    sample_.flow = SolveFlowNetwork(config_.pneumatics, sample_.leak_area_m2, warm);
    for (int i = 0; i < kNumChambers; ++i) warm[i] = sample_.flow.chamber_pa[i];
    warm[kNumChambers] = sample_.flow.port_pa;
    SensorChainParams sensor = config_.sensor;
    sensor.seed ^= static_cast<std::uint64_t>(raw_state[kSeedSlot]) * 0x9E3779B97F4A7C15ULL;
    TakeSamples(sensor, k, sample_.flow.tap_pa, state);
  }
  const std::array<double, kNumChambers> out = FilteredOutput(*state);
  for (int i = 0; i < kNumChambers; ++i) d->sensordata[sensor_adr_ + i] = out[i];
}

void ChamberPressureSensor::Visualize(const mjModel* m, mjData* d, const mjvOption* opt,
                                      mjvScene* scn) const {
  (void)opt;
  // Lip segments coloured by state: green = sealed (contact), amber = gap within the seal
  // distance, red = open.
  const double seal = config_.geometry.seal_distance_m;
  for (size_t i = 0; i < lip_geoms_.size() && i < sample_.lip.size(); ++i) {
    if (scn->ngeom >= scn->maxgeom) return;
    const LipSegmentState& s = sample_.lip[i];
    float rgba[4] = {0.9f, 0.15f, 0.1f, 1.0f};
    if (s.in_contact) {
      rgba[0] = 0.1f; rgba[1] = 0.85f; rgba[2] = 0.2f;
    } else if (s.gap_m <= seal) {
      rgba[0] = 1.0f; rgba[1] = 0.7f; rgba[2] = 0.0f;
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
  plugin.capabilityflags |= mjPLUGIN_SENSOR;
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
  plugin.compute = +[](const mjModel* m, mjData* d, int instance, int) {
    if (ChamberPressureSensor* sensor = SensorOf(d, instance)) sensor->Compute(m, d, instance);
  };
  plugin.visualize = +[](const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn,
                         int instance) {
    if (const ChamberPressureSensor* sensor = SensorOf(d, instance)) {
      sensor->Visualize(m, d, opt, scn);
    }
  };
  mjp_registerPlugin(&plugin);
}

}  // namespace ssc
