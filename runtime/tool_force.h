// The F/T transducer's reading as a trial (its axial force) and the software-in-the-loop plant
// (the whole wrench) use it.
//
// For a tool whose lip is rigid bodies, MuJoCo's force sensor at the transducer's site reads it.
// For a tool whose lip is a 2-D flex (models/ssc_tool_flex.xml) it cannot: under the discrete
// integrator the skirt's elasticity lives in the step's metric, not in any force the sensor's
// recursion sums, so the sensor misses the load the skirt carries to the cup (it reads ~0 N while
// the lip is pressed 2 mm into an object). There the reading is the quasi-static balance instead:
// minus the contact forces on everything below the transducer (cup geoms and the skirt) and
// minus the chamber vacuums' pull on them (the pressure plugin's passive force), along the site's
// z axis; the whole wrench likewise, its torques about the site. The cup's own inertia and weight
// are left out (under 1 % of the 1.5 N band at the trial's accelerations; the weight is a
// constant offset, which readers tare).
#ifndef SSC_RUNTIME_TOOL_FORCE_H_
#define SSC_RUNTIME_TOOL_FORCE_H_

#include <mujoco/mujoco.h>

#include <array>

namespace ssc {

class ToolForceReader {
 public:
  // `force_sensor`: the transducer's force sensor (mjSENS_FORCE on its site); `torque_sensor`:
  // its torque sensor on the same site, -1 when the scene has none (Wrench's torques read 0 on a
  // rigid lip then).
  void Bind(const mjModel* m, int force_sensor, int torque_sensor = -1);
  // Takes the contact balance of a step just finished (mj_step or mj_forward): only then do the
  // contacts and their solved forces belong together (a control callback sees this step's
  // contacts beside the last step's forces). Nothing to do for a rigid lip.
  void Update(const mjModel* m, const mjData* d);
  // Force the transducer exerts on the cup along its site's z axis (N; pressing reads +): the
  // sensor, or for a flex lip the balance taken by the last Update.
  double Axial(const mjModel* m, const mjData* d) const;
  // Force (N) and torque about the site (N m) the transducer exerts on the cup, in the site's
  // frame (the sensors' frame: pressing reads +z): the sensors, or for a flex lip the balance.
  std::array<double, 6> Wrench(const mjData* d) const;
  bool from_contacts() const { return flex_ >= 0; }

 private:
  int sensor_adr_ = 0;
  int torque_adr_ = -1;
  int site_ = -1;
  int root_body_ = -1;  // the body below the transducer
  int flex_ = -1;       // the skirt, -1 when the tool has none
  double balance_n_ = 0.0;
  std::array<double, 6> balance_wrench_{};  // site frame
};

}  // namespace ssc

#endif  // SSC_RUNTIME_TOOL_FORCE_H_
