// One check for every file a user names as input (scenes, logs, maps, resumed CSVs), made
// before the file is opened: a FIFO or a device would block the reader or never end, and a
// directory or a missing file deserve their own message. Header-only (used by pure readers
// and fuzz targets that do not link the rest).
#ifndef SSC_COMMON_INPUT_FILE_H_
#define SSC_COMMON_INPUT_FILE_H_

#include <unistd.h>

#include <filesystem>
#include <string>
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

}  // namespace ssc

#endif  // SSC_COMMON_INPUT_FILE_H_
