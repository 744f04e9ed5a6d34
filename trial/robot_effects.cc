#include "trial/robot_effects.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "common/counter_rng.h"
#include "common/strict_number.h"

namespace ssc {
namespace {

// (0, 1), never 0 or 1.
double Unit(std::uint64_t seed, std::uint64_t counter, int k, int lane) {
  const std::uint64_t h = SplitMix64(SplitMix64(SplitMix64(seed) ^ counter) ^
                                     (static_cast<std::uint64_t>(k) * 4 + lane));
  return UnitFromBits(h);
}

bool In(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

std::string Bad(const char* field, double v, const std::string& range) {
  std::ostringstream os;
  os << field << " = " << v << " is out of range " << range;
  return os.str();
}

}  // namespace

const std::array<EffectKey, 14>& EffectKeys() {
  static const std::array<EffectKey, 14> kKeys = {{
      {"jitter_s", "s", 0, 5, 0, 0.08, "half-width of the uniform jitter of the loop period",
       [](RobotEffectsParams* p) { return &p->loop.jitter_s; }},
      {"pose_delay_s", "s", 0, 10, 0, 0.15,
       "pressures read -> pose read (the live plot in between)",
       [](RobotEffectsParams* p) { return &p->loop.pose_delay_s; }},
      {"step_error_relative", "1", 0, 1, 0, 1,
       "1-sigma error of where each step ends, per axis, over the step length",
       [](RobotEffectsParams* p) { return &p->loop.step_error_relative; }},
      {"step_error_max_mm", "mm", 0, 3, 0.3, 3,
       "cap of that 1-sigma error (the lip's stick-slip; 0 = no cap)",
       [](RobotEffectsParams* p) { return &p->loop.step_error_max_mm; }},
      {"step_error_corr", "1", 0, 0.95, 0, 0.95,
       "correlation of successive steps' landing errors (the arm still settling; 0 = independent)",
       [](RobotEffectsParams* p) { return &p->loop.step_error_corr; }},
      {"slip_mm", "mm", 0, 3, 0.2, 2, "lip shear before the footprint slides (0 = no lip drag)",
       [](RobotEffectsParams* p) { return &p->lip.slip_mm; }},
      {"tilt_decades", "decades", 0, 1, 0, 0.4,
       "vacuum change of a leading/trailing chamber at full shear",
       [](RobotEffectsParams* p) { return &p->lip.tilt_decades; }},
      {"peel_decades", "decades", 0, 1.5, 0, 1, "vacuum loss of a trailing chamber at full shear",
       [](RobotEffectsParams* p) { return &p->lip.peel_decades; }},
      {"gain_spread", "1", 0, 0.3, 0, 0.2, "1-sigma relative gain spread between chambers",
       [](RobotEffectsParams* p) { return &p->chambers.gain_spread; }},
      {"cup_seed", "1", 0, 1e6, 0, 0,
       "the cup whose chamber gains every trial uses (0 = drawn per trial; a whole number)",
       [](RobotEffectsParams* p) { return &p->chambers.cup_seed; }},
      {"offset_spread_pa", "Pa", 0, 30, 0, 20,
       "1-sigma residual tare offset per chamber (tared at 30 % PWM)",
       [](RobotEffectsParams* p) { return &p->chambers.offset_spread_pa; }},
      {"drift_pa", "Pa", 0, 50, 0, 20, "1-sigma slow additive noise per chamber",
       [](RobotEffectsParams* p) { return &p->chambers.drift_pa; }},
      {"drift_relative", "1", 0, 0.5, 0, 0.3, "1-sigma slow relative noise common to the chambers",
       [](RobotEffectsParams* p) { return &p->chambers.drift_relative; }},
      {"drift_time_s", "s", 0.001, 10, 0, 0, "correlation time of the slow noise",
       [](RobotEffectsParams* p) { return &p->chambers.drift_time_s; }},
  }};
  return kKeys;
}

bool ParseRobotEffects(const std::string& text, RobotEffectsParams* p, std::string* error) {
  if (text == "off") {  // every effect whose range starts at 0 is off there
    for (const EffectKey& k : EffectKeys())
      if (k.min == 0) *k.field(p) = 0;
    return true;
  }
  if (text == "default") return true;
  std::size_t pos = 0;
  std::string seen = ",";
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find(',', pos), text.size());
    const std::string item = text.substr(pos, end - pos);
    const std::size_t eq = item.find('=');
    if (item.empty() || eq == std::string::npos) {
      *error = "effects: expected key=value, got '" + item + "'";
      return false;
    }
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const EffectKey* found = nullptr;
    for (const EffectKey& k : EffectKeys())
      if (key == k.key) found = &k;
    if (found == nullptr) {
      std::string names;
      for (const EffectKey& k : EffectKeys())
        names += std::string(names.empty() ? "" : ", ") + k.key;
      *error = "effects: unknown key '" + key + "' (keys: " + names + ")";
      return false;
    }
    // A key given twice is a typo, not an override: which one was meant is unknowable.
    if (seen.find("," + key + ",") != std::string::npos) {
      *error = "effects: " + key + " is given twice";
      return false;
    }
    seen += key + ",";
    double v = 0;
    std::string why;
    if (!ParseNumber(value, NumberRange::Closed(found->min, found->max), &v, &why)) {
      *error = "effects: " + key + " = '" + value + "': " + why + " (" + found->unit + ")";
      return false;
    }
    *found->field(p) = v;
    pos = end + 1;
  }
  return true;
}

