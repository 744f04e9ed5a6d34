// Helpers shared by the object builders (objects/*_objects.cc): not part of the library's API.
#ifndef SSC_OBJECTS_SPEC_HELPERS_H_
#define SSC_OBJECTS_SPEC_HELPERS_H_

#include <string>

#include "objects/object_spec.h"

namespace ssc::spec_internal {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kMm = 1e-3;

inline Point2 W() { return {kWorkspaceX, kWorkspaceY}; }
Point2 Polar(const Point2& centre, double r, double angle_rad);
// "<prefix><value>": integers as %02d/%03d (width digits), other values with one decimal.
std::string ValueName(const char* prefix, double value, int width);

// Fills spec->outline from spec->edge and the trial setup for a start at arc position
// start_arc_m, inset_m inside the edge. Closed edges succeed by the swept angle about
// sweep_centre (sign from the walking sense), open ones at end_arc_m.
void FinishSpec(ObjectSpec* spec, double start_arc_m, double inset_m, const Point2& sweep_centre,
                double end_arc_m);

}  // namespace ssc::spec_internal

#endif  // SSC_OBJECTS_SPEC_HELPERS_H_
