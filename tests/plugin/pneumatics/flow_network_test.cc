// The pneumatic model alone: no MuJoCo.
#include "plugin/pneumatics/flow_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "plugin/pneumatics/cup_geometry.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Static tap pressures with a straight edge `offset_m` inside the cup centre.
FlowSolution EdgeSolution(double offset_m, double normal_rad = kPi,
                          const PneumaticParams& params = {}, const CupGeometry& geo = {}) {
  return SolveProbe(geo, params, ProbeStraightEdge(geo, offset_m, normal_rad));
}

double Mean(const std::array<double, 4>& p) { return 0.25 * (p[0] + p[1] + p[2] + p[3]); }

// ---- Cases solved by hand (closed forms of the network; independent of the fitted targets) ----
//
// Orifice constant k = Cd sqrt(2 / rho): q = k A sqrt(dp). With n chambers each leaking through
// area a, no flow between chambers (equal pressures, or no neighbour restriction) and the rest
// sealed, each leaking chamber at vacuum p passes k a sqrt(p) to the port through the port
// restriction, so port - p = (a / A_port)^2 p, and the pump curve closes the balance:
//   n k a sqrt(p) = Q_max (1 - p (1 + (a / A_port)^2) / P_max),
// a quadratic in s = sqrt(p). The laminar blend (c Pa) changes an orifice flow by a relative
// c / (2 dp), so the hand cases run with c = 1e-9 Pa: the smallest drop here (1e-4 Pa, the
// opposite chamber below the port) is then off by 5e-6; 1e-5 relative covers it (the solver's
// residual tolerance is 1e-12 of the pump flow).
constexpr double kHandTolerance = 1e-5;

// The default network with a sharp orifice law (see above).
PneumaticParams Sharp() {
  PneumaticParams p;
  p.laminar_pa = 1e-9;
  return p;
}

double OrificeK(const PneumaticParams& p) {
  return p.discharge_coeff * std::sqrt(2.0 / p.air_density_kg_m3);
}

// Vacuum of each of n chambers leaking through area a (closed form above).
double ClosedFormLeakVacuum(const PneumaticParams& p, int n, double a) {
  const double ratio = a / p.port_area_m2;
  const double qa = p.pump_free_flow_m3_s * (1 + ratio * ratio) / p.pump_max_vacuum_pa;
  const double qb = n * OrificeK(p) * a;
  const double s = (-qb + std::sqrt(qb * qb + 4 * qa * p.pump_free_flow_m3_s)) / (2 * qa);
  return s * s;
}

// What the tap of a chamber at vacuum p with leak a reads: the jet's recovered dynamic pressure
// grows linearly with the leak area up to the jet area.
double ClosedFormTap(const PneumaticParams& p, double chamber_pa, double a) {
  return chamber_pa * (1 - p.tap_recovery * std::min(1.0, a / p.jet_area_m2));
}

TEST(FlowNetworkTest, SealedCupReachesThePumpsMaximumVacuum) {
  // No leak: no flow anywhere, so the pump sits at its blocked vacuum and every chamber with it.
  PneumaticParams other =
      Sharp();  // a different pump, so the answer is not the default by coincidence
  other.pump_max_vacuum_pa = 61000;
  other.pump_free_flow_m3_s = 3.1e-4;
  for (const PneumaticParams& p : {Sharp(), other}) {
    const FlowSolution s = SolveFlowNetwork(p, {0, 0, 0, 0});
    ASSERT_TRUE(s.converged);
    EXPECT_NEAR(s.port_pa, p.pump_max_vacuum_pa, 1e-6 * p.pump_max_vacuum_pa);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(s.chamber_pa[i], p.pump_max_vacuum_pa, 1e-6 * p.pump_max_vacuum_pa);
      EXPECT_NEAR(s.tap_pa[i], p.pump_max_vacuum_pa, 1e-6 * p.pump_max_vacuum_pa);
    }
    EXPECT_NEAR(s.pump_flow_m3_s, 0.0, 1e-9 * p.pump_free_flow_m3_s);
  }
}

