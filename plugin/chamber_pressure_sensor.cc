#include "plugin/chamber_pressure_sensor.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>

namespace ssc {
namespace {

// Config keys, in the order MuJoCo is told about them.
constexpr const char* kAttributes[] = {
    "opening_radius_mm", "seal_distance_mm",   "lip_roughness_um",   "rays_per_chamber",
    "ray_start_mm",      "ray_groups",         "lip_geom_group",     "pump_max_vacuum_pa",
    "pump_free_flow_lpm", "port_area_mm2",     "neighbour_area_mm2", "tap_recovery",
    "jet_area_mm2",      "discharge_coeff",    "air_density_kg_m3",  "sample_rate_hz",
    "noise_pa",          "average_samples",    "lag_ms",             "seed"};
constexpr int kNumAttributes = sizeof(kAttributes) / sizeof(kAttributes[0]);
constexpr int kWarmStartSize = kNumChambers + 1;
// Vertical-ray bisections that locate an edge the horizontal rays missed: 5.5 mm / 2^6 = 0.09 mm.
constexpr int kRimBisections = 6;
// Per-mjData noise seed (set by the application after a reset), after the warm start.
constexpr int kSeedSlot = kSensorChainStateSize + kWarmStartSize;

// One numeric config value: absent or empty -> default; otherwise must parse fully, be finite and
// lie in [lo, hi] (open ends where flagged).
struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;
};

bool ReadNumber(const mjModel* m, int instance, const char* key, double default_value, Range r,
                const char* unit, double* out, std::string* error) {
  const char* text = mj_getPluginConfig(m, instance, key);
  if (text == nullptr || text[0] == '\0') {
    *out = default_value;
    return true;
  }
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  while (end && *end == ' ') ++end;
  const bool parsed = end != text && end && *end == '\0';
  const bool in_range = std::isfinite(v) && (r.lo_open ? v > r.lo : v >= r.lo) &&
                        (r.hi_open ? v < r.hi : v <= r.hi);
  if (!parsed || !in_range) {
    std::ostringstream os;
    os << kChamberPressurePluginName << ": config key '" << key << "' has value '" << text
       << "'; valid range is " << (r.lo_open ? "(" : "[") << r.lo << ", " << r.hi
       << (r.hi_open ? ")" : "]") << (unit[0] ? " " : "") << unit;
    *error = os.str();
    return false;
  }
  *out = v;
  return true;
}

bool ReadInt(const mjModel* m, int instance, const char* key, int default_value, int lo, int hi,
             int* out, std::string* error) {
  double v = 0;
  if (!ReadNumber(m, instance, key, default_value, {double(lo), double(hi)}, "", &v, error)) {
    return false;
  }
  if (v != std::floor(v)) {
    *error = std::string(kChamberPressurePluginName) + ": config key '" + key +
             "' must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
             "], got '" + mj_getPluginConfig(m, instance, key) + "'";
    return false;
  }
  *out = static_cast<int>(v);
  return true;
}

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

}  // namespace

