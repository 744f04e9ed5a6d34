// Runs the project's matplotlib scripts (tools/*.py) with the project venv's Python.
#ifndef SSC_APPS_SSC_PLOTTING_H_
#define SSC_APPS_SSC_PLOTTING_H_

#include <string>
#include <vector>

namespace ssc {

// Returns true on success; prints a one-line reason and returns false otherwise.
bool RunPlotScript(const std::string& script, const std::vector<std::string>& args);

}  // namespace ssc

#endif  // SSC_APPS_SSC_PLOTTING_H_
