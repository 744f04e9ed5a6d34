#include "viewer/overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssc {
namespace {

constexpr int kTracePoints = 600;

bool Room(const mjvScene* scn) { return scn->ngeom < scn->maxgeom; }

void Arrow(mjvScene* scn, const mjtNum from[3], const mjtNum dir_world[3], double length_m,
           const float rgba[4]) {
  if (!Room(scn)) return;
  mjtNum to[3];
  for (int k = 0; k < 3; ++k) to[k] = from[k] + length_m * dir_world[k];
  mjvGeom* g = scn->geoms + scn->ngeom;
  mjv_initGeom(g, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
  mjv_connector(g, mjGEOM_ARROW, 0.0012, from, to);
  g->category = mjCAT_DECOR;
  ++scn->ngeom;
}

}  // namespace

void AddTrialDecorations(const mjModel* m, const mjData* d, const ContourTrial& trial,
                         int tool_site, mjvScene* scn) {
  (void)m;
  // Cup-centre trace (last points of the follow phase), as a polyline of thin capsules.
  const auto& path = trial.path();
  const size_t first = path.size() > kTracePoints ? path.size() - kTracePoints : 0;
  const double z = d->site_xpos[3 * tool_site + 2] + 0.0015;
  const float trace_rgba[4] = {0.9f, 0.1f, 0.6f, 1.0f};
  for (size_t i = first + 1; i < path.size() && Room(scn); ++i) {
    const mjtNum a[3] = {path[i - 1][0], path[i - 1][1], z}, b[3] = {path[i][0], path[i][1], z};
    mjvGeom* g = scn->geoms + scn->ngeom;
    mjv_initGeom(g, mjGEOM_LINE, nullptr, nullptr, nullptr, trace_rgba);
    mjv_connector(g, mjGEOM_LINE, 3, a, b);
    g->category = mjCAT_DECOR;
    ++scn->ngeom;
  }
  // The controller's vectors at the cup, from the tool frame to world.
  const ContourStep& s = trial.last_step();
  if (!s.moving) return;
  const mjtNum* R = d->site_xmat + 9 * tool_site;
  const mjtNum* p = d->site_xpos + 3 * tool_site;
  const mjtNum origin[3] = {p[0], p[1], p[2] + 0.004};
  auto world = [&](const std::array<double, 2>& v, mjtNum out[3]) {
    const mjtNum local[3] = {v[0], v[1], 0};
    mju_mulMatVec3(out, R, local);
  };
  mjtNum along[3], corr[3], dir[3];
  world(s.along_edge, along);
  world(s.correction, corr);
  world(s.direction, dir);
  const float blue[4] = {0.1f, 0.3f, 1.0f, 1}, orange[4] = {1.0f, 0.5f, 0.0f, 1};
  const float green[4] = {0.0f, 0.8f, 0.2f, 1};
  Arrow(scn, origin, along, 0.02, blue);
  Arrow(scn, origin, corr, 0.02 * std::min(2.0, std::fabs(s.cf)), orange);
  Arrow(scn, origin, dir, 0.03, green);
}

OverlayValues CurrentOverlayValues(const ContourTrial& trial, const mjData* d) {
  OverlayValues v;
  v.t_s = d->time;
  v.phase = trial.phase();
  v.p_pa = trial.Pressures();
  // Mean and differentials as the law defines them, on the current pressures.
  const ContourStep now = ComputeContourStep(v.p_pa, trial.config().law);
  v.mean_pa = now.p_mean_pa;
  v.dpx_pa = now.dpx_pa;
  v.dpy_pa = now.dpy_pa;
  v.cf = trial.last_step().cf;
  v.iterations = trial.result().iterations;
  return v;
}

std::string OverlayValuesLine(const OverlayValues& v) {
  char buf[320];
  std::snprintf(buf, sizeof(buf),
                "overlay t=%.4f phase=%s p_pa=%.9g,%.9g,%.9g,%.9g mean_pa=%.9g dpx_pa=%.9g "
                "dpy_pa=%.9g cf=%.9g iterations=%d",
                v.t_s, PhaseName(v.phase), v.p_pa[0], v.p_pa[1], v.p_pa[2], v.p_pa[3], v.mean_pa,
                v.dpx_pa, v.dpy_pa, v.cf, v.iterations);
  return buf;
}

PressureFigures::PressureFigures() { Reset(); }

void PressureFigures::Reset() {
  for (mjvFigure* f : {&pressures_, &correction_}) {
    mjv_defaultFigure(f);
    f->flg_extend = 1;
    f->gridsize[0] = 6;  // five intervals: four of data, one for the legend
    f->figurergba[3] = 0.5f;
    f->linewidth = 2;
    std::snprintf(f->xformat, sizeof(f->xformat), "%%.1f");
    std::snprintf(f->xlabel, sizeof(f->xlabel), "time (s)");
  }
  // log10 of the vacuum; ticks at whole decades read as 1e0 .. 1e5 Pa.
  std::snprintf(pressures_.title, sizeof(pressures_.title), "chamber vacuum (Pa, log scale)");
  std::snprintf(pressures_.yformat, sizeof(pressures_.yformat), "1e%%.0f");
  pressures_.gridsize[1] = 6;
  pressures_.range[1][0] = 0;
  pressures_.range[1][1] = 5;
  pressures_.flg_extend = 0;  // fixed decades; Add() sets the time range
  const char* names[8] = {"P1 SE", "P2 NE", "P3 NW", "P4 SW", "mean", "P_n", "P_ref", "P_g"};
  for (int i = 0; i < 8; ++i) std::snprintf(pressures_.linename[i], 100, "%s", names[i]);
  const float colours[8][3] = {{1, 0.3f, 0.3f}, {0.3f, 1, 0.3f},    {0.4f, 0.6f, 1}, {1, 1, 0.3f},
                               {1, 1, 1},       {0.6f, 0.6f, 0.6f}, {0, 1, 1},       {1, 0, 1}};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) pressures_.linergb[i][k] = colours[i][k];
  std::snprintf(correction_.title, sizeof(correction_.title), "correction factor c_f");
  std::snprintf(correction_.yformat, sizeof(correction_.yformat), "%%.0f");
  correction_.gridsize[1] = 5;
  correction_.range[1][0] = -2;  // c_f spans [-beta, beta]; the axis grows past +-2 if needed
  correction_.range[1][1] = 2;
  std::snprintf(correction_.linename[0], 100, "c_f");
  correction_.linergb[0][0] = 1;
  correction_.linergb[0][1] = 0.5f;
  correction_.linergb[0][2] = 0;
  for (mjvFigure* f : {&pressures_, &correction_})
    for (int i = 0; i < mjMAXLINE; ++i) f->linedata[i][0] = 0, f->linepnt[i] = 0;
  last_t_ = -1;
}

