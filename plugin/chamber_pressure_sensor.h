// ssc.chamber_pressure: a MuJoCo sensor plugin that estimates the four chamber vacuum pressures
// of the Smart Suction Cup from the compliant lip's contacts and the sealed area under the cup.
//
// MJCF:
//   <extension><plugin plugin="ssc.chamber_pressure">
//     <instance name="ssc_pressure"><config key="noise_pa" value="6"/></instance>
//   </plugin></extension>
//   <sensor><plugin name="ssc_chamber_pressure" instance="ssc_pressure"
//                   objtype="site" objname="ssc_tool_site"/></sensor>
//
// Frames: the sensor's site is the tool frame at the lip plane: +x toward the south chambers,
// +y toward the west chambers, +z along the cup axis down into the object (see
// plugin/pneumatics/cup_geometry.h for the chamber layout).
//
// Output (4 values): the host-filtered vacuum of chambers 1..4 in Pa, positive = vacuum,
// i.e. sensor noise, zero-order hold at the sensor rate and the 7-sample moving average are
// already applied (the controller must not filter again).
//
// What it reads each sensor sample (never more often than sample_rate_hz):
//   - lip segments: geoms in the site body's subtree whose group is lip_geom_group. A segment is
//     sealed when MuJoCo reports a contact of it with any geom; otherwise a ray along the cup axis
//     gives its gap to the surface below.
//   - the opening: a vertical ray at the centre and, per chamber, rays_per_chamber radial rays
//     in the plane seal_distance_mm below the lip plane find where a surface within the seal
//     distance begins and ends; the covered part of each chamber's opening is its sealed area.
//   Rays see only geoms in ray_groups (the cup's own geoms live in other groups); give object
//   geoms a group in ray_groups and contype/conaffinity that collide with the lip, so that rays
//   and contacts see the same surfaces.
//
// Config keys (all optional; units in the key; ranges enforced at load):
//   geometry:  opening_radius_mm 5.5 [0.5, 50]; seal_distance_mm 2.75 [0, 10];
//              lip_roughness_um 18 [0, 1000]; rays_per_chamber 4 [1, 64];
//              ray_start_mm 10 [0.1, 1000] (rays start this far above the lip plane);
//              ray_groups "0 2" (geom groups 0..5 the rays see; group 1 is the robot); lip_geom_group 4 [0, 5]
//   pneumatics: pump_max_vacuum_pa 40000 (0, 100000); pump_free_flow_lpm 12.9 (0, 60000];
//              port_area_mm2 22 (0, 10000]; neighbour_area_mm2 0.5 [0, 10000];
//              tap_recovery 0.97 [0, 1]; jet_area_mm2 7 (0, 10000];
//              discharge_coeff 0.6 (0, 1]; air_density_kg_m3 1.2 (0.1, 10]
//   sensor chain: sample_rate_hz 160 [1, 100000]; noise_pa 6 [0, 10000];
//              average_samples 7 [1, 64]; lag_ms 0 [0, 10000]; seed 0 [0, 2^53]
#ifndef SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_
#define SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/flow_network.h"
#include "plugin/pneumatics/sensor_chain.h"

namespace ssc {

inline constexpr char kChamberPressurePluginName[] = "ssc.chamber_pressure";

// Every config value, parsed and validated once.
struct ChamberPressureConfig {
  CupGeometry geometry;
  PneumaticParams pneumatics;
  SensorChainParams sensor;
  double ray_start_m = 0.01;
  std::array<mjtByte, mjNGROUP> ray_groups{};  // 1 = seen by rays
  int lip_geom_group = 4;

  // Parses the instance's config; on error returns nullopt and fills *error with a message that
  // names the key, the value and the valid range.
  static std::optional<ChamberPressureConfig> FromModel(const mjModel* m, int instance,
                                                        std::string* error);
};

// What the sensor measured at its newest sample, before noise and filtering.
struct ChamberPressureSample {
  double time_s = -1.0;
  std::array<double, kNumChambers> sealed_area_m2{};
  std::array<double, kNumChambers> leak_area_m2{};
  bool centre_covered = false;
  FlowSolution flow;
  std::vector<LipSegmentState> lip;  // sized once at init
  int rays_cast = 0;
};

class ChamberPressureSensor {
 public:
  // Returns nullptr (after mju_warning with the reason) when the config or model is invalid.
  static ChamberPressureSensor* Create(const mjModel* m, mjData* d, int instance,
                                       std::string* error);

  void Reset(mjtNum* plugin_state) const;
  void Compute(const mjModel* m, mjData* d, int instance);
  void Visualize(const mjModel* m, mjData* d, const mjvOption* opt, mjvScene* scn) const;

  // Geometric measurement and network solution at the current mjData, no noise, no filter.
  // Used by Compute and by tools that need the noiseless static pressures.
  void Measure(const mjModel* m, const mjData* d, ChamberPressureSample* sample) const;

  const ChamberPressureConfig& config() const { return config_; }
  const ChamberPressureSample& last_sample() const { return sample_; }
  int site_id() const { return site_id_; }
  int num_lip_segments() const { return static_cast<int>(lip_geoms_.size()); }
  int lip_geom(int segment) const { return lip_geoms_[segment]; }
  void CopyDiagnosticsFrom(const ChamberPressureSensor& other) { sample_ = other.sample_; }

  // Per-run noise seed kept in mjData's plugin state (combined with the config's `seed`);
  // mj_resetData sets it back to 0, so set it after each reset.
  static void SetRunSeed(const mjModel* m, mjData* d, int instance, std::uint64_t seed);

  static void RegisterPlugin();
  static int StateSize();

 private:
  ChamberPressureSensor(ChamberPressureConfig config, int site_id, int sensor_adr);

  ChamberPressureConfig config_;
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

// The sensor object behind plugin instance `instance` of `d`, or nullptr when that instance is
// not an ssc.chamber_pressure sensor. For tools linked against this library (probe, viewer).
ChamberPressureSensor* FindChamberPressureSensor(const mjModel* m, mjData* d, int* instance);

}  // namespace ssc

#endif  // SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_
