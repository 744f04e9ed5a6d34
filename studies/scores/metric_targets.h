// The published scores a twin run is read against besides the success map: the Fig. 6 targets at
// dL 5 mm (dr against P_ref; sigma_r and s_c against beta) and the published outcomes beside the
// map. Shared by `ssc validate` and the dynamic fit (neither includes the other for them).
#ifndef SSC_STUDIES_SCORES_METRIC_TARGETS_H_
#define SSC_STUDIES_SCORES_METRIC_TARGETS_H_

#include <limits>
#include <string>
#include <vector>

#include "studies/scores/map_scores.h"

namespace ssc {

// One Fig. 6 target at dL 5 mm (the map's cells; metrics of the successful trials).
struct MetricTarget {
  std::string name;  // e.g. "dr_mm beta 1.5 P_ref 40"
  double beta, pref_pa;
  enum Metric { kDr, kSigmaR, kSc } metric;
  double published, tolerance;
  double model = 0;   // the twin's mean over successful trials (NaN if none succeeded)
  int successes = 0;  // the successful trials the mean is over
  // Standard error of that mean, sample sd / sqrt(n) (NaN below 2 successes): the mean's
  // uncertainty from the seeds, to weigh against the tolerance.
  double standard_error = std::numeric_limits<double>::quiet_NaN();
};
std::vector<MetricTarget> PublishedMetricTargets();
// Fills each target's model and successes from the trials of the cells at dL 5 mm with its beta
// and P_ref (results[i] are cells[i]'s trials); a target whose cell is absent or never succeeded
// gets NaN and 0.
void MeasureMetricTargets(const std::vector<MapCell>& cells,
                          const std::vector<std::vector<MapTrial>>& results,
                          std::vector<MetricTarget>* targets);
// The published outcomes beside the map (calibration targets in smart-suction-cup.md): the pilot
// controller (P_ref 70, beta 1, dL 2.5 mm) succeeds; P_ref 100, beta 2 succeeds 3/3 at dL 2.5,
// 5 and 7.5 mm; and beta 0.5 fails (at P_ref 100, dL 2.5 and 7.5 mm: "beta <= 0.5 always
// failed"). The fit scores them like map cells.
std::vector<MapCell> PublishedOutcomeCells();

}  // namespace ssc

#endif  // SSC_STUDIES_SCORES_METRIC_TARGETS_H_