TEST(FlowNetworkTest, FourEqualLeaksNeedNoFlowBetweenChambers) {
  // Equal leaks: all chambers at one pressure, nothing crosses the neighbour restrictions, so
  // the answer is the closed form with n = 4 whatever the neighbour area. One leak below the jet
  // area (partial recovery at the tap) and one above it (full recovery).
  for (double a : {1.0e-6, 20.0e-6}) {
    const double expected = ClosedFormLeakVacuum(Sharp(), 4, a);
    for (double nbr : {0.0, 0.5e-6, 5.0e-6}) {
      PneumaticParams p = Sharp();
      p.neighbour_area_m2 = nbr;
      const FlowSolution s = SolveFlowNetwork(p, {a, a, a, a});
      ASSERT_TRUE(s.converged);
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(s.chamber_pa[i], expected, kHandTolerance * expected) << a << " " << nbr;
        EXPECT_NEAR(s.tap_pa[i], ClosedFormTap(p, expected, a), kHandTolerance * expected);
        // Each chamber passes exactly its own leak to the port: no neighbour flow.
        EXPECT_NEAR(s.port_flow_m3_s[i], s.leak_flow_m3_s[i], 1e-9 * p.pump_free_flow_m3_s);
      }
      const double ratio = a / p.port_area_m2;
      EXPECT_NEAR(s.port_pa, expected * (1 + ratio * ratio), kHandTolerance * expected);
      EXPECT_NEAR(s.pump_flow_m3_s, 4 * OrificeK(p) * a * std::sqrt(expected),
                  kHandTolerance * s.pump_flow_m3_s);
    }
  }
}

TEST(FlowNetworkTest, SingleLeakBalancesThePumpCurveAndItsOrifice) {
  // One chamber leaks, the others are sealed and (no neighbour restriction) carry no flow, so
  // they sit at the port vacuum; the leaking one follows the closed form with n = 1.
  PneumaticParams p = Sharp();
  p.neighbour_area_m2 = 0;
  for (double a : {0.3e-6, 3.5e-6, 12.0e-6}) {
    std::array<double, 4> leak{};
    leak[2] = a;
    const FlowSolution s = SolveFlowNetwork(p, leak);
    ASSERT_TRUE(s.converged);
    const double pv = ClosedFormLeakVacuum(p, 1, a);
    const double ratio = a / p.port_area_m2;
    const double port = pv * (1 + ratio * ratio);
    EXPECT_NEAR(s.chamber_pa[2], pv, kHandTolerance * pv) << a;
    EXPECT_NEAR(s.tap_pa[2], ClosedFormTap(p, pv, a), kHandTolerance * pv) << a;
    EXPECT_NEAR(s.port_pa, port, kHandTolerance * pv) << a;
    for (int i : {0, 1, 3}) {
      EXPECT_NEAR(s.chamber_pa[i], port, kHandTolerance * pv) << a;
      EXPECT_NEAR(s.tap_pa[i], port, kHandTolerance * pv) << a;  // no leak: no jet to recover
    }
    // The pump curve at the port vacuum carries the orifice flow of the leak.
    EXPECT_NEAR(s.pump_flow_m3_s, p.pump_free_flow_m3_s * (1 - port / p.pump_max_vacuum_pa),
                kHandTolerance * s.pump_flow_m3_s);
    EXPECT_NEAR(s.pump_flow_m3_s, OrificeK(p) * a * std::sqrt(pv),
                kHandTolerance * s.pump_flow_m3_s);
  }
}

TEST(FlowNetworkTest, NeighbourRestrictionFeedsTheLeakingChamberFromItsNeighbours) {
  // One chamber open, the others sealed: air crosses from the open chamber into each sealed
  // neighbour (lower vacuum to higher) and on to the port or the opposite chamber. The sealed
  // neighbour's balance A_port sqrt(port - p_n) = A_nbr (sqrt(p_n - p_open) - sqrt(p_opp - p_n))
  // puts it below the port by (A_nbr / A_port)^2 (sqrt(p_n - p_open) - sqrt(p_opp - p_n))^2;
  // the opposite chamber, fed by both neighbours, by (A_nbr / A_port)^2 (2 sqrt(p_opp - p_n))^2.
  const PneumaticParams p = Sharp();
  const FlowSolution s = SolveFlowNetwork(p, {20e-6, 0, 0, 0});
  ASSERT_TRUE(s.converged);
  const double ratio2 = std::pow(p.neighbour_area_m2 / p.port_area_m2, 2);
  EXPECT_LT(s.chamber_pa[0], s.chamber_pa[1]);
  EXPECT_NEAR(s.chamber_pa[1], s.chamber_pa[3], 1e-9 * s.port_pa);  // mirror symmetry
  EXPECT_LT(s.chamber_pa[1], s.chamber_pa[2]);
  EXPECT_LT(s.chamber_pa[2], s.port_pa);
  const double s_in = std::sqrt(s.chamber_pa[1] - s.chamber_pa[0]);
  const double s_on = std::sqrt(s.chamber_pa[2] - s.chamber_pa[1]);
  const double deficit = ratio2 * std::pow(s_in - s_on, 2);
  EXPECT_NEAR(s.port_pa - s.chamber_pa[1], deficit, 1e-3 * deficit);
  EXPECT_GT(deficit, 0.01);  // the neighbour flow is visible at all (0.07 Pa)
  const double opposite = ratio2 * 4 * s_on * s_on;
  EXPECT_NEAR(s.port_pa - s.chamber_pa[2], opposite, 1e-2 * opposite);
}

