// ssc bench: runs the separate benchmark binary that sits next to ssc.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/ssc/commands.h"

namespace ssc {

int RunBench(int argc, char** argv) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string bench = (self.parent_path() / "ssc_bench").string();
  std::vector<char*> args;
  args.push_back(const_cast<char*>(bench.c_str()));
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  execv(bench.c_str(), args.data());
  std::fprintf(stderr, "ssc bench: cannot run %s (build the ssc_bench target)\n", bench.c_str());
  return 1;
}

}  // namespace ssc
