// A point (or vector) in the plane, world metres unless a name says otherwise.
#ifndef SSC_GEOMETRY_POINT2_H_
#define SSC_GEOMETRY_POINT2_H_

#include <array>

namespace ssc {

using Point2 = std::array<double, 2>;

}  // namespace ssc

#endif  // SSC_GEOMETRY_POINT2_H_
