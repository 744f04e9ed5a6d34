// The topics of ssc_twin._core, each binding its part of the module (core.cc calls them).
#ifndef SSC_PYTHON_SRC_BINDING_TOPICS_H_
#define SSC_PYTHON_SRC_BINDING_TOPICS_H_

#include <nanobind/nanobind.h>

namespace ssc {

void BindTrials(nanobind::module_& m);   // trials.cc
void BindStudies(nanobind::module_& m);  // studies.cc
void BindLogs(nanobind::module_& m);     // logs.cc
void BindSil(nanobind::module_& m);      // sil.cc

}  // namespace ssc

#endif  // SSC_PYTHON_SRC_BINDING_TOPICS_H_
