// What makes the real cup on the real robot differ from an ideal one, as plain C++ (no MuJoCo).
//
// Each mechanism is a physical parameter set with units, a range argued from the hardware
// (docs/fidelity.md) and an off state (all zero = the ideal loop). The trial applies
// them between the plugin's filtered pressures and the control law ("what the host reads") and
// in the loop's timing; the viewer runs the same trial code, so it sees the same thing.
//
//   LoopTimingParams  the real loop: no fixed rate (it redrew a live plot), and the pressures are
//                     read before the plot while the pose the step is added to is read after it.
//   LipShearParams    the soft lip dragged across the object: its footprint sticks until the
//                     shear reaches slip_mm (Coulomb: mu * F_n / k_shear), and the sheared lip
//                     tilts, pressing the leading lip and lifting the trailing one; a chamber's
//                     vacuum scales by 10^(tilt_decades * (shear along the chamber) / slip).
//                     The trailing lip may also peel (peel_decades): a trailing chamber leaks and
//                     reads less, a leading one no more than a sealed lip gives.
//   ChamberSpreadParams  the four sensors and tubes: gain spread between chambers (drawn per
//                     trial: the twin does not know the real cup's), and slow noise the
//                     7-sample average cannot remove (tube/pump pulsation; Ornstein-Uhlenbeck),
//                     additive in Pa and relative (common to all chambers: the pump).
//
// Determinism: every random draw is a pure function of (seed, counter), so a trial with the same
// seed gives the same rows on any thread or rank.
#ifndef SSC_TRIAL_ROBOT_EFFECTS_H_
#define SSC_TRIAL_ROBOT_EFFECTS_H_

#include <array>
#include <cstdint>
#include <string>

