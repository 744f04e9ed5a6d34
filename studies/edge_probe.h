// Kinematic probe of the pressure sensor: the cup held by a mocap body (the rig's probe tier)
// and placed at given offsets across a straight edge or around a disk edge. The lip segments
// still settle dynamically on the surface at each placement; the cup body does not move.
#ifndef SSC_STUDIES_EDGE_PROBE_H_
#define SSC_STUDIES_EDGE_PROBE_H_

#include <array>
#include <functional>
#include <memory>
#include <string>

#include "geometry/dimensions.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"

namespace ssc {

struct ProbeReading {
  double x_m = 0, y_m = 0, yaw_rad = 0;
  std::array<double, 4> filtered_pa{};  // plugin output (noise + moving average)
  std::array<double, 4> static_pa{};    // noiseless tap pressures of the newest sample
  std::array<double, 4> sealed_area_mm2{};
  std::array<double, 4> leak_area_mm2{};
  int lip_contacts = 0;
  // Reference formulas on the filtered pressures (docs/controllers.md): differentials and the
  // world-frame direction toward the object (g) and of travel with the object on the left.
  double pbar_pa = 0, dpx_pa = 0, dpy_pa = 0;
  double g_world_rad = 0, travel_world_rad = 0;
  double static_pbar_pa = 0;
};

// Bounds of a placement's settling time and lip compression (ssc probe's --settle and
// --compression, Probe.read's settle_s and compression_m).
constexpr double kMaxProbeSettleS = 10;
constexpr double kMaxProbeCompressionMm = 10;

class EdgeProbe3d {
 public:
  // Loads the probe scene; null on error (message in *error).
  static std::unique_ptr<EdgeProbe3d> Create(const std::string& scene_path, std::string* error);

  // Places the tool centre (lip plane) at world (x, y), the lip plane `compression_m` below the
  // surface top `surface_z_m`, the tool rotated by yaw about the world z axis relative to the
  // project's convention, lets the lip settle for settle_s and reads the sensor.
  // Read() expects a placement CheckPlacement() accepts: "" or what is out of range.
  ProbeReading Read(double x_m, double y_m, double yaw_rad, double surface_z_m,
                    double compression_m, double settle_s);
  static std::string CheckPlacement(double x_m, double y_m, double yaw_rad, double surface_z_m,
                                    double compression_m, double settle_s);

  // "" when the scene has the layout RunProbeStudy probes (the rig's probe tier): the plate's
  // straight edge along world y at x = 0 (plate at x < 0) and the benchmark disk centred at
  // (kProbeDiskCentreXM, 0), both with their top at kProbeSurfaceTopM; else the first point
  // where it differs. A scene without it (the replay tier, another probe scene) would be probed in
  // air and give a table of sensor noise. Surfaces found by rays with the tool lifted away.
  std::string CheckStudyLayout();

  const mjModel* model() const { return model_.get(); }
  mjData* data() const { return data_.get(); }

 private:
  EdgeProbe3d() = default;
  ModelPtr model_;
  DataPtr data_;
  const ChamberPressureDiagnostics* sensor_ = nullptr;
  int instance_ = -1;
  int mocap_id_ = -1;
  int sensor_adr_ = -1;
  double tool_length_m_ = kToolCentreOffsetM;  // measured from the model at Create
};

// The probe tier's layout (runtime/rig.h): the plate edge at x = 0 and the disk's
// centre on the x axis, both surfaces' top height.
constexpr double kProbeSurfaceTopM = 0.010;
constexpr double kProbeDiskCentreXM = 0.15;

// ssc probe as a library function: the cup placed across a straight edge (plate at world x < 0,
// top at z = 10 mm) from from_mm to to_mm inside it, then round the 35 mm disk (centre
// (0.15, 0) m) at a fixed inset; OUT/edge.csv and OUT/disk.csv, one row per placement. False
// with *error when the scene lacks that layout (EdgeProbe3d::CheckStudyLayout) or a file fails.
struct ProbeStudySpec {
  double from_mm = -6, to_mm = 7, step_mm = 0.25;  // cup centre inside the edge
  double compression_mm = 1.0;                     // lip plane below the surface top
  double settle_s = 0.1;
  double disk_inset_mm = 2.5, disk_step_deg = 15;
  std::string out_dir;
};

struct ProbeStudyResult {
  double worst_direction_deg = 0;  // round the disk: travel direction vs the CCW tangent
  std::string edge_csv, disk_csv;
};

// `edge_row` (optional) sees each straight-edge placement. False + *error on a write failure.
bool RunProbeStudy(EdgeProbe3d* probe, const ProbeStudySpec& spec,
                   const std::function<void(double offset_mm, const ProbeReading&)>& edge_row,
                   ProbeStudyResult* result, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_EDGE_PROBE_H_