TEST(FlowNetworkTest, TapRecoveryGrowsLinearlyWithTheLeakUpToTheJetArea) {
  const PneumaticParams p;
  for (double fill : {0.0, 0.25, 0.5, 1.0, 2.0}) {
    std::array<double, 4> leak{};
    leak[1] = fill * p.jet_area_m2;
    const FlowSolution s = SolveFlowNetwork(p, leak);
    ASSERT_TRUE(s.converged);
    EXPECT_NEAR(s.tap_pa[1], s.chamber_pa[1] * (1 - p.tap_recovery * std::min(1.0, fill)),
                1e-9 * s.chamber_pa[1])
        << "leak " << fill << " jet areas";
  }
}

// ---- The cup in air and on a plate, two-sided ----

TEST(FlowNetworkTest, OpenCupReadsTheClosedFormNearAmbient) {
  // In air every quadrant is wide open (its whole opening, above the jet area, plus the lip's
  // roughness gap, which the leak model counts all round): four equal leaks, full tap recovery.
  const CupGeometry geo;
  const PneumaticParams params = Sharp();
  const FlowSolution s = EdgeSolution(-20e-3, kPi, params);
  ASSERT_TRUE(s.converged);
  const double a =
      geo.ChamberOpeningArea() + 0.5 * kPi * geo.opening_radius_m * geo.lip_roughness_gap_m;
  const double pv = ClosedFormLeakVacuum(params, 4, a);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(s.chamber_pa[i], pv, kHandTolerance * pv);
    EXPECT_NEAR(s.tap_pa[i], pv * (1 - params.tap_recovery), kHandTolerance * pv);
  }
}

TEST(FlowNetworkTest, SealedCupOnAPlateReadsTheClosedFormOfItsLipRoughness) {
  // On a plate every lip segment lies on the surface: each quadrant leaks through a quarter of
  // the lip times the roughness gap. That air enters as a sheet, not a jet: the taps read the
  // chamber vacuum.
  const CupGeometry geo;
  const PneumaticParams params = Sharp();
  const FlowSolution s = EdgeSolution(20e-3, kPi, params);
  ASSERT_TRUE(s.converged);
  const double a = 0.5 * kPi * geo.opening_radius_m * geo.lip_roughness_gap_m;
  const double pv = ClosedFormLeakVacuum(params, 4, a);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(s.chamber_pa[i], pv, kHandTolerance * pv);
    EXPECT_NEAR(s.tap_pa[i], pv, kHandTolerance * pv);
  }
}

// ---- The defaults give the readings documented in docs/testing.md ----
//
// The closed forms above hold for any parameters; this pins the documented defaults. Each
// tolerance is half a unit of the documented last digit (the network is exact to 1e-9), and each
// physical parameter moved by 20 % changes at least one reading by many tolerances (measured:
// docs/testing.md). Leak areas from the documented lip: 5.5 mm radius, 18 um roughness gap.
TEST(FlowNetworkTest, DefaultsGiveTheDocumentedReadings) {
  const PneumaticParams p;
  const CupGeometry geo;
  const double rough = 0.5 * kPi * geo.opening_radius_m * geo.lip_roughness_gap_m;
  const double quad = geo.ChamberOpeningArea();
  const FlowSolution plate = SolveFlowNetwork(p, {rough, rough, rough, rough});
  const FlowSolution air = SolveFlowNetwork(p, {quad, quad, quad, quad});
  const FlowSolution one_open = SolveFlowNetwork(p, {quad, rough, rough, rough});
  const FlowSolution half_jet = SolveFlowNetwork(p, {0.5 * p.jet_area_m2, rough, rough, rough});
  EXPECT_NEAR(Mean(plate.tap_pa), 25091, 0.5);     // on a plate
  EXPECT_NEAR(Mean(air.tap_pa), 0.2560, 0.00005);  // in air
  EXPECT_NEAR(one_open.tap_pa[0], 3.82, 0.005);    // one quadrant open: its tap
  EXPECT_NEAR(one_open.tap_pa[1], 257.55, 0.005);  // ... and its sealed neighbours
  EXPECT_NEAR(half_jet.tap_pa[0], 2032.8, 0.05);   // half a jet area open: its tap
  EXPECT_NEAR(half_jet.tap_pa[2], 3951.4, 0.05);   // ... and the opposite chamber
}

