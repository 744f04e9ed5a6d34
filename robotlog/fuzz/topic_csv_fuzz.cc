// libFuzzer target: the per-topic CSV reader must never crash, whatever the bytes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "robotlog/robot_log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<long long> t;
  std::vector<std::vector<double>> rows;
  ssc::LoadError error;
  static const std::vector<std::string> fields = {"ch", "P1", "P2", "P3", "P4"};
  if (!ssc::ParseTopicCsv(text, "fuzz.csv", fields, &t, &rows, &error)) {
    (void)error.ToString();
  }
  return 0;
}
