// A test process's scratch folder: <temp>/ssc_test_<pid>, made on first use and removed with
// everything in it when the process exits, so a test run leaves nothing in the temp directory.
#ifndef SSC_TESTS_SCRATCH_DIR_H_
#define SSC_TESTS_SCRATCH_DIR_H_

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace ssc {

inline const std::filesystem::path& ScratchDir() {
  struct Dir {
    std::filesystem::path path;
    int owner_pid;
    Dir()
        : path(std::filesystem::temp_directory_path() / ("ssc_test_" + std::to_string(::getpid()))),
          owner_pid(::getpid()) {
      std::filesystem::create_directories(path);
    }
    ~Dir() {
      std::error_code ec;
      if (::getpid() == owner_pid) std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

}  // namespace ssc

#endif  // SSC_TESTS_SCRATCH_DIR_H_
