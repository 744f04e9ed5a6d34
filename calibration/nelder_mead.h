// Nelder-Mead simplex minimisation (pure C++), for calibrations with a few parameters.
#ifndef SSC_CALIBRATION_NELDER_MEAD_H_
#define SSC_CALIBRATION_NELDER_MEAD_H_

#include <functional>
#include <vector>

namespace ssc {

struct NelderMeadResult {
  std::vector<double> x;
  double value = 0;
  int evaluations = 0;
  bool converged = false;
};

// Minimises f from x0 with initial simplex steps `step` (one per coordinate); stops when the
// simplex's value spread falls below `tolerance` or after `max_evaluations`.
NelderMeadResult NelderMead(const std::function<double(const std::vector<double>&)>& f,
                            const std::vector<double>& x0, const std::vector<double>& step,
                            double tolerance = 1e-8, int max_evaluations = 2000);

}  // namespace ssc

#endif  // SSC_CALIBRATION_NELDER_MEAD_H_