TEST(FlowNetworkTest, MeanPressureRisesMonotonicallyWithCoverage) {
  double previous = -1.0;
  for (double d_mm = -6.0; d_mm <= 6.0; d_mm += 0.1) {
    const FlowSolution s = EdgeSolution(d_mm * 1e-3);
    ASSERT_TRUE(s.converged) << d_mm;
    const double pbar = Mean(s.tap_pa);
    EXPECT_GE(pbar, previous - 1e-9) << "at offset " << d_mm << " mm";
    previous = pbar;
  }
}

TEST(FlowNetworkTest, MeanPressureFallsMonotonicallyWithHoverGap) {
  // Cup hovering over a plate: no distance at which the state jumps.
  const CupGeometry geo;
  double previous = 1e9;
  for (double gap_um = 0; gap_um <= 6000; gap_um += 25) {
    const FlowSolution s = SolveProbe(geo, PneumaticParams{}, ProbeFlatPlate(geo, gap_um * 1e-6));
    ASSERT_TRUE(s.converged);
    const double pbar = Mean(s.tap_pa);
    EXPECT_LE(pbar, previous + 1e-9) << "at gap " << gap_um << " um";
    if (gap_um > 0) {
      EXPECT_GT(pbar, 0.2 * previous) << "jump at gap " << gap_um << " um";
    }
    previous = pbar;
  }
  // At 2 mm each quadrant leaks through its lip curtain (a quarter of the lip times the gap
  // plus the roughness); the 2 mm layer over the opening is open enough to count as a jet area
  // above jet_area: four equal leaks, full recovery, the laminar blend's error c / p below 1 %.
  const PneumaticParams params;
  const double curtain = 0.5 * kPi * geo.opening_radius_m * (2e-3 + geo.lip_roughness_gap_m);
  const double closed = ClosedFormLeakVacuum(params, 4, curtain) * (1 - params.tap_recovery);
  EXPECT_NEAR(Mean(SolveProbe(geo, params, ProbeFlatPlate(geo, 2e-3)).tap_pa), closed,
              0.01 * closed);
}

TEST(FlowNetworkTest, SymmetricUnderChamberRotation) {
  const std::array<double, 4> leak = {3e-6, 12e-6, 0.2e-6, 7e-6};
  const FlowSolution base = SolveFlowNetwork(PneumaticParams{}, leak);
  for (int shift = 1; shift < 4; ++shift) {
    std::array<double, 4> rotated;
    for (int i = 0; i < 4; ++i) rotated[(i + shift) % 4] = leak[i];
    const FlowSolution s = SolveFlowNetwork(PneumaticParams{}, rotated);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(s.tap_pa[(i + shift) % 4], base.tap_pa[i], 1e-6 * (1 + base.tap_pa[i]));
    }
    EXPECT_NEAR(s.port_pa, base.port_pa, 1e-6 * base.port_pa);
  }
  // Mirror symmetry of the ring (1 2 3 4 -> 4 3 2 1).
  const std::array<double, 4> mirrored = {leak[3], leak[2], leak[1], leak[0]};
  const FlowSolution m = SolveFlowNetwork(PneumaticParams{}, mirrored);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(m.tap_pa[3 - i], base.tap_pa[i], 1e-6 * (1 + base.tap_pa[i]));
}

TEST(FlowNetworkTest, MassBalanceHoldsAtEveryNode) {
  const PneumaticParams params;
  const std::array<double, 4> leak = {1e-6, 15e-6, 4e-6, 0.05e-6};
  const FlowSolution s = SolveFlowNetwork(params, leak);
  ASSERT_TRUE(s.converged);
  double into_port = 0, from_ambient = 0;
  for (int i = 0; i < 4; ++i) {
    const int prev = (i + 3) % 4, next = (i + 1) % 4;
    const double from_neighbours =
        OrificeFlow(params, params.neighbour_area_m2, s.chamber_pa[i] - s.chamber_pa[prev]) +
        OrificeFlow(params, params.neighbour_area_m2, s.chamber_pa[i] - s.chamber_pa[next]);
    EXPECT_NEAR(s.leak_flow_m3_s[i] + from_neighbours, s.port_flow_m3_s[i],
                1e-9 * params.pump_free_flow_m3_s);
    into_port += s.port_flow_m3_s[i];
    from_ambient += s.leak_flow_m3_s[i];
  }
  EXPECT_NEAR(into_port, s.pump_flow_m3_s, 1e-9 * params.pump_free_flow_m3_s);
  EXPECT_NEAR(from_ambient, s.pump_flow_m3_s, 1e-9 * params.pump_free_flow_m3_s);
}

