#include "apps/ssc/trial_options.h"

#include <cmath>

namespace ssc {

std::vector<cli::Option> TrialSettingOptions() {
  const TrialConfig d;
  auto num = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%g", v);
    return std::string(buf);
  };
  return {
      {"period", num(d.control_period_s), "control iteration period, s"},
      {"smoothing", num(d.servo.smoothing_s), "servo look-ahead smoothing time constant, s"},
      {"timeout", num(d.timeout_s), "follow-phase time limit, simulated s"},
      {"approach-force", num(d.approach_force_n), "start-up compression read on the F/T, N"},
      {"start-offset", "32", "disk: start point distance east of the disk centre, mm"},
      {"pn", num(d.law.p_noise_pa), "P_n: noise level, c_f = +beta here and dead band, Pa"},
      {"pg", num(d.law.p_grasp_pa), "P_g in the c_f line, Pa"},
      {"off-edge", num(d.thresholds.off_edge_pa), "failure I below this mean vacuum, Pa"},
      {"grasp", num(d.thresholds.grasp_pa), "failure II when all chambers exceed this, Pa"},
      {"sweep-deg", num(d.target.success_sweep_deg), "disk: success when the swept angle passes, deg"},
      {"object-on", "left", "object on the 'left' (CCW around a disk) or 'right' of the motion"},
      {"no-dead-band", "", "take a step even when both differentials are below P_n", true},
  };
}

bool ReadTrialSettings(cli::Parser* p, TrialConfig* c, std::string* error) {
  double offset_mm = 0;
  if (!p->GetDouble("period", &c->control_period_s) ||
      !p->GetDouble("smoothing", &c->servo.smoothing_s) ||
      !p->GetDouble("timeout", &c->timeout_s) ||
      !p->GetDouble("approach-force", &c->approach_force_n) ||
      !p->GetDouble("start-offset", &offset_mm) || !p->GetDouble("pn", &c->law.p_noise_pa) ||
      !p->GetDouble("pg", &c->law.p_grasp_pa) ||
      !p->GetDouble("off-edge", &c->thresholds.off_edge_pa) ||
      !p->GetDouble("grasp", &c->thresholds.grasp_pa) ||
      !p->GetDouble("sweep-deg", &c->target.success_sweep_deg)) {
    *error = p->error();
    return false;
  }
  const double sweep = c->target.success_sweep_deg;
  c->target = TrialTarget::Disk(0.65, 0.0, 0.035, offset_mm * 1e-3);
  c->target.success_sweep_deg = sweep;
  const std::string side = p->Get("object-on");
  if (side == "left") {
    c->law.side = FollowSide::kObjectOnLeft;
  } else if (side == "right") {
    c->law.side = FollowSide::kObjectOnRight;
  } else {
    *error = "--object-on must be 'left' or 'right', got '" + side + "'";
    return false;
  }
  c->law.dead_band = !p->Flag("no-dead-band");
  return true;
}

}  // namespace ssc
