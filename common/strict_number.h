// One strict reader for every number a user types: command-line flags and lists, the plugin's
// MJCF config values, the sweep manifest. Pure C++ (no MuJoCo).
//
// Accepted: an optional sign, decimal digits with an optional point, an optional exponent
// ("100", "-6", "2.5e-3", ".5"); spaces around it are ignored. Rejected with a message: empty
// text, hex ("0x10"), "inf", "nan", trailing text ("5mm", "1,"), values outside the range,
// fractions where a whole number is needed, and in lists empty items and repeats.
#ifndef SSC_COMMON_STRICT_NUMBER_H_
#define SSC_COMMON_STRICT_NUMBER_H_

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace ssc {

struct NumberRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool whole = false;  // integers only

  static constexpr NumberRange Closed(double lo, double hi) {
    return {lo, hi, false, false, false};
  }
  static constexpr NumberRange Positive(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, hi, true, false, false};
  }
  static constexpr NumberRange Whole(double lo, double hi) { return {lo, hi, false, false, true}; }
  constexpr NumberRange OpenLow() const { return {lo, hi, true, hi_open, whole}; }
  constexpr NumberRange OpenHigh() const { return {lo, hi, lo_open, true, whole}; }

  bool Contains(double v) const;
  // "[0, 100000]", "(0, 1]", "a whole number in [1, 64]", "> 0".
  std::string ToString() const;
};

// Seeds travel through doubles (the plugin's state, CSV columns): whole numbers are exact up to
// 2^53 - 1, so every seed a user gives (--seed, a Python seed=, a sweep row) is one of these.
inline constexpr NumberRange kSeedRange = NumberRange::Whole(0, 9007199254740991.0);

// Formats a number the way ranges and defaults are shown (shortest exact-enough form, %g).
std::string FormatNumber(double v);

// Parses all of `text` as one number in `range`. On failure returns false and *error says what
// is wrong with the value and gives the range (the caller prefixes the input's name).
bool ParseNumber(std::string_view text, const NumberRange& range, double* out, std::string* error);

// A comma-separated list ("40,70,100"). Empty items (a trailing or doubled comma) are errors; so
// are repeated values when `unique` (a grid axis listing a value twice runs its trials twice).
bool ParseNumberList(std::string_view text, const NumberRange& range, bool unique,
                     std::vector<double>* out, std::string* error);

// A comma-separated list of names ("period_s,smoothing_s"), with the same rules: no empty item
// (a stray comma), no name twice, blanks around items dropped.
bool ParseNameList(std::string_view text, std::vector<std::string>* out, std::string* error);

}  // namespace ssc

#endif  // SSC_COMMON_STRICT_NUMBER_H_
