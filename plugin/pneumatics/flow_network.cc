#include "plugin/pneumatics/flow_network.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ssc {
namespace {

constexpr int kUnknowns = kNumChambers + 1;  // chamber vacuums, then the port vacuum

// Signed square root with a laminar blend: x / sqrt(|x| + c). Odd, smooth, slope 1/sqrt(c) at 0.
double Ssqrt(double x, double c) { return x / std::sqrt(std::fabs(x) + c); }
double SsqrtSlope(double x, double c) {
  const double s = std::fabs(x) + c;
  return (s - 0.5 * std::fabs(x)) / (s * std::sqrt(s));
}

std::string RangeError(const char* field, double value, const char* range) {
  std::ostringstream os;
  os << field << " = " << value << " is out of range " << range;
  return os.str();
}

// Solves the dense 5x5 system J dx = -r in place (Gaussian elimination, partial pivoting).
bool SolveLinear5(double a[kUnknowns][kUnknowns], double b[kUnknowns]) {
  for (int col = 0; col < kUnknowns; ++col) {
    int pivot = col;
    for (int row = col + 1; row < kUnknowns; ++row) {
      if (std::fabs(a[row][col]) > std::fabs(a[pivot][col])) pivot = row;
    }
    if (std::fabs(a[pivot][col]) < 1e-300) return false;
    if (pivot != col) {
      for (int k = 0; k < kUnknowns; ++k) std::swap(a[col][k], a[pivot][k]);
      std::swap(b[col], b[pivot]);
    }
    for (int row = col + 1; row < kUnknowns; ++row) {
      const double f = a[row][col] / a[col][col];
      for (int k = col; k < kUnknowns; ++k) a[row][k] -= f * a[col][k];
      b[row] -= f * b[col];
    }
  }
  for (int row = kUnknowns - 1; row >= 0; --row) {
    double s = b[row];
    for (int k = row + 1; k < kUnknowns; ++k) s -= a[row][k] * b[k];
    b[row] = s / a[row][row];
  }
  return true;
}

}  // namespace

std::string PneumaticParams::Validate() const {
  auto bad = [](double v) { return !std::isfinite(v); };
  if (bad(air_density_kg_m3) || air_density_kg_m3 <= 0.1 || air_density_kg_m3 > 10)
    return RangeError("air_density_kg_m3", air_density_kg_m3, "(0.1, 10]");
  if (bad(discharge_coeff) || discharge_coeff <= 0 || discharge_coeff > 1)
    return RangeError("discharge_coeff", discharge_coeff, "(0, 1]");
  if (bad(pump_max_vacuum_pa) || pump_max_vacuum_pa <= 0 || pump_max_vacuum_pa >= 100000)
    return RangeError("pump_max_vacuum_pa", pump_max_vacuum_pa, "(0, 100000) Pa");
  if (bad(pump_free_flow_m3_s) || pump_free_flow_m3_s <= 0 || pump_free_flow_m3_s > 1)
    return RangeError("pump_free_flow", pump_free_flow_m3_s, "(0, 1] m^3/s");
  if (bad(port_area_m2) || port_area_m2 <= 0 || port_area_m2 > 1e-2)
    return RangeError("port_area", port_area_m2, "(0, 0.01] m^2");
  if (bad(neighbour_area_m2) || neighbour_area_m2 < 0 || neighbour_area_m2 > 1e-2)
    return RangeError("neighbour_area", neighbour_area_m2, "[0, 0.01] m^2");
  if (bad(tap_recovery) || tap_recovery < 0 || tap_recovery > 1)
    return RangeError("tap_recovery", tap_recovery, "[0, 1]");
  if (bad(jet_area_m2) || jet_area_m2 <= 0 || jet_area_m2 > 1e-2)
    return RangeError("jet_area", jet_area_m2, "(0, 0.01] m^2");
  if (bad(laminar_pa) || laminar_pa <= 0 || laminar_pa > 100)
    return RangeError("laminar_pa", laminar_pa, "(0, 100] Pa");
  return "";
}

double OrificeFlow(const PneumaticParams& params, double area_m2, double dp_pa) {
  const double k = params.discharge_coeff * std::sqrt(2.0 / params.air_density_kg_m3);
  return k * area_m2 * Ssqrt(dp_pa, params.laminar_pa);
}

