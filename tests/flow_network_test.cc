// The pneumatic model alone: no MuJoCo.
#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "plugin/pneumatics/cup_geometry.h"
#include "plugin/pneumatics/flow_network.h"

namespace ssc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLipRadius = 5.5e-3;
constexpr int kLipSegments = 16;

// Static tap pressures with a straight edge `offset_m` inside the cup centre.
FlowSolution EdgeSolution(double offset_m, double normal_rad = kPi,
                          const PneumaticParams& params = {}, const CupGeometry& geo = {}) {
  const EdgeProbe probe = ProbeStraightEdge(geo, offset_m, normal_rad, kLipRadius, kLipSegments,
                                            kPi / kLipSegments);
  const auto leak = LeakAreas(geo, probe.sealed_area_m2, probe.segments.data(), probe.n_segments);
  return SolveFlowNetwork(params, leak);
}

double Mean(const std::array<double, 4>& p) { return 0.25 * (p[0] + p[1] + p[2] + p[3]); }

TEST(FlowNetworkTest, OpenCupReadsNearAmbient) {
  const FlowSolution s = EdgeSolution(-20e-3);
  ASSERT_TRUE(s.converged);
  for (double p : s.tap_pa) EXPECT_LT(p, 5.0);
  EXPECT_LT(Mean(s.tap_pa), 5.0);
}

TEST(FlowNetworkTest, SealedCupExceedsGraspThresholdInEveryChamber) {
  const FlowSolution s = EdgeSolution(20e-3);
  ASSERT_TRUE(s.converged);
  for (double p : s.tap_pa) EXPECT_GT(p, 10000.0);
  // And never beyond what the pump can pull.
  for (double p : s.chamber_pa) EXPECT_LE(p, PneumaticParams{}.pump_max_vacuum_pa);
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
  // Cup hovering over a plate: every lip segment at the same gap, opening covered while the
  // plate is within the seal distance.
  const CupGeometry geo;
  double previous = 1e9;
  for (double gap_um = 0; gap_um <= 2000; gap_um += 25) {
    const double gap = gap_um * 1e-6;
    std::array<LipSegmentState, kLipSegments> segs;
    for (int i = 0; i < kLipSegments; ++i) {
      segs[i].chamber = ChamberOfAngle(2 * kPi * (i + 0.5) / kLipSegments);
      segs[i].arc_m = 2 * kPi * kLipRadius / kLipSegments;
      segs[i].in_contact = gap == 0;
      segs[i].gap_m = gap;
    }
    std::array<double, 4> sealed{};
    if (gap <= geo.seal_distance_m) sealed.fill(geo.ChamberOpeningArea());
    const auto leak = LeakAreas(geo, sealed, segs.data(), kLipSegments);
    const FlowSolution s = SolveFlowNetwork(PneumaticParams{}, leak);
    ASSERT_TRUE(s.converged);
    const double pbar = Mean(s.tap_pa);
    EXPECT_LE(pbar, previous + 1e-9) << "at gap " << gap_um << " um";
    previous = pbar;
  }
  EXPECT_LT(previous, 5.0);  // far above the plate: open
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
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.tap_pa[3 - i], base.tap_pa[i], 1e-6 * (1 + base.tap_pa[i]));
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
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hot.tap_pa[i], cold.tap_pa[i], 1e-6 * (1 + cold.tap_pa[i]));
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
