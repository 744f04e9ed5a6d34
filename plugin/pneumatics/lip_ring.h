// The lip as a ring: out-of-plane bending of the silicone lip, coupling the segments' axial
// displacements. Pure C++: no MuJoCo types.
//
// The lip is a closed ring of radius R carrying N segments at angles theta_i; u_i is segment i's
// axial displacement (m, any sign convention, the same for all). The ring's bending energy is
// that of a thin ring bent out of its plane, E = 1/2 EI \int (d2u/ds2)^2 ds, taken mode by mode:
// for u = a cos(k theta) + b sin(k theta), E_k = 1/2 EI pi k^4 / R^3 (a^2 + b^2). Modes 0 and 1
// (the ring moving and tilting as a whole) cost nothing, so a ring lying on any plane has zero
// bending energy; a ring draped over a step or into a corner does not.
//
// Per segment the mode-k stiffness is lambda_k = 2 pi EI k^4 / (N R^3) (N/m). Short waves are
// stiff (k^4); `mode_cap_n_per_m` caps lambda_k so an explicit integrator stays stable at its time
// step (the adapter derives the cap from the step and the segment mass).
//
// The mode shapes at the segments' angles (RingModeShapes) depend on the angles only: the plugin
// makes them once, and the per-step force then needs no trigonometry and never allocates.
#ifndef SSC_PLUGIN_PNEUMATICS_LIP_RING_H_
#define SSC_PLUGIN_PNEUMATICS_LIP_RING_H_

#include <limits>
#include <vector>

namespace ssc {

inline constexpr double kNoModeCap = std::numeric_limits<double>::infinity();

// The lip's mechanics beyond its segments' own springs (MJCF): ring bending couples the
// segments; the shear and tilt springs act on the lip carrier's slide and hinge joints. A zero
// shear or tilt stiffness keeps those joints locked (the rigid cup, the default).
struct LipMechanics {
  double bending_stiffness_nm2 = 0.6e-6;   // EI of the lip ring bent out of its plane
  double shear_stiffness_n_per_m = 0.0;    // lip tip vs cup, lateral; 0 = rigid (off)
  double tilt_stiffness_nm_per_rad = 0.0;  // lip plane about its pivot; 0 = rigid (off)
};

// Mode-k per-segment stiffness, N/m (k >= 2), before any cap.
double RingModeStiffness(int k, int n_segments, double bending_stiffness_nm2, double radius_m);

// cos(k theta_i) and sin(k theta_i) for the modes k = 2 .. n/2 (index (k - 2) * n + i).
struct RingModeShapes {
  int n = 0;
  std::vector<double> cos_k, sin_k;
};
RingModeShapes MakeRingModeShapes(const double* theta_rad, int n);

// Bending energy (J) of displacements u[0..shapes.n).
double RingBendingEnergy(const double* u, const RingModeShapes& shapes,
                         double bending_stiffness_nm2, double radius_m,
                         double mode_cap_n_per_m = kNoModeCap);
// Adds the bending force -dE/du (N) to force[0..shapes.n). Never allocates.
void AddRingBendingForce(const double* u, const RingModeShapes& shapes,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m,
                         double* force);

// The same from the angles (makes the shapes on each call: for tests and tools).
// Bending energy (J) of displacements u[0..n) at angles theta_rad[0..n) (evenly spaced).
double RingBendingEnergy(const double* u, const double* theta_rad, int n,
                         double bending_stiffness_nm2, double radius_m,
                         double mode_cap_n_per_m = kNoModeCap);

// Adds the bending force -dE/du (N) to force[0..n).
void AddRingBendingForce(const double* u, const double* theta_rad, int n,
                         double bending_stiffness_nm2, double radius_m, double mode_cap_n_per_m,
                         double* force);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_LIP_RING_H_
