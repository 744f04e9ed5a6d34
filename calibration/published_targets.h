// The robot's published figures the twin is fitted to and scored against, one home each
// (shared/reference: the paper's disk trials, Fig. 6; means of three trials at dL 5 mm and
// P_ref 100 Pa unless a row names another). The success map itself is data/published/.
#ifndef SSC_CALIBRATION_PUBLISHED_TARGETS_H_
#define SSC_CALIBRATION_PUBLISHED_TARGETS_H_

#include <array>

namespace ssc {

// Where the cup rode at beta 1.5: the published dr at three P_ref, as depth inside the disk
// edge (mm, -dr).
inline constexpr double kPublishedDepthBeta = 1.5;
inline constexpr std::array<double, 3> kPublishedDepthPrefPa = {40, 100, 200};
inline constexpr std::array<double, 3> kPublishedDepthMm = {0.7, 2.5, 3.2};

// The differential |(dPx, dPy)| at a mean vacuum of 100 Pa, Pa.
inline constexpr double kPublishedDifferentialAt100PaPa = 200;

// The wander and the extra travel against beta at P_ref 100 Pa: sigma_r (mm) and s_c (the
// path's length over the edge's, minus one). sigma_r is not published at beta 2.5.
inline constexpr double kPublishedWanderPrefPa = 100;
struct PublishedWander {
  double beta;
  double sigma_r_mm;  // < 0: not published
  double s_c;
};
inline constexpr std::array<PublishedWander, 3> kPublishedWander = {
    {{1.5, 1.36, 0.11}, {2.5, -1, 0.21}, {3.5, 1.89, 0.31}}};

}  // namespace ssc

#endif  // SSC_CALIBRATION_PUBLISHED_TARGETS_H_
