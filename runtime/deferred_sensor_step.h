// mj_step with the acceleration-stage sensors evaluated only when asked for.
//
// mj_step evaluates every sensor at every step. The acceleration-stage ones (the F/T's force and
// torque) need mj_rnePostConstraint, about 4 % of a light-scene step, and a trial reads them only
// at its control iterations (one step in 75). Here a step runs in two parts:
// StepToAccSensors does all of mj_step up to those sensors (the checks, the position and velocity
// stages with their sensors, the control callback, actuation, the constraint solve) and
// FinishStep evaluates them when asked, then checks and integrates. The calls are mj_step's own,
// in its order (MuJoCo 4.0.0's mj_step and mj_forwardSkip), timers included. With the sensors
// asked for, mjData is bit for bit what mj_step leaves; without, only what those sensors and
// mj_rnePostConstraint write differs (their sensordata and cacc, cfrc_int, cfrc_ext keep the
// previous evaluation's values; flg_rnepost is 0): nothing in the physics reads them.
// (tests/runtime/trial_test.cc runs a trial both ways and compares every row and the final state.)
#ifndef SSC_RUNTIME_DEFERRED_SENSOR_STEP_H_
#define SSC_RUNTIME_DEFERRED_SENSOR_STEP_H_

#include <mujoco/mujoco.h>

namespace ssc {

// Whether `m` allows it: integrator Euler, implicit, implicitfast or discrete (RK4 runs forward
// passes of its own); no forward/inverse comparison (mjENBL_FWDINV); every
// acceleration-stage sensor built in (no plugin or user sensor) and without history, delay or
// interval; no mjcb_sensor installed. Otherwise use mj_step.
bool CanDeferAccSensors(const mjModel* m);

// The first part; returns the step timer's start, for FinishStep.
mjtNum StepToAccSensors(const mjModel* m, mjData* d);

// The second part: the acceleration-stage sensors when `acc_sensors`, then mj_checkAcc and the
// integrator.
void FinishStep(const mjModel* m, mjData* d, bool acc_sensors, mjtNum step_start);

}  // namespace ssc

#endif  // SSC_RUNTIME_DEFERRED_SENSOR_STEP_H_
