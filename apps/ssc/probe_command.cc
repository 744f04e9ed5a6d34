// ssc probe: the calibration view of the pressure sensor.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "calibration/published_targets.h"
#include "runtime/rig.h"
#include "studies/edge_probe.h"

namespace ssc {

int RunProbe(int argc, char** argv) {
  cli::Command cmd(
      "probe",
      "Moves the cup kinematically (mocap, no arm) across a straight edge and around a\n"
      "35 mm disk at a fixed inset, and writes edge.csv, disk.csv and probe.png: chamber\n"
      "pressures, mean P, differentials and the direction the reference formulas give.");
  std::string scene_name = RigTierFor(RigUse::kProbe).scene, out_dir = "out/probe", note;
  double from = -6, to = 7, step = 0.25, compression = 1.0, settle = 0.1, inset = 2.5,
         disk_step = 15;
  bool no_plot = false;
  cmd.Text("scene", &scene_name, "probe scene (name under scenes/ or a path)");
  cmd.OutputDir("out", &out_dir, "output directory");
  cmd.Number("from", &from, "first offset of the cup centre inside the edge", "mm",
             NumberRange::Closed(-50, 50));
  cmd.Number("to", &to, "last offset", "mm", NumberRange::Closed(-50, 50));
  cmd.Number("step", &step, "offset step", "mm", NumberRange::Positive(100).OpenLow());
  cmd.Number("compression", &compression, "lip plane below the surface top", "mm",
             NumberRange::Closed(-kMaxProbeCompressionMm, kMaxProbeCompressionMm));
  cmd.Number("settle", &settle, "settling time at each placement", "s",
             NumberRange::Positive(kMaxProbeSettleS));
  cmd.Number("disk-inset", &inset, "cup centre inside the disk edge for the disk sweep", "mm",
             NumberRange::Closed(-35, 35));
  cmd.Number("disk-step", &disk_step, "angle step around the disk", "deg",
             NumberRange::Closed(0.1, 360));
  cmd.Text("seed-note", &note, "free text copied to the console (for logs)");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Check([&]() -> std::string {
    if (to < from)
      return "--to (" + FormatNumber(to) + ") must be >= --from (" + FormatNumber(from) + ")";
    if ((to - from) / step > 100000) return "--from/--to/--step give more than 100000 placements";
    return "";
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  if (!note.empty()) std::printf("%s\n", note.c_str());
  std::string error;
  auto probe = EdgeProbe3d::Create(ResolveScenePath(scene_name), &error);
  if (!probe) {
    std::fprintf(stderr, "ssc probe: %s\n", error.c_str());
    return 1;
  }
  if (std::string e = probe->CheckStudyLayout(); !e.empty()) {
    std::fprintf(stderr, "ssc probe: %s: %s\n", scene_name.c_str(), e.c_str());
    return 1;
  }
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;
  ProbeStudySpec spec;
  spec.from_mm = from;
  spec.to_mm = to;
  spec.step_mm = step;
  spec.compression_mm = compression;
  spec.settle_s = settle;
  spec.disk_inset_mm = inset;
  spec.disk_step_deg = disk_step;
  spec.out_dir = out_dir;
  std::printf("straight edge (cup centre inside the edge by offset):\n");
  std::printf(
      "  offset_mm    pbar_pa   |dP|_pa  travel_deg  (travel 90 = along the edge, north)\n");
  ProbeStudyResult result;
  const bool ok = RunProbeStudy(
      probe.get(), spec,
      [](double off, const ProbeReading& r) {
        std::printf("  %8.2f %10.2f %9.2f %10.1f\n", off, r.pbar_pa, std::hypot(r.dpx_pa, r.dpy_pa),
                    r.travel_world_rad * 180 / M_PI);
      },
      &result, &error);
  if (!ok) {
    std::fprintf(stderr, "ssc probe: %s\n", error.c_str());
    return 1;
  }
  std::printf(
      "disk (radius 35 mm, inset %.2f mm): worst direction error vs the CCW tangent "
      "%.1f deg\n",
      inset, result.worst_direction_deg);
  std::printf("wrote %s and %s\n", result.edge_csv.c_str(), result.disk_csv.c_str());
  if (!no_plot) {
    const std::string png = (std::filesystem::path(out_dir) / "probe.png").string();
    // The published depths the plot marks, from their one home: "mm:Pa,mm:Pa,...".
    std::string targets;
    for (std::size_t i = 0; i < kPublishedDepthMm.size(); ++i) {
      char item[64];
      std::snprintf(item, sizeof(item), "%s%g:%g", i ? "," : "", kPublishedDepthMm[i],
                    kPublishedDepthPrefPa[i]);
      targets += item;
    }
    if (RunPlotScript("plot_probe.py", {result.edge_csv, result.disk_csv, png, targets})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
