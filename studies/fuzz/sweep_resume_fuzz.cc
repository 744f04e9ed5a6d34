// libFuzzer target for the sweep-resume reader and the manifest (tools/fuzz_inputs.sh).
// Input: arbitrary bytes as a sweep CSV and as a sweep.json. Every row the reader keeps must be
// a whole line with the header's field count; it must never crash, hang or read out of bounds.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "studies/sweep_io.h"

namespace {
const char kHeader[] =
    "scene,pref_pa,beta,step_mm,repeat,seed,outcome,s_mm,r_mean_mm,dr_mm,sigma_r_mm,s_c,"
    "duration_s,speed_mm_s,speed_body_d_s,contour_mean_mm,contour_max_mm,swept_deg,"
    "iterations,sim_time_s,detail";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const ssc::SweepCsvContents c = ssc::ParseSweepCsv(text, kHeader);
  if (c.rows.size() != c.lines.size()) std::abort();
  for (const std::string& line : c.lines) {
    if (line.find('\n') != std::string::npos) std::abort();
    if (text.find(line) == std::string_view::npos) std::abort();
  }
  for (const ssc::SweepRowKey& k : c.rows) {
    if (!(k.pref_pa > 0) || k.beta < 0 || !(k.step_mm > 0) || k.repeat < 0) std::abort();
  }
  ssc::SweepManifest m;
  std::string error;
  if (ssc::ParseSweepManifest(text, &m, &error)) {
    ssc::SweepManifest back;
    if (!ssc::ParseSweepManifest(ssc::SweepManifestJson(m), &back, &error) || back != m)
      std::abort();
    (void)ssc::CompareSweepManifests(m, back);
  }
  return 0;
}
