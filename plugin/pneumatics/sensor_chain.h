// The real device's sensor chain after the chamber taps: a first-order lag (tube + sensor),
// Gaussian sensor noise, sampling at the sensor's rate with zero-order hold, and the host's
// moving average. Pure C++: no MuJoCo types.
//
// The moving average is applied exactly once, here (the plugin outputs the host's filtered
// value); the controller uses the sensor output as it is.
//
// Determinism: sample k is taken at time k / sample_rate_hz; its noise is a pure function of
// (seed, k, chamber) (counter-based), so recomputing at the same time, resetting, or copying the
// state can never advance or change the noise stream.
#ifndef SSC_PLUGIN_PNEUMATICS_SENSOR_CHAIN_H_
#define SSC_PLUGIN_PNEUMATICS_SENSOR_CHAIN_H_

#include <array>
#include <cstdint>
#include <string>

#include "plugin/pneumatics/flow_network.h"

namespace ssc {

inline constexpr int kMaxAverageSamples = 64;

struct SensorChainParams {
  double sample_rate_hz = 160.0;  // MPRLS streaming rate, [1, 100000]
  double noise_pa = 6.0;          // 1-sigma noise per chamber per sample, [0, 10000]
  int average_samples = 7;        // host moving-average window, [1, 64]
  double lag_s = 0.0;             // first-order lag of tube + sensor, [0, 10]; 0 = none
  std::uint64_t seed = 0;         // noise seed

  std::string Validate() const;
};

// Sensor state kept in the simulator's plugin state array (all doubles, so it can live in
// mjData::plugin_state and survive copies and resets).
struct SensorChainState {
  double last_sample_index;  // index of the newest sample taken, -1 before the first
  double count;              // samples in the window, <= average_samples
  double head;               // next slot to write
  double lagged_pa[kNumChambers];
  double window_pa[kMaxAverageSamples][kNumChambers];  // noisy samples (what the host averages)
  // Each slot's sample before its noise and its sample index: with them the window can be
  // re-derived for another seed (ReseedSensorChain) exactly as TakeSamples would have written it.
  double clean_pa[kMaxAverageSamples][kNumChambers];
  double slot_index[kMaxAverageSamples];
};
inline constexpr int kSensorChainStateSize = sizeof(SensorChainState) / sizeof(double);

void ResetSensorChain(SensorChainState* state);

// Index of the newest sample due at `time_s` (floor(time * rate), robust to rounding).
std::int64_t SampleIndexAt(const SensorChainParams& params, double time_s);

// Standard-normal deviate for (seed, sample index, chamber).
double CounterGaussian(std::uint64_t seed, std::int64_t sample_index, int chamber);

// One noisy sample: `clean_pa` plus the noise of (seed, sample index, chamber). The one place the
// noise is added (TakeSamples and ReseedSensorChain both call it, so their results are identical
// to the bit).
double NoisySample(const SensorChainParams& params, double clean_pa, std::int64_t sample_index,
                   int chamber);

// Takes samples up to `sample_index` (one per missed index, at most the window length) of the
// tap pressures `tap_pa`, through lag and noise, into the window. Returns the number of samples
// taken (0 when `sample_index` was already taken).
int TakeSamples(const SensorChainParams& params, std::int64_t sample_index,
                const std::array<double, kNumChambers>& tap_pa, SensorChainState* state);

// Rewrites the window's noisy samples for `params.seed` (the lag state and the sample times are
// unchanged: noise never feeds back). The state then equals what TakeSamples would have left with
// that seed from the start.
void ReseedSensorChain(const SensorChainParams& params, SensorChainState* state);

// The host's moving average of the window (0 before the first sample).
std::array<double, kNumChambers> FilteredOutput(const SensorChainState& state);

}  // namespace ssc

#endif  // SSC_PLUGIN_PNEUMATICS_SENSOR_CHAIN_H_