void PressureFigures::Add(const OverlayValues& v, const ContourLawParams& law) {
  const double t = v.t_s;
  if (t <= last_t_) return;
  last_t_ = t;
  auto push = [](mjvFigure& f, int line, double x, double y) {
    int n = f.linepnt[line];
    if (n >= mjMAXLINEPNT) {  // scroll: drop the oldest half
      const int keep = mjMAXLINEPNT / 2;
      for (int i = 0; i < keep; ++i) {
        f.linedata[line][2 * i] = f.linedata[line][2 * (n - keep + i)];
        f.linedata[line][2 * i + 1] = f.linedata[line][2 * (n - keep + i) + 1];
      }
      n = keep;
    }
    f.linedata[line][2 * n] = static_cast<float>(x);
    f.linedata[line][2 * n + 1] = static_cast<float>(y);
    f.linepnt[line] = n + 1;
  };
  auto lg = [](double p) { return std::log10(std::max(1.0, p)); };
  for (int c = 0; c < 4; ++c) push(pressures_, c, t, lg(v.p_pa[c]));
  push(pressures_, 4, t, lg(v.mean_pa));
  push(pressures_, 5, t, lg(law.p_noise_pa));
  push(pressures_, 6, t, lg(law.p_ref_pa));
  push(pressures_, 7, t, lg(law.p_grasp_pa));
  push(correction_, 0, t, v.cf);
  // The time axis spans the data in four round intervals (0.5, 1, 2, 5, 10 ... s), so its ticks
  // read as round numbers; the vacuum axis keeps its decades.
  const double first = pressures_.linedata[0][0];
  double interval = 0.25;
  for (double k : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
    if (first + 4 * interval >= t) break;
    interval = k;
  }
  // One more interval on the right than the data fills: the legends sit there (top right),
  // over no data.
  for (mjvFigure* f : {&pressures_, &correction_}) {
    f->range[0][0] = static_cast<float>(interval * std::floor(first / interval));
    f->range[0][1] = f->range[0][0] + static_cast<float>(5 * interval);
    std::snprintf(f->xformat, sizeof(f->xformat), interval < 1 ? "%%.2g" : "%%.0f");
  }
}

