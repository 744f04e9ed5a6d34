#include "runtime/deferred_sensor_step.h"

namespace ssc {
namespace {

// MuJoCo's timers read the clock only when mjcb_time is set.
mjtNum TimerNow() { return mjcb_time ? mjcb_time() : 0; }

bool Enabled(const mjModel* m, int flag) { return (m->opt.enableflags & flag) != 0; }

}  // namespace

bool CanDeferAccSensors(const mjModel* m) {
  const int integrator = m->opt.integrator;
  if (integrator != mjINT_EULER && integrator != mjINT_IMPLICIT &&
      integrator != mjINT_IMPLICITFAST && integrator != mjINT_DISCRETE) {
    return false;
  }
  if (Enabled(m, mjENBL_FWDINV) || mjcb_sensor != nullptr) return false;
  for (int i = 0; i < m->nsensor; ++i) {
    if (m->sensor_needstage[i] != mjSTAGE_ACC) continue;
    const int type = m->sensor_type[i];
    if (type == mjSENS_PLUGIN || type == mjSENS_USER) return false;
    if (m->sensor_historyadr[i] >= 0 || m->sensor_delay[i] != 0 || m->sensor_interval[2 * i] != 0) {
      return false;
    }
  }
  return true;
}

mjtNum StepToAccSensors(const mjModel* m, mjData* d) {
  const mjtNum step_start = TimerNow();
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  // mj_forwardSkip's position and velocity stages with their sensors and energy terms, timed into
  // its timer; mj_forwardSkip itself then runs the rest without sensors and counts the pass.
  const mjtNum forward_start = TimerNow();
  mj_fwdPosition(m, d);
  mj_sensorPos(m, d);
  if (!d->flg_energypos) {
    if (Enabled(m, mjENBL_ENERGY)) {
      mj_energyPos(m, d);
    } else {
      d->energy[0] = d->energy[1] = 0;
    }
  }
  mj_fwdVelocity(m, d);
  mj_sensorVel(m, d);
  if (Enabled(m, mjENBL_ENERGY) && !d->flg_energyvel) mj_energyVel(m, d);
  d->timer[mjTIMER_FORWARD].duration += TimerNow() - forward_start;
  // The control callback, actuation, acceleration and the constraint solve.
  mj_forwardSkip(m, d, mjSTAGE_VEL, /*skipsensor=*/1);
  return step_start;
}

void FinishStep(const mjModel* m, mjData* d, bool acc_sensors, mjtNum step_start) {
  d->flg_rnepost = 0;  // as mj_forwardSkip: mj_rnePostConstraint is evaluated lazily
  if (acc_sensors) {
    const mjtNum sensor_start = TimerNow();
    mj_sensorAcc(m, d);
    d->timer[mjTIMER_FORWARD].duration += TimerNow() - sensor_start;
  }
  mj_checkAcc(m, d);
  if (m->opt.integrator == mjINT_EULER) {
    mj_Euler(m, d);
  } else if (m->opt.integrator == mjINT_DISCRETE) {
    // The discrete map's acceleration comes from the forward pass (its constraint solve in the
    // effective metric); mj_step then advances it explicitly (qvel += h qacc, then positions),
    // which is mj_Euler's branch without its implicit damping. A shallow copy of the model
    // (every array shared, read only) with that damping off takes it.
    mjModel explicit_advance = *m;
    explicit_advance.opt.disableflags |= mjDSBL_EULERDAMP;
    mj_Euler(&explicit_advance, d);
  } else {
    mj_implicit(m, d);
  }
  d->timer[mjTIMER_STEP].duration += TimerNow() - step_start;
  ++d->timer[mjTIMER_STEP].number;
}

}  // namespace ssc
