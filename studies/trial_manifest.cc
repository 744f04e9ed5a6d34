#include "studies/trial_manifest.h"

#include <cstdio>
#include <vector>

#include "common/strict_number.h"
#include "runtime/rig.h"
#include "trial/robot_effects.h"

namespace ssc {

SweepManifest TrialManifest(const mjModel* m, const std::string& scene, const TrialConfig& c) {
  auto num = [](double v) { return FormatNumber(v); };
  std::vector<unsigned char> buffer(static_cast<size_t>(mj_sizeModel(m)));
  mj_saveModel(m, nullptr, buffer.data(), static_cast<int>(buffer.size()));
  char hash[32];
  std::snprintf(hash, sizeof(hash), "%016llx",
                static_cast<unsigned long long>(Fnv1a64(buffer.data(), buffer.size())));
  SweepManifest manifest = {
      {"scene", scene},
      {"default_scene", DefaultScene()},
      {"model_hash", hash},
      {"timeout_s", num(c.timeout_s)},
      {"control_period_s", num(c.control_period_s)},
      {"smoothing_s", num(c.servo.smoothing_s)},
      {"servo_damping", num(c.servo.damping)},
      {"approach_force_n", num(c.approach_force_n)},
      {"start_x_m", num(c.target.start[0])},
      {"start_y_m", num(c.target.start[1])},
      {"landing_x_m", num(c.target.approach[0])},
      {"landing_y_m", num(c.target.approach[1])},
      {"p_noise_pa", num(c.law.p_noise_pa)},
      {"p_grasp_pa", num(c.law.p_grasp_pa)},
      {"object_on", c.law.side == FollowSide::kObjectOnRight ? "right" : "left"},
      {"dead_band", c.law.dead_band ? "on" : "off"},
      {"off_edge_pa", num(c.thresholds.off_edge_pa)},
      {"grasp_pa", num(c.thresholds.grasp_pa)},
      {"goal_sweep_deg", num(c.target.goal.sweep_deg)},
      {"goal_band_m", num(c.target.goal.band_m)},
      {"effects", FormatRobotEffects(c.effects)}};
  // Recorded only for another controller than the published law, so that the published law's
  // manifests stay as they were.
  if (!c.controller.IsPublished()) manifest["controller"] = c.controller.Text();
  return manifest;
}

}  // namespace ssc
