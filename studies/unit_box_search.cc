#include "studies/unit_box_search.h"

#include <nlopt.hpp>

namespace ssc {

bool MinimiseOnUnitBox(const UnitBoxSearch& search, const std::vector<double>& x0,
                       const std::function<double(const std::vector<double>&)>& cost) {
  const nlopt::algorithm algorithm = search.algorithm == "sbplx"    ? nlopt::LN_SBPLX
                                     : search.algorithm == "cobyla" ? nlopt::LN_COBYLA
                                                                    : nlopt::LN_BOBYQA;
  const std::size_t n = x0.size();
  nlopt::opt opt(algorithm, static_cast<unsigned>(n));
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_maxeval(search.max_evaluations);
  opt.set_initial_step(std::vector<double>(n, search.initial_step));
  opt.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* data) {
        return (*static_cast<const std::function<double(const std::vector<double>&)>*>(data))(x);
      },
      const_cast<std::function<double(const std::vector<double>&)>*>(&cost));
  std::vector<double> x = x0;
  double f = 0;
  try {
    opt.optimize(x, f);
  } catch (const nlopt::forced_stop&) {
    return false;
  } catch (const std::exception&) {
    // Budget reached or round-off: the caller's record already holds every evaluation.
  }
  return true;
}

}  // namespace ssc
