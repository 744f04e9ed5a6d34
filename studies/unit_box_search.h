// A derivative-free NLopt search over the unit box [0, 1]^n, the one both parameter fits share
// (success_map_fit: the robot effects; controller_tune: a controller's keys). Each caller maps
// the box onto its own parameter ranges and keeps its own record of the evaluations.
#ifndef SSC_STUDIES_UNIT_BOX_SEARCH_H_
#define SSC_STUDIES_UNIT_BOX_SEARCH_H_

#include <functional>
#include <string>
#include <vector>

namespace ssc {

// "bobyqa" (the default for any other name), "sbplx" or "cobyla".
struct UnitBoxSearch {
  std::string algorithm = "bobyqa";
  int max_evaluations = 12;
  double initial_step = 0.25;  // a quarter of each range
};

// Minimises `cost` from `x0`. `cost` may throw nlopt::forced_stop to end the search (an
// evaluation that failed): then false. Reaching the budget or NLopt's round-off ends it with true;
// the callers' own records hold every evaluation either way.
bool MinimiseOnUnitBox(const UnitBoxSearch& search, const std::vector<double>& x0,
                       const std::function<double(const std::vector<double>&)>& cost);

}  // namespace ssc

#endif  // SSC_STUDIES_UNIT_BOX_SEARCH_H_
