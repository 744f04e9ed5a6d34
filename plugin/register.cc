#include <mujoco/mujoco.h>

#include "plugin/chamber_pressure_sensor.h"
#include "plugin/mujoco_messages.h"

namespace ssc {

mjPLUGIN_LIB_INIT(ssc_plugin) {
  RegisterChamberPressurePlugin();
  InstallMuJoCoMessageHandlers();  // no MUJOCO_LOG.TXT in the host's working directory
}

}  // namespace ssc
