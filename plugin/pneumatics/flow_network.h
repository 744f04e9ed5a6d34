// Lumped flow network of the Smart Suction Cup: four chambers, one shared vacuum port, a pump.
//
// Pure C++: no MuJoCo types. Pressures are vacuum relative to ambient in Pa (positive = vacuum).
// Flows are volumetric at ambient density, m^3/s. Areas are in m^2 (inputs) unless named _mm2.
//
// Network (orifice law q = Cd * A * sqrt(2 |dp| / rho), with a laminar blend near dp = 0):
//
//   ambient --leak_i--> chamber i --port--> shared port --pump--> exhaust
//                         |   ^
//                 neighbour restriction (across the cup interior)
//
// The pump follows a linear characteristic q = Q_max (1 - p_port / P_max): free flow Q_max at
// zero vacuum, no flow at its blocked vacuum P_max.
//
// What the sensors read: each chamber's pressure sensor sits at a tap near the lip. Air rushing
// in through an uncovered part of a chamber's opening passes the tap as a jet, and the tap
// recovers most of that jet's dynamic pressure, so an open chamber reads near ambient even while
// the cup interior is at vacuum (`tap_recovery`). This is the structure that lets the model give
// both the steep rise of the mean pressure with coverage (the uncovered opening is the dominant
// restriction) and the large side-to-side differential the real cup shows (the over-the-edge side
// reads near zero, the covered side near twice the mean). A purely resistive network with a
// constant-flow pump cannot do both: see docs/pneumatics.md.
#ifndef SSC_PLUGIN_PNEUMATICS_FLOW_NETWORK_H_
#define SSC_PLUGIN_PNEUMATICS_FLOW_NETWORK_H_

#include <array>
#include <string>

namespace ssc {

inline constexpr int kNumChambers = 4;

struct PneumaticParams {
  double air_density_kg_m3 = 1.2;        // ambient air density, (0.1, 10]
  double discharge_coeff = 0.6;          // orifice discharge coefficient Cd, (0, 1]
  double pump_max_vacuum_pa = 40000.0;   // pump vacuum at zero flow, (0, 100000)
  double pump_free_flow_m3_s = 2.15e-4;  // pump flow at zero vacuum (12.9 L/min), > 0
  double port_area_m2 = 22.0e-6;         // each chamber -> shared port restriction, > 0
  double neighbour_area_m2 = 0.5e-6;     // restriction between neighbouring chambers, >= 0
  double tap_recovery = 0.97;            // fraction of an inflow jet's dynamic pressure the tap
                                         // recovers when the jet fills the chamber, [0, 1]
  double jet_area_m2 = 7.0e-6;           // leak area at which the inflow jet fills the
                                         // chamber: recovery grows linearly with the leak area
                                         // up to tap_recovery at this area, > 0
  double laminar_pa = 0.01;              // below this |dp| flow blends to laminar (keeps the
                                         // Newton Jacobian finite at dp = 0), > 0

  // Empty when valid; otherwise names the field, its value and the valid range.
  std::string Validate() const;
};

// Solution of the network for given leak areas.
struct FlowSolution {
  std::array<double, kNumChambers> chamber_pa{};      // static vacuum in each chamber
  std::array<double, kNumChambers> tap_pa{};          // what each chamber's sensor tap reads
  double port_pa = 0.0;                               // vacuum at the shared port
  std::array<double, kNumChambers> leak_flow_m3_s{};  // ambient -> chamber i
  std::array<double, kNumChambers> port_flow_m3_s{};  // chamber i -> port
  double pump_flow_m3_s = 0.0;
  int iterations = 0;
  bool converged = false;
};

// Solves the network by damped Newton iteration. `warm_start` (may be null) holds a previous
// solution's {chamber_pa[0..3], port_pa} to start from; results are independent of it to the
// solver tolerance. `jet_area_m2` (may be null: all of the leak) is the part of each chamber's
// leak that enters as a jet past the sensor tap; only that part drives the tap recovery. Never
// allocates.
FlowSolution SolveFlowNetwork(const PneumaticParams& params,
                              const std::array<double, kNumChambers>& leak_area_m2,
                              const double* warm_start = nullptr,
                              const std::array<double, kNumChambers>* jet_area_m2 = nullptr);

// Orifice flow for a pressure difference dp (Pa) through area (m^2): signed, m^3/s.
double OrificeFlow(const PneumaticParams& params, double area_m2, double dp_pa);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_FLOW_NETWORK_H_
