// The plain log format for anyone else's robot: one CSV file, one row per time, a header row
// naming the columns with their units. Columns are found by name, in any order:
//
//   t_s                      time, s (strictly increasing; any origin)              required
//   x_m, y_m, z_m            tool centre point in the scene frame, m                required
//   qw, qx, qy, qz           tool0 orientation in the scene frame (unit quaternion) required
//   p1_pa, p2_pa, p3_pa, p4_pa   chamber GAUGE vacuum, Pa, positive = vacuum,       required
//                            already offset-corrected and filtered as wanted
//   fx_n, fy_n, fz_n, tx_nm, ty_nm, tz_nm   F/T, N and N m                          optional, all 6
//   pwm_pct                  pump drive, percent                                    optional
//
// A column not in this list is refused (a typo or a unit the format does not take, such as
// p1_kpa, must not be read as garbage). Pressures above 80 kPa are refused as absolute, below
// -5 kPa as the opposite sign convention, and a log whose largest vacuum stays under 50 Pa as
// kPa (or a cup that never touched anything: nothing to compare). Times go through CheckClock
// (robot_log.h): ms written as s, or ns, are refused.
#ifndef SSC_ROBOTLOG_PLAIN_LOG_H_
#define SSC_ROBOTLOG_PLAIN_LOG_H_

#include <string>
#include <string_view>

#include "robotlog/log_types.h"

namespace ssc {

inline constexpr double kGaugeVacuumMaxPa = 80e3;  // above: an absolute pressure
inline constexpr double kGaugeVacuumMinPa = -5e3;  // below: vacuum written negative
inline constexpr double kPeakVacuumMinPa = 50;     // largest vacuum below this: kPa?

bool ParsePlainLog(std::string_view text, const std::string& file, ProcessedLog* log,
                   LoadError* error);
bool LoadPlainLog(const std::string& path, ProcessedLog* log, LoadError* error);

// Writes the required columns, plus F/T and PWM when `log` has them (one per sample), values in
// shortest round-trip form.
bool WritePlainLog(const std::string& path, const ProcessedLog& log, std::string* error);

}  // namespace ssc

#endif  // SSC_ROBOTLOG_PLAIN_LOG_H_
