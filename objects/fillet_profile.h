// The variable fillet's radius along its 180 mm edge: a monotone cubic (Fritsch-Carlson)
// through the published cross-sections 0, 4.7, 10.4, 14.5 and 16.0 mm at 0, 45, 90, 135 and
// 180 mm. Monotone so the radius never shrinks between stations; C1 so the surface has no kinks.
// Pure C++.
#ifndef SSC_OBJECTS_FILLET_PROFILE_H_
#define SSC_OBJECTS_FILLET_PROFILE_H_

#include <array>

namespace ssc {

inline constexpr double kFilletEdgeLengthM = 0.180;
inline constexpr std::array<double, 5> kFilletStationsM = {0.0, 0.045, 0.090, 0.135, 0.180};
inline constexpr std::array<double, 5> kFilletRadiiM = {0.0, 0.0047, 0.0104, 0.0145, 0.0160};

// Fillet radius (m) at x_m along the edge from its sharp end; constant beyond the ends.
double FilletRadius(double x_m);

}  // namespace ssc

#endif  // SSC_OBJECTS_FILLET_PROFILE_H_
