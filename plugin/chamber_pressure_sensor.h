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
//   - lip segments: geoms in the site body's subtree whose group is lip_geom_group. A segment
//     touches when MuJoCo reports a contact of it with any geom; otherwise a ray along the cup
//     axis gives the gap from its tip to the surface below.
//   - the opening (in the frame of the body carrying the lip, so it shears and tilts with a soft
//     lip): per chamber, rays_per_chamber radial rays in a plane open_depth_mm below the lip tips
//     find where surfaces begin and end; each stretch between them is sampled by vertical rays
//     (the gap field). Each wedge's leak follows from its rim gap and gap field
//     (pneumatics/cup_geometry.h: WedgeLeakArea); no distance threshold decides a chamber.
// Passive forces (same plugin, mjPLUGIN_PASSIVE): the lip ring's bending couples the segments'
// slide joints; the lip carrier's shear slides and tilt hinges get springs when lip_shear_n_per_mm
// / lip_tilt_nmm_per_deg are set, and stay locked by their equality constraints when 0.
//   Rays see only geoms in ray_groups (the cup's own geoms live in other groups); give object
//   geoms a group in ray_groups and contype/conaffinity that collide with the lip, so that rays
//   and contacts see the same surfaces.
//
// Config keys: one table in plugin/chamber_pressure_config.cc; docs/plugin.md lists each key with
// its unit, default and range (generated from that table).
//
// Tools (trials, viewer, probe, replay, bench) see a sensor only through the read-only
// ChamberPressureDiagnostics below; the sensor class itself is private to the plugin.
#ifndef SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_
#define SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_

#include <mujoco/mujoco.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "plugin/chamber_pressure_config.h"
#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/flow_network.h"
#include "plugin/pneumatics/sensor_chain.h"

namespace ssc {

// What the sensor measured at its newest sample, before noise and filtering.
struct ChamberPressureSample {
  double time_s = -1.0;
  std::array<double, kNumChambers> sealed_area_m2{};
  std::array<double, kNumChambers> leak_area_m2{};
  std::array<double, kNumChambers> jet_area_m2{};  // part of the leak that passes the taps as a jet
  bool centre_covered = false;
  FlowSolution flow;
  std::vector<LipSegmentState> lip;  // sized once at init
  std::vector<OpeningWedge> wedges;  // one per radial ray, sized once at init
  int rays_cast = 0;
};

// Read-only diagnostics of one sensor instance. Valid while its mjData lives.
class ChamberPressureDiagnostics {
 public:
  virtual ~ChamberPressureDiagnostics() = default;
  virtual int instance() const = 0;    // plugin instance id
  virtual int site_id() const = 0;     // the tool site the sensor is attached to
  virtual int sensor_adr() const = 0;  // first of its 4 values in sensordata
  virtual int num_lip_segments() const = 0;
  virtual const ChamberPressureConfig& config() const = 0;
  virtual const ChamberPressureSample& last_sample() const = 0;
  // The force the chamber vacuums put on the tool (a flex skirt and the cup; world frame, N) at
  // the last passive evaluation; zero for a segment lip or with lip_vacuum_load off.
  virtual std::array<double, 3> lip_vacuum_force_n(const mjModel* m, const mjData* d) const = 0;
  // Their moment about the tool site (world frame, N m), the same evaluation.
  virtual std::array<double, 3> lip_vacuum_torque_nm(const mjModel* m, const mjData* d) const = 0;
  // Geometric measurement and network inputs at the current mjData, no noise, no filter (for
  // tools that need the noiseless static pressures); does not touch the sensor's state.
  virtual void Measure(const mjModel* m, const mjData* d, ChamberPressureSample* sample) const = 0;
};

// The diagnostics of the ssc.chamber_pressure instance of `d`: the one way for tools to reach a
// sensor. nullptr when the model has none, or more than one (a scene with two cups: which one a
// trial follows with cannot be guessed); `why` (may be null) then says which.
const ChamberPressureDiagnostics* FindChamberPressureDiagnostics(const mjModel* m, const mjData* d,
                                                                 std::string* why = nullptr);

// Per-run noise seed kept in mjData's plugin state (combined with the config's `seed`);
// mj_resetData sets it back to 0, so set it after each reset.
void SetChamberPressureRunSeed(const mjModel* m, mjData* d, int instance, std::uint64_t seed);

// Sets the per-run noise seed on a running sensor and re-derives the noise of the samples it
// holds for it (the samples, lag and sample times stay): the state and the sensor's output are
// then what a run with `seed` from the start would have at this mjData, as long as the pressures
// fed nothing back (the shared approach, runtime/approach_cache.h). Bit-identical.
void ReseedChamberPressure(const mjModel* m, mjData* d, int instance, std::uint64_t seed);

// Registers the plugin with MuJoCo (the library's init does this when it is loaded).
void RegisterChamberPressurePlugin();

}  // namespace ssc

#endif  // SSC_PLUGIN_CHAMBER_PRESSURE_SENSOR_H_
