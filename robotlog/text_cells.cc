#include "robotlog/text_cells.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "common/input_file.h"

namespace ssc::text {

std::string_view Trim(std::string_view s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

NumberParse ParseDouble(std::string_view cell, double* value) {
  std::string_view t = Trim(cell);
  if (t.empty()) return NumberParse::kEmpty;
  // from_chars takes no leading '+'; a writer may still put one there.
  if (t.front() == '+' && t.size() > 1 && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  const char* end = t.data() + t.size();
  const std::from_chars_result r = std::from_chars(t.data(), end, *value);
  if (r.ec == std::errc::result_out_of_range && r.ptr == end) return NumberParse::kNonFinite;
  if (r.ec != std::errc() || r.ptr != end) return NumberParse::kNotANumber;
  return std::isfinite(*value) ? NumberParse::kOk : NumberParse::kNonFinite;
}

bool ParseInt64(std::string_view cell, long long* value) {
  std::string_view t = Trim(cell);
  if (t.size() > 1 && t.front() == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  if (t.empty()) return false;
  const char* end = t.data() + t.size();
  const std::from_chars_result r = std::from_chars(t.data(), end, *value);
  return r.ec == std::errc() && r.ptr == end;
}

std::vector<std::string_view> SplitCells(std::string_view line) {
  std::vector<std::string_view> cells;
  while (true) {
    const size_t comma = line.find(',');
    cells.push_back(line.substr(0, comma));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return cells;
}

std::string Quote(std::string_view cell) {
  constexpr size_t kMaxShown = 24;
  std::string out = "'";
  for (size_t i = 0; i < cell.size() && i < kMaxShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(cell[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\x%02X", static_cast<unsigned>(c));
      out += buf;
    }
  }
  if (cell.size() > kMaxShown) out += "...";
  return out + "'";
}

bool CheckReadableFile(const std::string& path, LoadError* error) {
  if (const std::string why = CheckInputFile(path); !why.empty()) {
    SetError(error, path, 0, 0, why);
    return false;
  }
  return true;
}

bool ForEachFileLine(const std::string& path, const std::function<bool(int, std::string_view)>& fn,
                     LoadError* error, bool* stopped, int* torn_last) {
  if (stopped != nullptr) *stopped = false;
  if (torn_last != nullptr) *torn_last = 0;
  if (!CheckReadableFile(path, error)) return false;
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    SetError(error, path, 0, 0, "cannot open the file for reading");
    return false;
  }
  // One buffer of bounded size: a line longer than kMaxLineBytes is refused before more of it
  // is read, so memory stays O(kMaxLineBytes) whatever the file holds.
  std::string line;
  line.reserve(4096);
  int line_no = 0;
  bool first = true;
  std::vector<char> chunk(1 << 16);
  auto deliver = [&]() {
    std::string_view v(line);
    if (first && v.substr(0, 3) == "\xEF\xBB\xBF") v.remove_prefix(3);
    first = false;
    if (!v.empty() && v.back() == '\r') v.remove_suffix(1);
    if (line_no < 0x7fffffff) ++line_no;
    return fn(line_no, v);
  };
  while (f) {
    f.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const size_t got = static_cast<size_t>(f.gcount());
    size_t from = 0;
    while (from < got) {
      const void* nl = std::memchr(chunk.data() + from, '\n', got - from);
      const size_t end =
          nl ? static_cast<size_t>(static_cast<const char*>(nl) - chunk.data()) : got;
      if (line.size() + (end - from) > kMaxLineBytes) {
        SetError(error, path, line_no + 1, 0,
                 "line longer than " + std::to_string(kMaxLineBytes / 1024) +
                     " KiB: not a log file (a log row is under 1 kB)");
        return false;
      }
      line.append(chunk.data() + from, end - from);
      if (!nl) break;
      if (!deliver()) {
        if (stopped != nullptr) *stopped = true;
        return true;
      }
      line.clear();
      from = end + 1;
    }
  }
  if (f.bad()) {
    SetError(error, path, line_no + 1, 0, "read error");
    return false;
  }
  if (line.empty()) return true;
  if (torn_last != nullptr && line_no >= 1) {
    *torn_last = line_no + 1;
    return true;
  }
  if (!deliver() && stopped != nullptr) *stopped = true;
  return true;
}

std::string PyFloat(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  // Shortest round-trip digits, then Python's layout: fixed for exponents -4..15, else
  // d.ddde+XX with at least two exponent digits.
  char buf[40];
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::scientific);
  const std::string sci(buf, r.ptr);
  const size_t e = sci.find('e');
  const int exp = std::atoi(sci.c_str() + e + 1);
  std::string digits;
  const bool negative = sci[0] == '-';
  for (size_t i = negative ? 1 : 0; i < e; ++i) {
    if (sci[i] != '.') digits += sci[i];
  }
  std::string out = negative ? "-" : "";
  if (exp >= -4 && exp < 16) {
    if (exp < 0) {
      out += "0." + std::string(static_cast<size_t>(-exp - 1), '0') + digits;
    } else if (static_cast<int>(digits.size()) <= exp + 1) {
      out += digits + std::string(static_cast<size_t>(exp + 1) - digits.size(), '0') + ".0";
    } else {
      out += digits.substr(0, static_cast<size_t>(exp + 1)) + "." +
             digits.substr(static_cast<size_t>(exp + 1));
    }
    return out;
  }
  out += digits.substr(0, 1);
  if (digits.size() > 1) out += "." + digits.substr(1);
  char exp_buf[16];
  std::snprintf(exp_buf, sizeof(exp_buf), "e%c%02d", exp < 0 ? '-' : '+', std::abs(exp));
  return out + exp_buf;
}

void SetError(LoadError* error, const std::string& file, int line, int column,
              const std::string& message) {
  error->file = file;
  error->line = line;
  error->column = column;
  error->message = message;
}

std::string FormatDouble(double v) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

int ToInt(size_t n) { return n > 0x7fffffff ? 0x7fffffff : static_cast<int>(n); }

}  // namespace ssc::text
