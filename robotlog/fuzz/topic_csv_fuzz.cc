// libFuzzer target: whatever the bytes, the readers return a result and never crash, hang,
// leak or hit undefined behaviour. The bytes are parsed as a lab topic file and as a plain log;
// a topic file that parses as /SensorPacket is validated and processed with a still pose.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "robotlog/robot_log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ssc::TopicTable table;
  ssc::LoadError error;
  if (ssc::ParseTopicCsv(text, "fuzz.csv", &table, &error) && table.header.topic != nullptr &&
      table.header.topic->id == ssc::StreamId::kPressure) {
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