std::optional<ChamberPressureConfig> ChamberPressureConfig::FromModel(const mjModel* m,
                                                                      int instance,
                                                                      std::string* error) {
  ChamberPressureConfig c;
  PneumaticParams& p = c.pneumatics;
  SensorChainParams& s = c.sensor;
  double v = 0;
  // Geometry.
  if (!ReadNumber(m, instance, "opening_radius_mm", c.geometry.opening_radius_m * 1e3, {0.5, 50}, "mm", &v, error)) return {};
  c.geometry.opening_radius_m = v * 1e-3;
  if (!ReadNumber(m, instance, "seal_distance_mm", c.geometry.seal_distance_m * 1e3, {0, 10}, "mm", &v, error)) return {};
  c.geometry.seal_distance_m = v * 1e-3;
  if (!ReadNumber(m, instance, "lip_roughness_um", c.geometry.lip_roughness_gap_m * 1e6, {0, 1000}, "um", &v, error)) return {};
  c.geometry.lip_roughness_gap_m = v * 1e-6;
  if (!ReadInt(m, instance, "rays_per_chamber", c.geometry.rays_per_chamber, 1, kMaxRaysPerChamber,
               &c.geometry.rays_per_chamber, error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "ray_start_mm", c.ray_start_m * 1e3, {0.1, 1000}, "mm", &v, error)) return {};
  c.ray_start_m = v * 1e-3;
  if (!ReadInt(m, instance, "lip_geom_group", c.lip_geom_group, 0, mjNGROUP - 1, &c.lip_geom_group, error)) {
    return {};
  }
  const char* groups = mj_getPluginConfig(m, instance, "ray_groups");
  if (groups == nullptr || groups[0] == '\0') groups = "0 2";
  {
    std::istringstream in(groups);
    std::string token;
    int count = 0;
    while (in >> token) {
      char* end = nullptr;
      const long g = std::strtol(token.c_str(), &end, 10);
      if (*end != '\0' || g < 0 || g >= mjNGROUP) {
        *error = std::string(kChamberPressurePluginName) + ": config key 'ray_groups' has value '" +
                 groups + "'; expected space-separated geom groups in [0, " +
                 std::to_string(mjNGROUP - 1) + "]";
        return {};
      }
      c.ray_groups[g] = 1;
      ++count;
    }
    if (count == 0) {
      *error = std::string(kChamberPressurePluginName) +
               ": config key 'ray_groups' lists no geom group; expected groups in [0, 5]";
      return {};
    }
  }
  if (c.ray_groups[c.lip_geom_group]) {
    *error = std::string(kChamberPressurePluginName) + ": lip_geom_group " +
             std::to_string(c.lip_geom_group) +
             " is also in ray_groups: the rays would hit the cup's own lip";
    return {};
  }
  // Pneumatics.
  if (!ReadNumber(m, instance, "pump_max_vacuum_pa", p.pump_max_vacuum_pa, {0, 100000, true, true}, "Pa",
                  &p.pump_max_vacuum_pa, error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "pump_free_flow_lpm", p.pump_free_flow_m3_s * 60000.0, {0, 60000, true}, "L/min", &v, error)) {
    return {};
  }
  p.pump_free_flow_m3_s = v / 60000.0;
  if (!ReadNumber(m, instance, "port_area_mm2", p.port_area_m2 * 1e6, {0, 10000, true}, "mm^2", &v, error)) return {};
  p.port_area_m2 = v * 1e-6;
  if (!ReadNumber(m, instance, "neighbour_area_mm2", p.neighbour_area_m2 * 1e6, {0, 10000}, "mm^2", &v, error)) {
    return {};
  }
  p.neighbour_area_m2 = v * 1e-6;
  if (!ReadNumber(m, instance, "tap_recovery", p.tap_recovery, {0, 1}, "", &p.tap_recovery, error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "jet_area_mm2", p.jet_area_m2 * 1e6, {0, 10000, true}, "mm^2", &v, error)) return {};
  p.jet_area_m2 = v * 1e-6;
  if (!ReadNumber(m, instance, "discharge_coeff", p.discharge_coeff, {0, 1, true}, "", &p.discharge_coeff,
                  error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "air_density_kg_m3", p.air_density_kg_m3, {0.1, 10, true}, "kg/m^3",
                  &p.air_density_kg_m3, error)) {
    return {};
  }
  // Sensor chain.
  if (!ReadNumber(m, instance, "sample_rate_hz", s.sample_rate_hz, {1, 100000}, "Hz", &s.sample_rate_hz,
                  error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "noise_pa", s.noise_pa, {0, 10000}, "Pa", &s.noise_pa, error)) return {};
  if (!ReadInt(m, instance, "average_samples", s.average_samples, 1, kMaxAverageSamples, &s.average_samples,
               error)) {
    return {};
  }
  if (!ReadNumber(m, instance, "lag_ms", s.lag_s * 1e3, {0, 10000}, "ms", &v, error)) return {};
  s.lag_s = v * 1e-3;
  if (!ReadNumber(m, instance, "seed", double(s.seed), {0, 9007199254740992.0}, "", &v, error)) return {};
  if (v != std::floor(v)) {
    *error = std::string(kChamberPressurePluginName) +
             ": config key 'seed' must be a whole number in [0, 2^53]";
    return {};
  }
  s.seed = static_cast<std::uint64_t>(v);
  // The pure structs validate their own invariants once more (belt and braces).
  for (const std::string& e : {c.geometry.Validate(), p.Validate(), s.Validate()}) {
    if (!e.empty()) {
      *error = std::string(kChamberPressurePluginName) + ": " + e;
      return {};
    }
  }
  return c;
}