namespace ssc {

struct LoopTimingParams {
  // Half-width of the uniform jitter of each iteration's period, s: [0, period / 2].
  double jitter_s = 0.0;
  // Time from reading the pressures to reading the pose the step is added to, s: [0, period).
  // The lab's loop drew a live plot in between (about 0.05-0.15 s).
  double pose_delay_s = 0.0;
  // 1-sigma error of where each step ends, per horizontal axis, as a fraction of the step's
  // length: [0, 1]; 0 = off. The arm servoing the tool's payload at an irregular ~4 Hz does not
  // land on its target (its tracking lag, the period's jitter, the turn within a step: all grow
  // with the step); the next step is added to the measured pose, so the error stays in the path
  // until the law corrects it.
  double step_error_relative = 0.0;
  // Largest 1-sigma step error, mm: [0, 3]; 0 = no cap. The landing error grows with the step
  // only up to a size the step does not set: the lip's stick-slip on the object (it sticks, then
  // slides by up to its slip length, mu * F_n / k_shear ~ 0.5-3 mm) and the servo's settling at
  // the payload. sigma = min(step_error_relative * step, step_error_max_mm).
  double step_error_max_mm = 0.0;
  // Correlation of successive steps' landing errors: [0, 0.95]; 0 = independent. The arm is
  // still settling from one step when the next is added to its measured pose, and the lip's
  // stick-slip keeps its sense for a while, so the misses persist: error_k = rho * error_{k-1} +
  // sqrt(1 - rho^2) * fresh draw (an AR(1) with the same 1-sigma). The law removes a
  // slowly varying miss only as fast as its gain allows, so a persistent miss takes a weak
  // correction (small beta) further off the edge than a strong one.
  double step_error_corr = 0.0;
};

struct LipShearParams {
  // Shear the lip takes before its footprint slides, mm: [0, 3]; 0 = off. A silicone lip of
  // ~1.5 mm wall under ~1.5-4 N of contact and suction load, mu ~ 0.5-1, k_shear ~ 1-5 N/mm.
  double slip_mm = 0.0;
  // Change of a fully leading / trailing chamber's vacuum at full shear, decades: [0, 1].
  double tilt_decades = 0.0;
  // Loss of a fully trailing chamber's vacuum at full shear, decades: [0, 1.5]; 0 = off. The
  // dragged lip peels at its trailing edge and leaks, while the pressed leading edge cannot seal
  // better than sealed, so only trailing chambers change: the moving cup reads less than the
  // static one at the same inset. 1.5 decades takes a covered chamber (~200 Pa) to the
  // open-cup level (~5-10 Pa): a trailing lip lifted clear.
  double peel_decades = 0.0;
};

struct ChamberSpreadParams {
  double gain_spread = 0.0;  // 1-sigma relative gain spread between chambers: [0, 0.3]
  // Which cup the gains belong to: 0 = drawn afresh in every trial (the twin does not know the
  // real cup's); a whole number 1..1e6 = the gains of that one cup in every trial (the lab ran
  // its whole map with one cup, whose chamber gains stayed put). Never chosen to match: a study
  // reports every cup it ran.
  double cup_seed = 0.0;
  // 1-sigma residual tare offset per chamber, Pa: [0, 30]. The lab tared the sensors in air
  // with the pump at 30 % PWM and followed at 100 %: each chamber keeps the difference of its
  // open-cup vacuum between the two (and the MPRLS zero drift), drawn per trial.
  double offset_spread_pa = 0.0;
  double drift_pa = 0.0;        // 1-sigma slow additive noise per chamber, Pa: [0, 50]
  double drift_relative = 0.0;  // 1-sigma slow relative noise common to all chambers: [0, 0.5]
  double drift_time_s = 0.5;    // correlation time of both, s: (0, 10]
};

struct RobotEffectsParams {
  LoopTimingParams loop;
  LipShearParams lip;
  ChamberSpreadParams chambers;
  // Empty when valid, else names the field, its value and range. `period_s` bounds the timing.
  std::string Validate(double period_s) const;
  bool AnyOn() const;
};

// The twin's default effects, fitted globally (`ssc calibrate --dynamic`, BOBYQA, common seeds)
// to the published dL 5 mm map, the Fig. 6 targets and the published outcomes beside the map
// (docs/fidelity.md): the landing error of each step (a share of the step, capped, successive
// misses correlated) and a residual tare offset per chamber, drawn per trial. Every other effect
// is off. `--effects off` gives the ideal loop. The values: docs/defaults.md.
RobotEffectsParams FittedRobotEffects();

// The keys of the effects, one table: name, unit, valid range, the range `ssc calibrate
// --dynamic` searches (fit_min == fit_max: never fitted), what it is. Parsing, validation,
// --help, the fit and docs/defaults.md all read it.
struct EffectKey {
  const char* key;
  const char* unit;
  double min, max;
  double fit_min, fit_max;
  const char* what;
  double* (*field)(RobotEffectsParams*);
};
const std::array<EffectKey, 14>& EffectKeys();
// Parses "key=value,key=value" (or "off": every effect off) onto *p. Values must be whole,
// finite numbers in the key's range; the error names the key, the value and the range.
bool ParseRobotEffects(const std::string& text, RobotEffectsParams* p, std::string* error);
// "key=value,..." for every key (for summaries and reproducible command lines).
std::string FormatRobotEffects(const RobotEffectsParams& p);

// Counter-based standard normal / uniform(-1, 1) deviates: pure functions of (seed, counter, k).
double EffectGaussian(std::uint64_t seed, std::uint64_t counter, int k);
double EffectUniform(std::uint64_t seed, std::uint64_t counter, int k);

// Stream ids (the `counter`'s top byte), so the mechanisms never share draws.
enum class EffectStream : std::uint64_t {
  kJitter = 1,
  kGain = 2,
  kDrift = 3,
  kOffset = 4,
  kStepError = 5
};
std::uint64_t EffectCounter(EffectStream stream, std::uint64_t index);

// The period of iteration `index`: period_s + jitter_s * U(-1, 1).
double IterationPeriod(const LoopTimingParams& p, double period_s, std::uint64_t seed,
                       std::uint64_t index);

// The error of step `index`'s end point (tool frame x, y), m: sigma * u per axis, with
// sigma = step_error_relative * step_m capped at step_error_max_mm (when > 0), step_m the step's
// length, and u a unit-variance AR(1) sequence with correlation step_error_corr over the step
// index (u = N(0, 1) draws when 0). A pure function of (seed, index): u_k is summed from the
// draws of steps k, k-1, ... with weights sqrt(1 - rho^2) rho^j, except the oldest (step 0),
// which weighs rho^k so that the sequence starts stationary; cut where rho^j < 1e-6.
std::array<double, 2> StepError(const LoopTimingParams& p, double step_m, std::uint64_t seed,
                                std::uint64_t index);

// The lip's shear state: the footprint lags the body until |shear| reaches slip (then slides).
// Unit vectors of the chambers' centres in the tool frame come from ChamberDirection.
struct LipShearState {
  std::array<double, 2> shear_m{};  // body minus footprint, tool frame, m
};
// Moves the body by `body_move_m` (tool frame, m).
void AdvanceLipShear(const LipShearParams& p, const std::array<double, 2>& body_move_m,
                     LipShearState* s);
// F/T compression below which the cup is taken as not pressed on anything (the F/T's noise is of
// this order): the lip then hangs free.
inline constexpr double kLipPressedN = 0.05;
// The lip dragged along while the F/T reads `press_n` of compression: pressed, as
// AdvanceLipShear; not pressed, the lip hangs free and its footprint is new where it lands.
void DragLip(const LipShearParams& p, const std::array<double, 2>& body_move_m, double press_n,
             LipShearState* s);
// Chamber i's centre direction seen from the cup axis, tool frame (unit): chambers 1..4 =
// SE, NE, NW, SW with north = -x_tool, west = +y_tool (controller/contour_law.h).
std::array<double, 2> ChamberDirection(int chamber);
// Multiplies each chamber's vacuum by the tilt and the trailing-lip peel the shear gives it.
void ApplyLipTilt(const LipShearParams& p, const LipShearState& s, std::array<double, 4>* p_pa);

// Per-trial chamber gains and the slow noise state.
struct ChamberSpreadState {
  std::array<double, 4> gain{1, 1, 1, 1};
  std::array<double, 4> offset_pa{};
  std::array<double, 4> drift_pa{};
  double drift_rel = 0;
  double last_time_s = -1;
  std::uint64_t draws = 0;
};
void ResetChamberSpread(const ChamberSpreadParams& p, std::uint64_t seed, ChamberSpreadState* s);
// Advances the slow noise to `time_s` (exact Ornstein-Uhlenbeck update) and applies gain, drift,
// the common relative drift and the residual tare offsets to the four vacuums.
void ApplyChamberSpread(const ChamberSpreadParams& p, std::uint64_t seed, double time_s,
                        ChamberSpreadState* s, std::array<double, 4>* p_pa);

}  // namespace ssc

#endif  // SSC_TRIAL_ROBOT_EFFECTS_H_
