// libFuzzer target: whatever the bytes, the readers return a result and never crash, hang,
// leak or hit undefined behaviour. The first byte picks the topic; the rest is the file text,
// parsed as that topic, as a plain log, and (when it parses) processed as a pressure stream.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "robotlog/robot_log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const ssc::StreamSpec& spec = ssc::AllStreamSpecs()[data[0] % 4];
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  ssc::TopicTable table;
  ssc::LoadError error;
  if (ssc::ParseTopicCsv(text, "fuzz.csv", spec, &table, &error) &&
      spec.id == ssc::StreamId::kPressure) {
    // A log with this pressure stream and a still pose: validation and processing must cope.
    ssc::RobotLog log;
    log.t0_ns = table.t_ns.front();
    for (size_t i = 0; i < table.t_ns.size(); ++i) {
      log.pressure_abs.t_s.push_back(static_cast<double>(table.t_ns[i] - log.t0_ns) * 1e-9);
    }
    log.pressure_abs.rows = table.rows;
    log.pressure_abs.lines = table.lines;
    log.tool_pose.t_s = log.pressure_abs.t_s;
    log.tool_pose.rows.assign(table.rows.size(), {1, 0, 0, 0, 0.5, 0, 0.3});
    ssc::ProcessedLog processed;
    (void)ssc::ProcessRobotLog(log, ssc::ProcessOptions(), &processed, &error);
  }
  (void)error.ToString();
  ssc::ProcessedLog plain;
  if (!ssc::ParsePlainLog(text, "fuzz_plain.csv", &plain, &error)) (void)error.ToString();
  return 0;
}