ChamberPressureSensor::ChamberPressureSensor(ChamberPressureConfig config, int site_id,
                                             int sensor_adr)
    : config_(std::move(config)), site_id_(site_id), sensor_adr_(sensor_adr) {}

int ChamberPressureSensor::StateSize() { return kSeedSlot + 1; }

ChamberPressureSensor* ChamberPressureSensor::Create(const mjModel* m, mjData* d, int instance,
                                                     std::string* error) {
  (void)d;
  std::optional<ChamberPressureConfig> config = ChamberPressureConfig::FromModel(m, instance, error);
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
  auto* sensor = new ChamberPressureSensor(std::move(*config), site_id, m->sensor_adr[sensor_id]);

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

void ChamberPressureSensor::SetRunSeed(const mjModel* m, mjData* d, int instance,
                                       std::uint64_t seed) {
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

ChamberPressureSensor* FindChamberPressureSensor(const mjModel* m, mjData* d, int* instance) {
  int slot = -1;
  const mjpPlugin* plugin = mjp_getPlugin(kChamberPressurePluginName, &slot);
  if (plugin == nullptr) return nullptr;
  for (int i = 0; i < m->nplugin; ++i) {
    if (m->plugin[i] == slot && d->plugin_data[i] != 0) {
      if (instance) *instance = i;
      return reinterpret_cast<ChamberPressureSensor*>(d->plugin_data[i]);
    }
  }
  return nullptr;
}

void ChamberPressureSensor::RegisterPlugin() {
  mjpPlugin plugin;
  mjp_defaultPlugin(&plugin);
  plugin.name = kChamberPressurePluginName;
  plugin.capabilityflags |= mjPLUGIN_SENSOR;
  plugin.nattribute = kNumAttributes;
  plugin.attributes = kAttributes;
  // Position stage: a control callback in the same step sees this step's pressures.
  plugin.needstage = mjSTAGE_POS;
  plugin.nstate = +[](const mjModel*, int) { return StateSize(); };
  plugin.nsensordata = +[](const mjModel*, int, int) { return kNumChambers; };
  plugin.init = +[](const mjModel* m, mjData* d, int instance) {
    std::string error;
    ChamberPressureSensor* sensor = Create(m, d, instance, &error);
    if (sensor == nullptr) {
      mju_warning("%s", error.c_str());
      return -1;
    }
    d->plugin_data[instance] = reinterpret_cast<uintptr_t>(sensor);
    sensor->Reset(d->plugin_state + m->plugin_stateadr[instance]);
    return 0;
  };
  plugin.destroy = +[](mjData* d, int instance) {
    delete reinterpret_cast<ChamberPressureSensor*>(d->plugin_data[instance]);
    d->plugin_data[instance] = 0;
  };
  plugin.copy = +[](mjData* dest, const mjModel*, const mjData* src, int instance) {
    auto* to = reinterpret_cast<ChamberPressureSensor*>(dest->plugin_data[instance]);
    auto* from = reinterpret_cast<const ChamberPressureSensor*>(src->plugin_data[instance]);
    if (to && from) to->CopyDiagnosticsFrom(*from);
  };
  plugin.reset = +[](const mjModel*, mjtNum* plugin_state, void* plugin_data, int) {
    auto* sensor = reinterpret_cast<ChamberPressureSensor*>(plugin_data);
    if (sensor) sensor->Reset(plugin_state);
  };
  plugin.compute = +[](const mjModel* m, mjData* d, int instance, int) {
    auto* sensor = reinterpret_cast<ChamberPressureSensor*>(d->plugin_data[instance]);
    if (sensor) sensor->Compute(m, d, instance);
  };
  plugin.visualize = +[](const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn,
                         int instance) {
    auto* sensor = reinterpret_cast<ChamberPressureSensor*>(d->plugin_data[instance]);
    if (sensor) sensor->Visualize(m, d, opt, scn);
  };
  mjp_registerPlugin(&plugin);
}

}  // namespace ssc