TEST(FlowNetworkTest, WarmStartDoesNotChangeTheAnswer) {
  const std::array<double, 4> leak = {2e-6, 9e-6, 9e-6, 2e-6};
  const FlowSolution cold = SolveFlowNetwork(PneumaticParams{}, leak);
  const double warm[5] = {30000, 1, 5000, 7, 12000};
  const FlowSolution hot = SolveFlowNetwork(PneumaticParams{}, leak, warm);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(hot.tap_pa[i], cold.tap_pa[i], 1e-6 * (1 + cold.tap_pa[i]));
}

// The published disk results give points of the static curve mean P vs how far the cup centre
// sits inside a straight edge (the controller settles where P = P_ref).
double OffsetForMean(double target_pa) {
  double lo = -6e-3, hi = 6e-3;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Mean(EdgeSolution(mid).tap_pa) < target_pa ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(FlowNetworkTest, DefaultsReproduceThePublishedStaticCurve) {
  EXPECT_NEAR(OffsetForMean(40) * 1e3, 0.7, 0.3);
  EXPECT_NEAR(OffsetForMean(100) * 1e3, 2.5, 0.3);
  EXPECT_NEAR(OffsetForMean(200) * 1e3, 3.2, 0.3);
}

TEST(FlowNetworkTest, DefaultsReproduceThePublishedDifferential) {
  // Settled near mean P = 100 Pa on a sharp edge: |(dPx, dPy)| about 200 Pa, the over-the-edge
  // side near zero, the covered side near twice the mean.
  const FlowSolution s = EdgeSolution(OffsetForMean(100));
  const auto& p = s.tap_pa;  // edge normal points north: chambers 2, 3 hang over the edge
  const double north = 0.5 * (p[1] + p[2]), south = 0.5 * (p[0] + p[3]);
  EXPECT_NEAR(south - north, 200.0, 30.0);
  EXPECT_LT(north, 15.0);
  EXPECT_NEAR(south, 2 * Mean(p), 20.0);
}

// |(dPx, dPy)| where the mean is 100 Pa over an edge rounded with radius rho (edge normal north).
double DifferentialAtMean100(double rho_m) {
  const CupGeometry geo;
  auto taps = [&](double offset) {
    return SolveProbe(geo, PneumaticParams{}, ProbeRoundedEdge(geo, offset, kPi, rho_m)).tap_pa;
  };
  double lo = -30e-3, hi = 8e-3;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Mean(taps(mid)) < 100.0 ? lo : hi) = mid;
  }
  const auto p = taps(0.5 * (lo + hi));
  return 0.5 * (p[0] + p[3]) - 0.5 * (p[1] + p[2]);
}

TEST(FlowNetworkTest, DifferentialOverARoundedEdgeFallsAsTheRadiusGrows) {
  // The published cross-sections of the fillet bar: 0, 4.7, 10.4, 14.5, 16 mm.
  const double sharp = DifferentialAtMean100(0.0);
  EXPECT_GT(sharp, 150.0);
  double previous = sharp;
  for (double rho_mm : {4.7, 10.4, 14.5, 16.0}) {
    const double dp = DifferentialAtMean100(rho_mm * 1e-3);
    EXPECT_LE(dp, previous + 0.1) << "fillet radius " << rho_mm << " mm";
    previous = dp;
  }
  EXPECT_LT(previous, 0.8 * sharp);
}

TEST(FlowNetworkTest, ValidateNamesTheBadField) {
  PneumaticParams p;
  p.port_area_m2 = -1;
  EXPECT_NE(p.Validate().find("port_area"), std::string::npos);
  p = PneumaticParams{};
  p.tap_recovery = std::nan("");
  EXPECT_NE(p.Validate().find("tap_recovery"), std::string::npos);
  EXPECT_EQ(PneumaticParams{}.Validate(), "");
}

}  // namespace
}  // namespace ssc
