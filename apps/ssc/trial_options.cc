#include "apps/ssc/trial_options.h"

#include <cstdio>

#include "common/exit_codes.h"

namespace ssc {

void AddLawOptions(cli::Command* cmd, ContourLawParams* law) {
  cmd->Number("pref", &law->p_ref_pa, "P_ref, set point of the mean vacuum (between P_n and P_g)",
              "Pa", NumberRange::Positive(1e6).OpenHigh());
  cmd->Number("beta", &law->beta, "beta, correction gain (dimensionless)", "",
              NumberRange::Closed(0, 100));
  cmd->Number("step", &law->step_mm, "step length dL per control iteration", "mm",
              NumberRange::Closed(kMinStepMm, kMaxStepMm));
}

void AddTrialSettingOptions(cli::Command* cmd, TrialConfig* c, TrialSettings* s) {
  s->sweep_deg = c->target.goal.sweep_deg;
  cmd->Number("period", &c->control_period_s, "control iteration period", "s",
              NumberRange::Closed(0.002, 10));
  cmd->Number("smoothing", &c->servo.smoothing_s, "servo look-ahead smoothing time constant", "s",
              NumberRange::Closed(0, 5));
  cmd->Number("damping", &c->servo.damping,
              "servo damping ratio of a second-order tracking (0 = first-order smoothing)", "",
              NumberRange::Closed(0, 2));
  cmd->Number("timeout", &c->timeout_s, "follow-phase time limit, simulated", "s",
              NumberRange::Positive(3600));
  cmd->Number("approach-force", &c->approach_force_n, "start-up compression read on the F/T", "N",
              NumberRange::Closed(0.05, 50));
  cmd->Number("start-offset", &s->start_offset_mm,
              "disk: start point distance east of the disk centre", "mm",
              NumberRange::Closed(0, 1000));
  cmd->Choice("land-at", &s->land_at,
              "disk: where the cup lands to the preload: 'start' (the lab's script) or 'centre' "
              "(the paper's text; a sealed landing)",
              {DiskLandingName(DiskLanding::kAtStart), DiskLandingName(DiskLanding::kAtCentre)});
  cmd->Number("pn", &c->law.p_noise_pa, "P_n: noise level, c_f = +beta here and dead band", "Pa",
              NumberRange::Positive(1e6).OpenHigh());
  cmd->Number("pg", &c->law.p_grasp_pa, "P_g in the c_f line", "Pa",
              NumberRange::Positive(1e6).OpenHigh());
  cmd->Number("off-edge", &c->thresholds.off_edge_pa, "failure I below this mean vacuum", "Pa",
              NumberRange::Closed(0, 1e6));
  cmd->Number("grasp", &c->thresholds.grasp_pa, "failure II when all chambers exceed this", "Pa",
              NumberRange::Closed(0, 1e6));
  cmd->Number("sweep-deg", &s->sweep_deg, "disk: success when the swept angle passes", "deg",
              NumberRange::Closed(1, 3600));
  cmd->Choice("object-on", &s->object_on,
              "object on the 'left' (CCW around a disk) or 'right' of the motion",
              {"left", "right"});
  cmd->Flag("no-dead-band", &s->no_dead_band,
            "take a step even when both differentials are below P_n");
  AddEffectsOption(cmd, "robot effects (docs/fidelity.md)", &s->effects, &c->effects);
  cmd->Check([c, s]() {
    c->target = TrialTarget::Disk(
        kWorkspaceX, kWorkspaceY, kBenchmarkDiskRadiusM, s->start_offset_mm * 1e-3,
        s->land_at == DiskLandingName(DiskLanding::kAtCentre) ? DiskLanding::kAtCentre
                                                              : DiskLanding::kAtStart);
    c->target.goal.sweep_deg = s->sweep_deg;
    c->law.side = s->object_on == "right" ? FollowSide::kObjectOnRight : FollowSide::kObjectOnLeft;
    c->law.dead_band = !s->no_dead_band;
    return c->Validate();
  });
}

void AddThreadsOption(cli::Command* cmd, long* threads) {
  cmd->Integer("threads", threads, "worker threads", NumberRange::Closed(1, 256));
}

void AddEffectsOption(cli::Command* cmd, const std::string& what, std::string* text,
                      RobotEffectsParams* effects) {
  cmd->Text("effects", text,
            what + ": 'default', 'off', or key=value,... over the defaults; defaults " +
                FormatRobotEffects(*effects));
  cmd->Check([text, effects]() {
    std::string error;
    return ParseRobotEffects(*text, effects, &error) ? std::string() : error;
  });
}

void AddControllerOptions(cli::Command* cmd, std::string* name, std::string* params,
                          ControllerChoice* choice) {
  cmd->Text("controller", name,
            "what decides while following: " + ControllerNames() +
                " (docs/controllers.md; keys with --controller-param)");
  cmd->Text(
      "controller-param", params,
      "the controller's parameters, key=value,... over its defaults:\n" + ControllerKeyTable());
  cmd->Check([name, params, choice]() {
    std::string error;
    return ParseControllerChoice(*name, *params, choice, &error) ? std::string()
                                                                 : "--controller: " + error;
  });
}

ModelPtr LoadTrialScene(const cli::Command& cmd, const std::string& scene_path,
                        const TrialConfig& config) {
  std::string error;
  ModelPtr model = LoadModel(scene_path, &error);
  if (!model) {
    std::fprintf(stderr, "ssc %s: %s\n", cmd.name().c_str(), error.c_str());
    cli::NoteInputError(error);
    return nullptr;
  }
  if (!CheckTrialSetup(model.get(), config, &error)) {
    std::fprintf(stderr, "ssc %s: %s: %s\n", cmd.name().c_str(), scene_path.c_str(), error.c_str());
    cli::NoteExitCode(kExitBadData);  // a scene that loads but cannot hold this trial
    return nullptr;
  }
  return model;
}

void PrintApproachSharing(bool on, const SweepSummary& summary) {
  if (!on) {
    std::printf("approach: not shared (--no-shared-approach)\n");
    return;
  }
  const ApproachCache::Counts& c = summary.approach;
  std::printf("approach: shared: %d simulated, %d trials started from one, %d from scratch%s%s\n",
              c.simulated, c.resumed, c.unshared, summary.approach_unshareable.empty() ? "" : ": ",
              summary.approach_unshareable.c_str());
}

}  // namespace ssc
