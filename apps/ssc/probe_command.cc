// ssc probe: the calibration view of the pressure sensor.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/plotting.h"
#include "studies/edge_probe.h"

namespace ssc {
namespace {

void WriteHeader(std::ofstream& f) {
  f << "offset_mm,angle_deg,x_mm,y_mm,p1_pa,p2_pa,p3_pa,p4_pa,pbar_pa,dpx_pa,dpy_pa,diff_pa,"
       "g_world_deg,travel_world_deg,static_p1_pa,static_p2_pa,static_p3_pa,static_p4_pa,"
       "static_pbar_pa,sealed1_mm2,sealed2_mm2,sealed3_mm2,sealed4_mm2,leak1_mm2,leak2_mm2,"
       "leak3_mm2,leak4_mm2,lip_contacts\n";
}

void WriteRow(std::ofstream& f, double offset_mm, double angle_deg, const ProbeReading& r) {
  char line[1024];
  const double deg = 180.0 / M_PI;
  std::snprintf(line, sizeof(line),
                "%.4f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,"
                "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n",
                offset_mm, angle_deg, r.x_m * 1e3, r.y_m * 1e3, r.filtered_pa[0],
                r.filtered_pa[1], r.filtered_pa[2], r.filtered_pa[3], r.pbar_pa, r.dpx_pa,
                r.dpy_pa, std::hypot(r.dpx_pa, r.dpy_pa), r.g_world_rad * deg,
                r.travel_world_rad * deg, r.static_pa[0], r.static_pa[1], r.static_pa[2],
                r.static_pa[3], r.static_pbar_pa, r.sealed_area_mm2[0], r.sealed_area_mm2[1],
                r.sealed_area_mm2[2], r.sealed_area_mm2[3], r.leak_area_mm2[0],
                r.leak_area_mm2[1], r.leak_area_mm2[2], r.leak_area_mm2[3], r.lip_contacts);
  f << line;
}

}  // namespace

int RunProbe(int argc, char** argv) {
  cli::Command cmd("probe",
                   "Moves the cup kinematically (mocap, no arm) across a straight edge and around a\n"
                   "35 mm disk at a fixed inset, and writes edge.csv, disk.csv and probe.png: chamber\n"
                   "pressures, mean P, differentials and the direction the reference formulas give.");
  std::string scene_name = "probe_edge", out_dir = "out/probe", note;
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
             NumberRange::Closed(-10, 10));
  cmd.Number("settle", &settle, "settling time at each placement", "s", NumberRange::Positive(10));
  cmd.Number("disk-inset", &inset, "cup centre inside the disk edge for the disk sweep", "mm",
             NumberRange::Closed(-35, 35));
  cmd.Number("disk-step", &disk_step, "angle step around the disk", "deg",
             NumberRange::Closed(0.1, 360));
  cmd.Text("seed-note", &note, "free text copied to the console (for logs)");
  cmd.Flag("no-plot", &no_plot, "skip the PNG plot");
  cmd.Check([&]() -> std::string {
    if (to < from) return "--to (" + FormatNumber(to) + ") must be >= --from (" + FormatNumber(from) + ")";
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
  const std::filesystem::path out = out_dir;

  // Straight edge along world y at x = 0, plate at x < 0 with its top at z = 10 mm.
  const double surface_z = 0.010;
  std::ofstream edge(out / "edge.csv");
  WriteHeader(edge);
  std::printf("straight edge (cup centre inside the edge by offset):\n");
  std::printf("  offset_mm    pbar_pa   |dP|_pa  travel_deg  (travel 90 = along the edge, north)\n");
  for (double off = from; off <= to + 1e-9; off += step) {
    const ProbeReading r = probe->Read(-off * 1e-3, 0.0, 0.0, surface_z, compression * 1e-3, settle);
    WriteRow(edge, off, 0.0, r);
    std::printf("  %8.2f %10.2f %9.2f %10.1f\n", off, r.pbar_pa, std::hypot(r.dpx_pa, r.dpy_pa),
                r.travel_world_rad * 180 / M_PI);
  }
  edge.close();

  // Around the disk (centre (0.15, 0), radius 35 mm) at a fixed inset.
  std::ofstream disk(out / "disk.csv");
  WriteHeader(disk);
  const double cx = 0.15, radius = 0.035;
  double worst_deg = 0;
  for (double a = 0; a < 360 - 1e-9; a += disk_step) {
    const double th = a * M_PI / 180;
    const double r_m = radius - inset * 1e-3;
    const ProbeReading r = probe->Read(cx + r_m * std::cos(th), r_m * std::sin(th), 0.0,
                                       surface_z, compression * 1e-3, settle);
    WriteRow(disk, inset, a, r);
    // Counter-clockwise tangent at angle th is th + 90 deg.
    double err = std::remainder(r.travel_world_rad - (th + M_PI / 2), 2 * M_PI) * 180 / M_PI;
    worst_deg = std::max(worst_deg, std::fabs(err));
  }
  disk.close();
  std::printf("disk (radius 35 mm, inset %.2f mm): worst direction error vs the CCW tangent "
              "%.1f deg\n", inset, worst_deg);
  std::printf("wrote %s and %s\n", (out / "edge.csv").c_str(), (out / "disk.csv").c_str());
  if (!no_plot) {
    const std::string png = (out / "probe.png").string();
    if (RunPlotScript("plot_probe.py", {(out / "edge.csv").string(), (out / "disk.csv").string(),
                                        png})) {
      std::printf("wrote %s\n", png.c_str());
    }
  }
  return 0;
}

}  // namespace ssc