namespace {
// Noise about ambient printed at 0 decimals reads "-0": values within half the last printed
// digit of zero print as 0.
double NoNegativeZero(double v, double half_digit = 0.5) {
  return std::fabs(v) < half_digit ? 0.0 : v;
}
}  // namespace

std::string TrialStatusText(const ContourTrial& trial, const OverlayValues& v, double rtf,
                            bool paused, double speed, const ChamberPressureDiagnostics* sensor) {
  const ChamberPressureSample* sample = sensor ? &sensor->last_sample() : nullptr;
  const TrialConfig& c = trial.config();
  // A chamber's opening can be mostly covered and still read ambient through a leak under the
  // lip: both are shown, so a covered share beside 0 Pa reads as "open through the leak".
  char sealed[200] = "covered / leak: (no sample yet)";
  if (sample && sample->time_s >= 0) {
    const double quarter = sensor->config().geometry.ChamberOpeningArea();
    int n = std::snprintf(sealed, sizeof(sealed), "covered %% / leak mm2 ");
    const char* names[4] = {"SE", "NE", "NW", "SW"};
    for (int k = 0; k < 4 && n > 0 && n < static_cast<int>(sizeof(sealed)); ++k) {
      n += std::snprintf(sealed + n, sizeof(sealed) - n, " %s %.0f/%.1f", names[k],
                         100 * sample->sealed_area_m2[k] / quarter, sample->leak_area_m2[k] * 1e6);
    }
  }
  char timing[96];
  if (rtf >= 0) {
    std::snprintf(timing, sizeof(timing), "speed x%.2f %s   real-time factor %.2f   (F1: help)",
                  speed, paused ? "PAUSED" : "", rtf);
  } else {
    std::snprintf(timing, sizeof(timing), "t = %.3f s", v.t_s);
  }
  const TrialResult& r = trial.result();
  char buf[1024];
  std::snprintf(buf, sizeof(buf),
                "P_ref %.0f Pa   beta %.2f   dL %.2f mm   seed %llu\n"
                "phase %s   outcome %s\n"
                "P1 %.0f  P2 %.0f  P3 %.0f  P4 %.0f Pa\n"
                "mean P %.1f Pa   dPx %.1f  dPy %.1f Pa   c_f %.2f\n"
                "iterations %d   swept %.0f deg   path points %zu\n"
                "%s\n"
                "%s",
                c.law.p_ref_pa, c.law.beta, c.law.step_mm, static_cast<unsigned long long>(c.seed),
                PhaseName(v.phase), OutcomeName(r.outcome), NoNegativeZero(v.p_pa[0]),
                NoNegativeZero(v.p_pa[1]), NoNegativeZero(v.p_pa[2]), NoNegativeZero(v.p_pa[3]),
                NoNegativeZero(v.mean_pa, 0.05), NoNegativeZero(v.dpx_pa, 0.05),
                NoNegativeZero(v.dpy_pa, 0.05), NoNegativeZero(v.cf, 0.005), v.iterations,
                trial.phase() == TrialPhase::kDone ? r.swept_deg : trial.swept_deg(),
                trial.path().size(), sealed, timing);
  return buf;
}

std::string ViewerHelpText() {
  return "space      pause / run\n"
         "right      one step (paused)\n"
         "- / =      slower / faster\n"
         "backspace  reset and restart the trial\n"
         "P / O      P_ref x1.25 / /1.25\n"
         "B / V      beta +0.5 / -0.5\n"
         "L / K      step +0.5 / -0.5 mm\n"
         "R          restart the trial with the new parameters\n"
         "T          camera: track the cup / free\n"
         "F1         this help\n"
         "mouse      left: rotate, right: move, wheel: zoom\n"
         "Esc        quit";
}

}  // namespace ssc
