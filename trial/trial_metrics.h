// Trajectory metrics of a trial (the published ones): path length s, mean radius r, dr, radial
// standard deviation sigma_r, relative travel s_c, duration and speed, and the distance of the
// cup-centre path from the true contour. Pure C++.
#ifndef SSC_TRIAL_TRIAL_METRICS_H_
#define SSC_TRIAL_TRIAL_METRICS_H_

#include <array>
#include <functional>
#include <vector>

#include "geometry/dimensions.h"
#include "geometry/point2.h"

namespace ssc {

struct DiskTrialMetrics {
  double s_mm = 0;        // path length
  double r_mean_mm = 0;   // mean distance from the centre
  double dr_mm = 0;       // r_mean - R
  double sigma_r_mm = 0;  // standard deviation of the radius about r_mean
  double s_c = 0;         // s / (2 pi R) - 1
  double duration_s = 0;
  double speed_mm_s = 0;       // s / duration
  double speed_body_d_s = 0;   // speed in cup body diameters (23 mm) per second
  double contour_mean_mm = 0;  // mean distance from the true contour
  double contour_max_mm = 0;   // max distance from the true contour
};

// Unsigned distance (m) of a point from the true contour.
using ContourDistance = std::function<double(double x_m, double y_m)>;

// Path in metres (world x/y), times in seconds; centre and radius of the disk in metres.
DiskTrialMetrics ComputeDiskMetrics(const std::vector<Point2>& path_m,
                                    const std::vector<double>& t_s, const Point2& centre_m,
                                    double radius_m);

// Path length (m) of a polyline.
double PathLength(const std::vector<Point2>& path_m);

// Mean and max of the contour distance over the path points (m).
std::array<double, 2> ContourError(const std::vector<Point2>& path_m, const ContourDistance& dist);

}  // namespace ssc

#endif  // SSC_TRIAL_TRIAL_METRICS_H_
