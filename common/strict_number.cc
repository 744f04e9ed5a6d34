#include "common/strict_number.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ssc {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The decimal grammar, checked by hand: strtod alone would also take hex, inf, nan and a
// locale's decimal comma.
bool IsDecimal(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t digits = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == s.size();
}

// Whether decimal text (IsDecimal) denotes a whole number, read from the digits themselves:
// "12", "1.0", "1.5e1", "3e2" yes; "2.5", "1e-1" no. strtod alone would round
// "9007199254740990.6" to a whole double.
bool TextIsWhole(std::string_view s) {
  std::string digits;
  long point = -1;  // digits before the decimal point
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') {
      point = static_cast<long>(digits.size());
    } else {
      digits += s[i];
    }
  }
  if (point < 0) point = static_cast<long>(digits.size());
  long exponent = 0;
  if (i < s.size()) {
    const std::string e(s.substr(i + 1));
    exponent = std::strtol(e.c_str(), nullptr, 10);  // huge exponents saturate; fine below
  }
  const long first_fraction = point + std::max(-100000L, std::min(exponent, 100000L));
  for (long k = std::max(0L, first_fraction); k < static_cast<long>(digits.size()); ++k) {
    if (digits[static_cast<size_t>(k)] != '0') return false;
  }
  return true;
}

// Doubles hold every whole number up to 2^53; above, "2^53 + 1" would silently become 2^53.
constexpr double kLargestExactWhole = 9007199254740991.0;  // 2^53 - 1

std::string Quote(std::string_view s) {
  constexpr size_t kMax = 40;  // long garbage is cut in messages
  std::string q(s.substr(0, kMax));
  for (char& c : q) {
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  }
  return "'" + q + (s.size() > kMax ? "...'" : "'");
}

}  // namespace

bool NumberRange::Contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return !whole || v == std::floor(v);
}

std::string FormatNumber(double v) {
  char buf[32];
  if (v == std::floor(v) && std::fabs(v) < 1e17) {
    std::snprintf(buf, sizeof(buf), "%.0f", v);  // whole numbers in full (seeds, 2^53)
  } else {
    std::snprintf(buf, sizeof(buf), "%.10g", v);
  }
  return buf;
}

std::string NumberRange::ToString() const {
  const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
  std::string s = whole ? "a whole number " : "";
  if (lo_inf && hi_inf) return s.empty() ? "any finite number" : "a whole number";
  if (hi_inf) return s + (lo_open ? "> " : ">= ") + FormatNumber(lo);
  if (lo_inf) return s + (hi_open ? "< " : "<= ") + FormatNumber(hi);
  return s + (s.empty() ? "" : "in ") + (lo_open ? "(" : "[") + FormatNumber(lo) + ", " +
         FormatNumber(hi) + (hi_open ? ")" : "]");
}

bool ParseNumber(std::string_view text, const NumberRange& range, double* out, std::string* error) {
  const std::string_view t = Trim(text);
  if (t.empty()) {
    *error = "empty value; expected " + range.ToString();
    return false;
  }
  if (!IsDecimal(t)) {
    *error = Quote(text) + " is not a decimal number; expected " + range.ToString();
    return false;
  }
  const std::string owned(t);
  const double v = std::strtod(owned.c_str(), nullptr);
  if (!std::isfinite(v)) {
    *error = Quote(text) + " is too large; expected " + range.ToString();
    return false;
  }
  if (range.whole && (!TextIsWhole(t) || std::fabs(v) > kLargestExactWhole)) {
    *error = Quote(text) +
             (TextIsWhole(t) ? " is beyond 2^53 - 1, where whole numbers stop being exact"
                             : " is not a whole number") +
             "; expected " + range.ToString();
    return false;
  }
  if (!range.Contains(v)) {
    *error = Quote(text) + " is outside the valid range; expected " + range.ToString();
    return false;
  }
  *out = v;
  return true;
}

bool ParseNumberList(std::string_view text, const NumberRange& range, bool unique,
                     std::vector<double>* out, std::string* error) {
  std::vector<double> values;
  if (Trim(text).empty()) {
    *error = "empty list; expected comma-separated numbers, each " + range.ToString();
    return false;
  }
  size_t start = 0;
  for (int item = 1;; ++item) {
    const size_t comma = text.find(',', start);
    const std::string_view cell = text.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (Trim(cell).empty()) {
      *error = "item " + std::to_string(item) + " of " + Quote(text) + " is empty (a stray comma?)";
      return false;
    }
    double v = 0;
    std::string e;
    if (!ParseNumber(cell, range, &v, &e)) {
      *error = "item " + std::to_string(item) + " of " + Quote(text) + ": " + e;
      return false;
    }
    if (unique) {
      for (double w : values) {
        if (w == v) {
          *error = Quote(text) + " lists " + FormatNumber(v) + " twice";
          return false;
        }
      }
    }
    values.push_back(v);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  *out = std::move(values);
  return true;
}

bool ParseNameList(std::string_view text, std::vector<std::string>* out, std::string* error) {
  std::vector<std::string> names;
  if (Trim(text).empty()) {
    *error = "empty list; expected comma-separated names";
    return false;
  }
  size_t start = 0;
  for (int item = 1;; ++item) {
    const size_t comma = text.find(',', start);
    const std::string_view cell = Trim(text.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (cell.empty()) {
      *error = "item " + std::to_string(item) + " of " + Quote(text) + " is empty (a stray comma?)";
      return false;
    }
    for (const std::string& earlier : names) {
      if (earlier == cell) {
        *error = Quote(text) + " lists " + Quote(cell) + " twice";
        return false;
      }
    }
    names.emplace_back(cell);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  *out = std::move(names);
  return true;
}

}  // namespace ssc