FlowSolution SolveFlowNetwork(const PneumaticParams& params,
                              const std::array<double, kNumChambers>& leak_area_m2,
                              const double* warm_start,
                              const std::array<double, kNumChambers>* jet_area_m2) {
  const double k = params.discharge_coeff * std::sqrt(2.0 / params.air_density_kg_m3);
  const double c = params.laminar_pa;
  const double p_max = params.pump_max_vacuum_pa;
  const double q_max = params.pump_free_flow_m3_s;
  const double a_port = params.port_area_m2;
  const double a_nbr = params.neighbour_area_m2;

  double x[kUnknowns];
  if (warm_start != nullptr) {
    for (int i = 0; i < kUnknowns; ++i) x[i] = warm_start[i];
  } else {
    for (int i = 0; i < kUnknowns; ++i) x[i] = 0.0;
  }
  for (int i = 0; i < kUnknowns; ++i) {
    if (!std::isfinite(x[i])) x[i] = 0.0;
    x[i] = std::clamp(x[i], 0.0, p_max);
  }

  // Residuals: net volumetric inflow at each node (m^3/s), scaled by flow_scale for conditioning.
  const double flow_scale = 1.0 / q_max;
  auto residual = [&](const double* p, double* r, double jac[kUnknowns][kUnknowns]) {
    for (int i = 0; i < kUnknowns; ++i) {
      r[i] = 0.0;
      if (jac)
        for (int j = 0; j < kUnknowns; ++j) jac[i][j] = 0.0;
    }
    const double port = p[kNumChambers];
    for (int i = 0; i < kNumChambers; ++i) {
      // Ambient -> chamber i (inflow when the chamber is at vacuum).
      const double leak_k = k * leak_area_m2[i];
      r[i] += leak_k * Ssqrt(p[i], c);
      if (jac) jac[i][i] += leak_k * SsqrtSlope(p[i], c);
      // Chamber i -> port: leaves chamber i, enters the port node.
      const double q_port = k * a_port * Ssqrt(port - p[i], c);
      const double dq_port = k * a_port * SsqrtSlope(port - p[i], c);
      r[i] -= q_port;
      r[kNumChambers] += q_port;
      if (jac) {
        jac[i][i] += dq_port;
        jac[i][kNumChambers] -= dq_port;
        jac[kNumChambers][kNumChambers] += dq_port;
        jac[kNumChambers][i] -= dq_port;
      }
      // Neighbours i-1 and i+1 (the quadrants form a ring): inflow into i from j.
      for (int step : {-1, 1}) {
        const int j = (i + step + kNumChambers) % kNumChambers;
        const double q = k * a_nbr * Ssqrt(p[i] - p[j], c);
        const double dq = k * a_nbr * SsqrtSlope(p[i] - p[j], c);
        r[i] += q;
        if (jac) {
          jac[i][i] += dq;
          jac[i][j] -= dq;
        }
      }
    }
    // Port -> pump.
    r[kNumChambers] -= q_max * (1.0 - port / p_max);
    if (jac) jac[kNumChambers][kNumChambers] += q_max / p_max;
    for (int i = 0; i < kUnknowns; ++i) {
      r[i] *= flow_scale;
      if (jac)
        for (int j = 0; j < kUnknowns; ++j) jac[i][j] *= flow_scale;
    }
  };

  FlowSolution sol;
  double r[kUnknowns];
  double jac[kUnknowns][kUnknowns];
  auto norm = [](const double* v) {
    double s = 0;
    for (int i = 0; i < kUnknowns; ++i) s += v[i] * v[i];
    return std::sqrt(s);
  };
  residual(x, r, jac);
  double r_norm = norm(r);
  constexpr int kMaxIterations = 100;
  constexpr double kTolerance = 1e-12;  // relative to the pump's free flow
  for (int it = 0; it < kMaxIterations && r_norm > kTolerance; ++it) {
    double dx[kUnknowns];
    for (int i = 0; i < kUnknowns; ++i) dx[i] = -r[i];
    if (!SolveLinear5(jac, dx)) break;
    // Backtracking line search on the residual norm; keeps iterates in [-p_max, 2 p_max].
    double step = 1.0;
    double trial[kUnknowns];
    double r_trial[kUnknowns];
    double trial_norm = r_norm;
    for (int ls = 0; ls < 30; ++ls) {
      for (int i = 0; i < kUnknowns; ++i)
        trial[i] = std::clamp(x[i] + step * dx[i], -p_max, 2.0 * p_max);
      residual(trial, r_trial, nullptr);
      trial_norm = norm(r_trial);
      if (trial_norm < r_norm) break;
      step *= 0.5;
    }
    sol.iterations = it + 1;
    if (!(trial_norm < r_norm)) break;  // no progress possible: stop at the best iterate
    for (int i = 0; i < kUnknowns; ++i) x[i] = trial[i];
    residual(x, r, jac);
    r_norm = norm(r);
  }
  sol.converged = r_norm <= 1e-9;

  for (int i = 0; i < kNumChambers; ++i) {
    sol.chamber_pa[i] = x[i];
    sol.leak_flow_m3_s[i] = k * leak_area_m2[i] * Ssqrt(x[i], c);
    sol.port_flow_m3_s[i] = k * a_port * Ssqrt(x[kNumChambers] - x[i], c);
    // The tap reads the static pressure minus the recovered part of the inflow jet's dynamic
    // pressure (which, for orifice inflow from ambient, equals the chamber vacuum itself).
    const double jet = jet_area_m2 ? std::min((*jet_area_m2)[i], leak_area_m2[i]) : leak_area_m2[i];
    const double fill = std::min(1.0, std::max(0.0, jet) / params.jet_area_m2);
    const double recovered = params.tap_recovery * fill * std::max(0.0, x[i]);
    sol.tap_pa[i] = x[i] - recovered;
  }
  sol.port_pa = x[kNumChambers];
  sol.pump_flow_m3_s = q_max * (1.0 - sol.port_pa / p_max);
  return sol;
}

}  // namespace ssc