std::string FormatRobotEffects(const RobotEffectsParams& p) {
  std::ostringstream os;
  RobotEffectsParams copy = p;
  for (const EffectKey& k : EffectKeys())
    os << (&k == &EffectKeys()[0] ? "" : ",") << k.key << "=" << *k.field(&copy);
  return os.str();
}

double EffectGaussian(std::uint64_t seed, std::uint64_t counter, int k) {
  // Box-Muller on two independent lanes.
  const double u1 = Unit(seed, counter, k, 0), u2 = Unit(seed, counter, k, 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

double EffectUniform(std::uint64_t seed, std::uint64_t counter, int k) {
  return 2.0 * Unit(seed, counter, k, 2) - 1.0;
}

std::uint64_t EffectCounter(EffectStream stream, std::uint64_t index) {
  return (static_cast<std::uint64_t>(stream) << 56) ^ index;
}

RobotEffectsParams FittedRobotEffects() {
  RobotEffectsParams p;
  p.loop.step_error_relative = 0.38;
  p.loop.step_error_max_mm = 1.43;
  p.loop.step_error_corr = 0.29;
  p.chambers.offset_spread_pa = 7.9;
  return p;
}

std::string RobotEffectsParams::Validate(double period_s) const {
  // Every key's range from its one home, the key table; then what the period bounds.
  RobotEffectsParams copy = *this;
  for (const EffectKey& k : EffectKeys()) {
    const double v = *k.field(&copy);
    if (!In(v, k.min, k.max)) {
      std::ostringstream range;
      range << '[' << k.min << ", " << k.max << ']' << (std::string(k.unit) == "1" ? "" : " ")
            << (std::string(k.unit) == "1" ? "" : k.unit);
      return Bad(k.key, v, range.str());
    }
  }
  if (!In(loop.jitter_s, 0, period_s / 2))
    return Bad("loop jitter_s", loop.jitter_s, "[0, period/2] s");
  if (!In(loop.pose_delay_s, 0, period_s) || (loop.pose_delay_s >= period_s && period_s > 0))
    return Bad("loop pose_delay_s", loop.pose_delay_s, "[0, period) s");
  if (loop.pose_delay_s + loop.jitter_s >= period_s && loop.pose_delay_s > 0)
    return Bad("loop pose_delay_s + jitter_s", loop.pose_delay_s + loop.jitter_s,
               "below the period");
  if (chambers.cup_seed != std::floor(chambers.cup_seed))
    return Bad("chamber cup_seed", chambers.cup_seed, "[0, 1e6] (whole numbers)");
  return "";
}

bool RobotEffectsParams::AnyOn() const {
  return loop.jitter_s > 0 || loop.pose_delay_s > 0 || loop.step_error_relative > 0 ||
         (lip.slip_mm > 0 && (lip.tilt_decades > 0 || lip.peel_decades > 0)) ||
         chambers.gain_spread > 0 || chambers.offset_spread_pa > 0 || chambers.drift_pa > 0 ||
         chambers.drift_relative > 0;
}

double IterationPeriod(const LoopTimingParams& p, double period_s, std::uint64_t seed,
                       std::uint64_t index) {
  if (p.jitter_s <= 0) return period_s;
  return period_s +
         p.jitter_s * EffectUniform(seed, EffectCounter(EffectStream::kJitter, index), 0);
}

std::array<double, 2> StepError(const LoopTimingParams& p, double step_m, std::uint64_t seed,
                                std::uint64_t index) {
  if (p.step_error_relative <= 0) return {0, 0};
  const std::uint64_t c = EffectCounter(EffectStream::kStepError, index);
  double sigma_m = p.step_error_relative * step_m;
  if (p.step_error_max_mm > 0) sigma_m = std::min(sigma_m, p.step_error_max_mm * 1e-3);
  const double rho = p.step_error_corr;
  if (rho <= 0) return {sigma_m * EffectGaussian(seed, c, 0), sigma_m * EffectGaussian(seed, c, 1)};
  // u_k = sqrt(1 - rho^2) sum_j rho^j n_{k-j}; the oldest draw (step 0) weighs
  // rho^k so that u_0 = n_0 and every u_k has unit variance.
  const double fresh = std::sqrt(1 - rho * rho);
  std::array<double, 2> u{0, 0};
  double w = 1;
  for (std::uint64_t j = 0; j <= index && w >= 1e-6; ++j, w *= rho) {
    const std::uint64_t cj = EffectCounter(EffectStream::kStepError, index - j);
    const double weight = j == index ? w : fresh * w;
    u[0] += weight * EffectGaussian(seed, cj, 0);
    u[1] += weight * EffectGaussian(seed, cj, 1);
  }
  return {sigma_m * u[0], sigma_m * u[1]};
}

void DragLip(const LipShearParams& p, const std::array<double, 2>& body_move_m, double press_n,
             LipShearState* s) {
  if (press_n < kLipPressedN) {
    *s = LipShearState();
    return;
  }
  AdvanceLipShear(p, body_move_m, s);
}

void AdvanceLipShear(const LipShearParams& p, const std::array<double, 2>& body_move_m,
                     LipShearState* s) {
  if (p.slip_mm <= 0) {
    s->shear_m = {0, 0};
    return;
  }
  const double slip_m = p.slip_mm * 1e-3;
  s->shear_m[0] += body_move_m[0];
  s->shear_m[1] += body_move_m[1];
  const double n = std::hypot(s->shear_m[0], s->shear_m[1]);
  if (n > slip_m) {  // the footprint slides: shear stays at the friction limit
    s->shear_m[0] *= slip_m / n;
    s->shear_m[1] *= slip_m / n;
  }
}

std::array<double, 2> ChamberDirection(int chamber) {
  // south = +x_tool, west = +y_tool; SE, NE, NW, SW.
  static const double kS = std::sqrt(0.5);
  static const std::array<std::array<double, 2>, 4> kDir = {
      {{kS, -kS}, {-kS, -kS}, {-kS, kS}, {kS, kS}}};
  return kDir[static_cast<std::size_t>(chamber)];
}

void ApplyLipTilt(const LipShearParams& p, const LipShearState& s, std::array<double, 4>* p_pa) {
  if (p.slip_mm <= 0 || (p.tilt_decades <= 0 && p.peel_decades <= 0)) return;
  const double slip_m = p.slip_mm * 1e-3;
  for (int i = 0; i < 4; ++i) {
    const std::array<double, 2> d = ChamberDirection(i);
    // Leading chambers (along the shear: the way the body moved) are pressed, trailing lifted;
    // trailing ones (along < 0) also peel.
    const double along = (d[0] * s.shear_m[0] + d[1] * s.shear_m[1]) / slip_m;
    const double decades = p.tilt_decades * along + p.peel_decades * std::fmin(along, 0.0);
    (*p_pa)[static_cast<std::size_t>(i)] *= std::pow(10.0, decades);
  }
}

void ResetChamberSpread(const ChamberSpreadParams& p, std::uint64_t seed, ChamberSpreadState* s) {
  *s = ChamberSpreadState();
  // One cup's gains in every trial, or a fresh cup per trial.
  const std::uint64_t gain_seed = p.cup_seed > 0 ? static_cast<std::uint64_t>(p.cup_seed) : seed;
  for (int i = 0; i < 4; ++i) {
    const double g =
        1.0 + p.gain_spread * EffectGaussian(gain_seed, EffectCounter(EffectStream::kGain, 0), i);
    s->gain[static_cast<std::size_t>(i)] = std::fmax(0.2, g);  // a sensor never reads inverted
    s->offset_pa[static_cast<std::size_t>(i)] =
        p.offset_spread_pa * EffectGaussian(seed, EffectCounter(EffectStream::kOffset, 0), i);
  }
  // Start the slow noise in its stationary distribution.
  const std::uint64_t c = EffectCounter(EffectStream::kDrift, s->draws++);
  for (int i = 0; i < 4; ++i)
    s->drift_pa[static_cast<std::size_t>(i)] = p.drift_pa * EffectGaussian(seed, c, i);
  s->drift_rel = p.drift_relative * EffectGaussian(seed, c, 4);
}

void ApplyChamberSpread(const ChamberSpreadParams& p, std::uint64_t seed, double time_s,
                        ChamberSpreadState* s, std::array<double, 4>* p_pa) {
  if (s->last_time_s >= 0 && time_s > s->last_time_s && (p.drift_pa > 0 || p.drift_relative > 0)) {
    const double a = std::exp(-(time_s - s->last_time_s) / p.drift_time_s);
    const double b = std::sqrt(1.0 - a * a);
    const std::uint64_t c = EffectCounter(EffectStream::kDrift, s->draws++);
    for (int i = 0; i < 4; ++i) {
      auto& x = s->drift_pa[static_cast<std::size_t>(i)];
      x = a * x + b * p.drift_pa * EffectGaussian(seed, c, i);
    }
    s->drift_rel = a * s->drift_rel + b * p.drift_relative * EffectGaussian(seed, c, 4);
  }
  s->last_time_s = time_s;
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    (*p_pa)[k] = (*p_pa)[k] * s->gain[k] * (1.0 + s->drift_rel) + s->drift_pa[k] + s->offset_pa[k];
  }
}

}  // namespace ssc
