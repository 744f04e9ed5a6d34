// The sensor at its extremes: in air, fully sealed, sliding off a corner, crossing the edge of a
// sheet thinner than the seal distance, and a surface passing the seal distance below the lip.
// No NaN, and no jump between consecutive samples larger than the stated bound.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "geometry/dimensions.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"
#include "tests/scratch_dir.h"

namespace ssc {
namespace {

namespace fs = std::filesystem;

// Tool on a mocap body (tool0 frame; tool z down) over: a plate with a corner at (0, 0) covering
// x < 0, y < 0 (top 10 mm); a 0.3 mm sheet floating at 10 mm covering x > 0.1 (air below).
std::string Scene() {
  const fs::path dir = ScratchDir() / "ssc_extremes";
  fs::create_directories(dir);
  const fs::path path = dir / "extremes.xml";
  std::ofstream(path)
      << "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.001\" "
         "integrator=\"implicitfast\"/>"
      << "<asset><model name=\"ssc_tool\" file=\"" << SourceDir()
      << "/models/ssc_tool.xml\"/></asset>"
      << "<worldbody><geom name=\"table\" type=\"plane\" size=\"1 1 0.01\"/>"
      << "<geom name=\"plate\" type=\"box\" size=\"0.05 0.05 0.005\" pos=\"-0.05 -0.05 0.005\" "
         "group=\"2\"/>"
      << "<geom name=\"sheet\" type=\"box\" size=\"0.05 0.05 0.00015\" pos=\"0.15 0 0.00985\" "
         "group=\"2\"/>"
      << "<body name=\"probe\" mocap=\"true\" pos=\"0 0 0.3\" quat=\"0 0.70710678 -0.70710678 0\">"
      << "<attach model=\"ssc_tool\" body=\"tool\" prefix=\"ssc_\"/></body></worldbody></mujoco>";
  return path.string();
}

struct SweepRecord {
  std::vector<double> pbar;  // noiseless mean tap pressure at every new sample
  bool finite = true;
};

// Moves the lip-plane centre along `path(s)` (s from 0 to 1 over `duration_s`) and records.
SweepRecord Sweep(const std::function<std::array<double, 3>(double)>& path, double duration_s) {
  std::string error;
  static ModelPtr m = LoadModel(Scene(), &error);
  EXPECT_TRUE(m) << error;
  DataPtr d = MakeData(m.get(), &error);
  const ChamberPressureDiagnostics* sensor = FindChamberPressureDiagnostics(m.get(), d.get());
  SweepRecord run;
  double last_sample = -1;
  const int steps = static_cast<int>(duration_s / m->opt.timestep);
  for (int i = 0; i <= steps; ++i) {
    const auto p = path(static_cast<double>(i) / steps);
    d->mocap_pos[0] = p[0];
    d->mocap_pos[1] = p[1];
    d->mocap_pos[2] = p[2] + kToolCentreOffsetM;  // tool0 is above the lip plane
    mj_step(m.get(), d.get());
    const ChamberPressureSample& s = sensor->last_sample();
    if (s.time_s != last_sample) {
      last_sample = s.time_s;
      double mean = 0;
      for (double v : s.flow.tap_pa) {
        run.finite = run.finite && std::isfinite(v);
        mean += 0.25 * v;
      }
      for (int k = 0; k < 4; ++k) run.finite = run.finite && std::isfinite(d->sensordata[k]);
      run.pbar.push_back(mean);
    }
  }
  return run;
}

// Largest change of log10(mean vacuum, floored at 1 Pa) between consecutive samples.
double MaxLogJump(const SweepRecord& r, size_t skip = 20) {
  double worst = 0;
  for (size_t i = skip + 1; i < r.pbar.size(); ++i) {
    worst = std::max(worst, std::fabs(std::log10(std::max(1.0, r.pbar[i])) -
                                      std::log10(std::max(1.0, r.pbar[i - 1]))));
  }
  return worst;
}

constexpr double kLipPlaneOnPlate = 0.010 - 0.001;  // 1 mm compression

TEST(SensorExtremesTest, InAirAndFullySealed) {
  const SweepRecord air = Sweep([](double) { return std::array<double, 3>{0.3, 0.3, 0.2}; }, 0.3);
  EXPECT_TRUE(air.finite);
  EXPECT_LT(air.pbar.back(), 5.0);
  const SweepRecord sealed = Sweep(
      [](double) {
        return std::array<double, 3>{-0.03, -0.03, kLipPlaneOnPlate};
      },
      0.3);
  EXPECT_TRUE(sealed.finite);
  EXPECT_GT(sealed.pbar.back(), 10000.0);
}

TEST(SensorExtremesTest, SlidingOffACornerIsSmooth) {
  // Diagonally out over the plate's corner at 20 mm/s: 0.125 mm per 160 Hz sample.
  const SweepRecord r = Sweep(
      [](double s) {
        const double t = -0.012 + 0.024 * s;
        return std::array<double, 3>{t, t, kLipPlaneOnPlate};
      },
      1.2);
  EXPECT_TRUE(r.finite);
  EXPECT_GT(r.pbar.front(), 10000.0);
  EXPECT_LT(r.pbar.back(), 5.0);
  EXPECT_LT(MaxLogJump(r), 0.6) << "bound: 0.6 decades per sample (0.125 mm of travel)";
}

TEST(SensorExtremesTest, EdgeOfASheetThinnerThanTheSealDistance) {
  // Across the edge of a 0.3 mm sheet (seal distance 0.5 mm) at 20 mm/s; the lip presses 1 mm.
  const SweepRecord r = Sweep(
      [](double s) {
        return std::array<double, 3>{0.1 + 0.012 - 0.024 * s, 0.0, kLipPlaneOnPlate};
      },
      1.2);
  EXPECT_TRUE(r.finite);
  EXPECT_GT(r.pbar.front(), 10000.0);
  EXPECT_LT(r.pbar.back(), 5.0);
  EXPECT_LT(MaxLogJump(r), 0.6) << "bound: 0.6 decades per sample (0.125 mm of travel)";
}

TEST(SensorExtremesTest, SurfacePassingTheSealDistanceBelowTheLip) {
  // Lowering the cup over the plate from 4 mm above to 1 mm into it at 10 mm/s. The seal
  // distance (2.75 mm) is where a hovering lip's curtain (perimeter x gap) equals the opening's
  // area, so the leak is continuous through it: no step beyond the smooth bound either.
  const SweepRecord r = Sweep(
      [](double s) {
        return std::array<double, 3>{-0.03, -0.03, 0.010 + 0.004 - 0.005 * s};
      },
      0.5);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.pbar.front(), 5.0);
  EXPECT_GT(r.pbar.back(), 10000.0);
  EXPECT_LT(MaxLogJump(r), 0.6) << "bound: 0.6 decades per sample (0.06 mm of travel)";
}

}  // namespace
}  // namespace ssc
