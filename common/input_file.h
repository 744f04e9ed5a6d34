// One check for every file a user names as input (scenes, logs, maps, resumed CSVs), made
// before the file is opened: a FIFO or a device would block the reader or never end, and a
// directory or a missing file deserve their own message. Header-only (used by pure readers
// and fuzz targets that do not link the rest).
#ifndef SSC_COMMON_INPUT_FILE_H_
#define SSC_COMMON_INPUT_FILE_H_

#include <unistd.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace ssc {

// "" when `path` is a readable regular file (links followed); otherwise what it is instead:
// "no such file", "is a directory, expected a file", "is not a regular file (a FIFO, device or
// socket)", "cannot be read (no permission)". The caller prefixes the path.
inline std::string CheckInputFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    return fs::is_symlink(fs::symlink_status(path, ec))
               ? "no such file (a symbolic link to nothing)"
               : "no such file";
  }
  if (fs::is_directory(status)) return "is a directory, expected a file";
  if (!fs::is_regular_file(status)) {
    return "is not a regular file (a FIFO, device or socket): give the file itself";
  }
  if (::access(path.c_str(), R_OK) != 0) return "cannot be read (no permission)";
  return "";
}

// "" when `head` (the first bytes of a file) looks like UTF-8 or ASCII text; otherwise why not:
// UTF-16 (a byte-order mark or every other byte NUL), NUL bytes, or control bytes that no text
// file holds. The caller prefixes the path and says what text it expected.
inline std::string NonTextReason(std::string_view head) {
  if (head.size() >= 2 &&
      ((head[0] == '\xFF' && head[1] == '\xFE') || (head[0] == '\xFE' && head[1] == '\xFF'))) {
    return "is UTF-16 text (a byte-order mark FF FE or FE FF): save it as UTF-8";
  }
  size_t nul = 0, control = 0;
  for (char ch : head) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == 0)
      ++nul;
    else if (c < 0x20 && c != '\n' && c != '\r' && c != '\t')
      ++control;
  }
  if (nul > 0 && nul * 3 >= head.size()) {
    return "holds a NUL byte in every other or third byte: UTF-16 or binary, not UTF-8 text";
  }
  if (nul > 0) return "holds NUL bytes: a binary file, not text";
  if (control * 100 > head.size()) return "holds control bytes: a binary file, not text";
  return "";
}

// At most `max_chars` of `text` for a message: printable ASCII as is, other bytes as \xHH, so a
// binary file is never echoed raw to a terminal.
inline std::string ShownText(std::string_view text, size_t max_chars = 60) {
  std::string out;
  for (size_t i = 0; i < text.size() && i < max_chars; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789ABCDEF";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (text.size() > max_chars) out += "...";
  return out;
}

}  // namespace ssc

#endif  // SSC_COMMON_INPUT_FILE_H_
