#include "studies/scores/metric_targets.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibration/published_targets.h"
#include "trial/trial_outcome.h"

namespace ssc {

std::vector<MetricTarget> PublishedMetricTargets() {
  // calibration/published_targets.h; tolerances 0.3 mm and 5 points of s_c.
  auto name = [](const char* metric, double beta, double pref) {
    std::ostringstream os;
    os << metric << " beta " << beta << " P_ref " << pref;
    return os.str();
  };
  std::vector<MetricTarget> targets;
  for (std::size_t i = 0; i < kPublishedDepthMm.size(); ++i) {
    targets.push_back({name("dr_mm", kPublishedDepthBeta, kPublishedDepthPrefPa[i]),
                       kPublishedDepthBeta, kPublishedDepthPrefPa[i], MetricTarget::kDr,
                       -kPublishedDepthMm[i], 0.3});
  }
  for (const PublishedWander& w : kPublishedWander) {
    if (w.sigma_r_mm < 0) continue;
    targets.push_back({name("sigma_r_mm", w.beta, kPublishedWanderPrefPa), w.beta,
                       kPublishedWanderPrefPa, MetricTarget::kSigmaR, w.sigma_r_mm, 0.3});
  }
  for (const PublishedWander& w : kPublishedWander) {
    targets.push_back({name("s_c", w.beta, kPublishedWanderPrefPa), w.beta, kPublishedWanderPrefPa,
                       MetricTarget::kSc, w.s_c, 0.05});
  }
  return targets;
}

std::vector<MapCell> PublishedOutcomeCells() {
  return {{2.5, 1.0, 70, MapClass::kThreeOfThree},
          {2.5, 2.0, 100, MapClass::kThreeOfThree},
          {7.5, 2.0, 100, MapClass::kThreeOfThree},
          // issue #11, "what the robot did": beta <= 0.5 always failed (at every step).
          {2.5, 0.5, 100, MapClass::kAtMostOne},
          {7.5, 0.5, 100, MapClass::kAtMostOne}};
}

void MeasureMetricTargets(const std::vector<MapCell>& cells,
                          const std::vector<std::vector<MapTrial>>& results,
                          std::vector<MetricTarget>* targets) {
  for (MetricTarget& t : *targets) {
    double sum = 0, sum_sq = 0;
    int n = 0;
    for (std::size_t i = 0; i < cells.size() && i < results.size(); ++i) {
      if (cells[i].step_mm != 5.0 || cells[i].beta != t.beta || cells[i].pref_pa != t.pref_pa)
        continue;
      for (const MapTrial& r : results[i]) {
        if (r.outcome != OutcomeName(Outcome::kSuccess)) continue;
        const double v = t.metric == MetricTarget::kDr
                             ? r.dr_mm
                             : (t.metric == MetricTarget::kSigmaR ? r.sigma_r_mm : r.s_c);
        sum += v;
        sum_sq += v * v;
        ++n;
      }
    }
    t.model = n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
    t.successes = n;
    t.standard_error = std::numeric_limits<double>::quiet_NaN();
    if (n >= 2) {
      const double variance = std::max(0.0, (sum_sq - sum * sum / n) / (n - 1));
      t.standard_error = std::sqrt(variance / n);
    }
  }
}

}  // namespace ssc
