// The worked example of docs/controllers.md: a complete controller of one's own in C++.
#ifndef SSC_CONTROLLER_EXAMPLE_CONTROLLER_H_
#define SSC_CONTROLLER_EXAMPLE_CONTROLLER_H_

#include "controller/controller_registry.h"

namespace ssc {

ControllerType ExampleControllerType();

}  // namespace ssc

#endif  // SSC_CONTROLLER_EXAMPLE_CONTROLLER_H_
