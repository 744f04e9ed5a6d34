#include "robotlog/text_cells.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

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

bool ReadWholeFile(const std::string& path, std::string* contents, LoadError* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    SetError(error, path, 0, 0, "no such file");
    return false;
  }
  if (fs::is_directory(status)) {
    SetError(error, path, 0, 0, "is a directory, expected a file");
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    SetError(error, path, 0, 0, "cannot open the file for reading");
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  if (f.bad()) {
    SetError(error, path, 0, 0, "read error");
    return false;
  }
  *contents = ss.str();
  return true;
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
