#include <mujoco/mujoco.h>

#include "plugin/chamber_pressure_sensor.h"

namespace ssc {

mjPLUGIN_LIB_INIT(ssc_plugin) { RegisterChamberPressurePlugin(); }

}  // namespace ssc
