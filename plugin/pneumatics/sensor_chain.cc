#include "plugin/pneumatics/sensor_chain.h"

#include <cmath>
#include <sstream>

#include "common/counter_rng.h"

namespace ssc {
namespace {

double ToUnit(std::uint64_t bits) { return UnitFromBits(bits); }

}  // namespace

std::string SensorChainParams::Validate() const {
  std::ostringstream os;
  if (!std::isfinite(sample_rate_hz) || sample_rate_hz < 1 || sample_rate_hz > 100000) {
    os << "sample_rate_hz = " << sample_rate_hz << " is out of range [1, 100000] Hz";
  } else if (!std::isfinite(noise_pa) || noise_pa < 0 || noise_pa > 10000) {
    os << "noise_pa = " << noise_pa << " is out of range [0, 10000] Pa";
  } else if (average_samples < 1 || average_samples > kMaxAverageSamples) {
    os << "average_samples = " << average_samples << " is out of range [1, " << kMaxAverageSamples
       << "]";
  } else if (!std::isfinite(lag_s) || lag_s < 0 || lag_s > 10) {
    os << "lag_s = " << lag_s << " is out of range [0, 10] s";
  }
  return os.str();
}

void ResetSensorChain(SensorChainState* state) {
  double* raw = reinterpret_cast<double*>(state);
  for (int i = 0; i < kSensorChainStateSize; ++i) raw[i] = 0.0;
  state->last_sample_index = -1.0;
}

std::int64_t SampleIndexAt(const SensorChainParams& params, double time_s) {
  // The tiny epsilon keeps t = k / rate (up to rounding) inside sample k.
  return static_cast<std::int64_t>(std::floor(time_s * params.sample_rate_hz + 1e-7));
}

double CounterGaussian(std::uint64_t seed, std::int64_t sample_index, int chamber) {
  const std::uint64_t key =
      SplitMix64(seed ^ SplitMix64(static_cast<std::uint64_t>(sample_index) * 4 +
                                   static_cast<std::uint64_t>(chamber)));
  const double u1 = ToUnit(SplitMix64(key));
  const double u2 = ToUnit(SplitMix64(key + 1));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

double NoisySample(const SensorChainParams& params, double clean_pa, std::int64_t sample_index,
                   int chamber) {
  return clean_pa + params.noise_pa * CounterGaussian(params.seed, sample_index, chamber);
}

int TakeSamples(const SensorChainParams& params, std::int64_t sample_index,
                const std::array<double, kNumChambers>& tap_pa, SensorChainState* state) {
  const std::int64_t last = static_cast<std::int64_t>(state->last_sample_index);
  if (sample_index <= last) return 0;
  const bool first = last < 0 && state->count == 0;
  std::int64_t from = last + 1;
  if (first || sample_index - from >= params.average_samples) {
    from = sample_index - params.average_samples + 1;  // older samples would leave the window
  }
  if (from < 0) from = 0;
  const double dt = 1.0 / params.sample_rate_hz;
  const double alpha = params.lag_s > 0 ? 1.0 - std::exp(-dt / params.lag_s) : 1.0;
  int taken = 0;
  for (std::int64_t k = from; k <= sample_index; ++k) {
    const int slot = static_cast<int>(state->head);
    for (int c = 0; c < kNumChambers; ++c) {
      double& lagged = state->lagged_pa[c];
      lagged = (first && taken == 0) ? tap_pa[c] : lagged + alpha * (tap_pa[c] - lagged);
      state->clean_pa[slot][c] = lagged;
      state->window_pa[slot][c] = NoisySample(params, lagged, k, c);
    }
    state->slot_index[slot] = static_cast<double>(k);
    state->head = static_cast<double>((slot + 1) % params.average_samples);
    if (state->count < params.average_samples) state->count += 1.0;
    ++taken;
  }
  state->last_sample_index = static_cast<double>(sample_index);
  return taken;
}

void ReseedSensorChain(const SensorChainParams& params, SensorChainState* state) {
  const int n = static_cast<int>(state->count);
  for (int slot = 0; slot < n; ++slot) {
    const auto k = static_cast<std::int64_t>(state->slot_index[slot]);
    for (int c = 0; c < kNumChambers; ++c) {
      state->window_pa[slot][c] = NoisySample(params, state->clean_pa[slot][c], k, c);
    }
  }
}

std::array<double, kNumChambers> FilteredOutput(const SensorChainState& state) {
  std::array<double, kNumChambers> out{};
  const int n = static_cast<int>(state.count);
  if (n == 0) return out;
  for (int s = 0; s < n; ++s) {
    for (int c = 0; c < kNumChambers; ++c) out[c] += state.window_pa[s][c];
  }
  for (int c = 0; c < kNumChambers; ++c) out[c] /= n;
  return out;
}

}  // namespace ssc
