// The simulation cost of each object: mean wall time of one mj_step in the object's probe scene
// (objects/object_mjcf.h) while the mocap cup, lip pressed onto the top face, slides along the
// edge from the trial's start. Figures, never pass/fail.
#ifndef SSC_STUDIES_OBJECT_STEP_COST_H_
#define SSC_STUDIES_OBJECT_STEP_COST_H_

#include <optional>
#include <string>

#include "objects/object_spec.h"

namespace ssc {

struct StepCostOptions {
  int warmup_steps = 200;
  int steps = 2000;          // timed steps (4 s at the 2 ms step)
  int repeats = 3;           // runs from the start; the fastest run's mean is reported, as
                             // other processes on a shared machine only ever add time
  double speed_m_s = 0.010;  // cup speed along the edge
  double press_m = 0.001;    // lip plane below the top face (about 1.5 N on a flat face)
};

struct StepCost {
  std::string object;
  int object_geoms = 0;  // geoms in group 2
  double step_us = 0;    // mean wall time per mj_step (fastest run)
  double contacts = 0;   // mean contacts per step
  double sim_s = 0;      // simulated time timed
};

// Loads `probe_scene` (written for `spec`) and measures; nullopt with *error on failure.
std::optional<StepCost> MeasureStepCost(const ObjectSpec& spec, const std::string& probe_scene,
                                        const StepCostOptions& options, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_OBJECT_STEP_COST_H_
