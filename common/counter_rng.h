// The project's one counter-based random number home: every random draw (sensor noise, robot
// effects, sweep seeds) is a pure function of (seed, counter), so a trial gives the same rows on
// any thread, rank or machine, and a resumed sweep draws what an uninterrupted one would.
#ifndef SSC_COMMON_COUNTER_RNG_H_
#define SSC_COMMON_COUNTER_RNG_H_

#include <cstdint>

namespace ssc {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix; chained with XOR to
// hash (seed, counter, lane) tuples.
constexpr std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Uniform in (0, 1) from the top 53 bits: never exactly 0 or 1 (safe for log and Box-Muller).
constexpr double UnitFromBits(std::uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

}  // namespace ssc

#endif  // SSC_COMMON_COUNTER_RNG_H_
