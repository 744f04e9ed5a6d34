// ssc_twin._core: the twin's C++ for Python (nanobind). Trials, sweeps, map validation, the
// kinematic probe and log comparison run here; results come back as dicts of numbers and NumPy
// arrays. No physics or control is re-written in Python.
#include "python/src/binding_common.h"
#include "python/src/binding_controller.h"
#include "python/src/binding_topics.h"

NB_MODULE(_core, m) {
  // A Python controller held by a trial that Python still held at exit (a closure over the
  // environment that owns the trial) is a cycle through C++ that Python's collector cannot see:
  // freed by the process's end, not a leak to report on every exit.
  nb::set_leak_warnings(false);
  using namespace ssc;
  m.doc() = "Smart Suction Cup twin: trials, sweeps, validation, probe and log comparison (C++).";
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "law_defaults",
      [law] {
        return Dict({{"pref", nb::cast(law.p_ref_pa)},
                     {"beta", nb::cast(law.beta)},
                     {"step_mm", nb::cast(law.step_mm)}});
      },
      "The contour law's default P_ref (Pa), beta and step (mm): ContourLawParams{} in C++.");

  m.attr("max_seed") = static_cast<std::uint64_t>(kSeedRange.hi);
  m.def(
      "check_seed", [](const nb::object& seed) { return SeedArg(seed); }, "seed"_a,
      "The seed as an int when it is a whole number in [0, max_seed] (2^53 - 1, as every ssc "
      "--seed), else ValueError naming the range.");
  m.def("resource_dir", &ResourceDir, "The folder holding models/ and scenes/.");
  m.def("set_resource_dir", &SetResourceDir, "dir"_a);
  m.def("scene_path", &ResolveScenePath, "scene"_a,
        "Path of a scene given by name (under scenes/) or path.");
  m.def("default_scene", &DefaultScene,
        "The scene every trial entry point runs when none is named (runtime/rig.h).");
  m.def(
      "scene_tiers",
      [] {
        nb::list tiers;
        for (const RigTier& t : RigTiers()) {
          tiers.append(Dict({{"name", nb::cast(std::string(t.name))},
                             {"scene", nb::cast(std::string(t.scene))},
                             {"kind", nb::cast(std::string(RigKindName(t.kind)))},
                             {"timestep_s", nb::cast(t.timestep_s)},
                             {"what", nb::cast(std::string(t.what))}}));
        }
        return tiers;
      },
      "The rig's scene tiers (runtime/rig.h): name, scene, kind (arm, gantry, flex, replay, "
      "probe), time step and what each is.");
  m.def("mujoco_version", [] { return std::string(mj_versionString()); });
  m.def("check_mujoco_version", &CheckMuJoCoVersion,
        "Empty when the loaded libmujoco matches the headers this was built with.");
  m.def("install_message_handlers", [] {
    // Only where the host (e.g. the mujoco package) set none: no MUJOCO_LOG.TXT litter.
    InstallMuJoCoMessageHandlers();
  });
  m.attr("default_control_period_s") = TrialConfig{}.control_period_s;
  m.def(
      "plugin_registered",
      [] { return mjp_getPlugin(kChamberPressurePluginName, nullptr) != nullptr; },
      "Whether the running libmujoco has the ssc.chamber_pressure plugin.");
  m.def("phase_names", [] {
    return std::vector<std::string>{PhaseName(TrialPhase::kApproach),
                                    PhaseName(TrialPhase::kMoveToStart),
                                    PhaseName(TrialPhase::kFollow), PhaseName(TrialPhase::kDone)};
  });
  m.def(
      "controllers",
      [] {
        nb::dict d;
        for (const ControllerType& t : ControllerTypes()) {
          nb::list keys;
          for (const ControllerParamKey& k : t.keys) {
            keys.append(Dict({{"key", nb::cast(k.key)},
                              {"unit", nb::cast(k.unit)},
                              {"default", nb::cast(k.default_value)},
                              {"min", nb::cast(k.min)},
                              {"max", nb::cast(k.max)},
                              {"what", nb::cast(k.what)}}));
          }
          d[t.name.c_str()] = Dict({{"what", nb::cast(t.what)}, {"keys", keys}});
        }
        return d;
      },
      "The registered controllers: name -> what it is and its parameter keys (unit, default, "
      "range).");
  m.def("object_names", [] {
    std::vector<std::string> names;
    for (const ObjectSpec& s : AllObjects()) names.push_back(s.name);
    return names;
  });

  m.def("wilson_interval", &WilsonInterval, "successes"_a, "trials"_a,
        "The Wilson score interval (95 %) of a success rate (studies/statistics/intervals.h).");
  m.def("student_t95", &StudentT95, "dof"_a,
        "The two-sided 95 % Student t quantile for dof degrees of freedom (dof >= 1).");
  BindTrials(m);
  BindStudies(m);
  BindLogs(m);
  BindSil(m);
  // The lab's disk benchmark set-up (compare/frames.h, geometry/dimensions.h).
  m.attr("LAB_DISK_CENTRE_BASE_LINK_M") = nb::make_tuple(kLabDiskCentreX, kLabDiskCentreY);
  m.attr("LAB_DISK_ENGAGE_Z_M") = kLabDiskEngageZ;
  m.attr("TOOL_CENTRE_OFFSET_M") = kToolCentreOffsetM;
  // How a trial ends (trial/trial_outcome.h, trial_goal.h), for the SIL's verdict.
  nb::dict exit_codes;
  for (const ExitCodeRow& row : kExitCodeTable) exit_codes[row.name] = static_cast<int>(row.code);
  m.attr("EXIT_CODES") = exit_codes;  // common/exit_codes.h
  m.attr("OFF_EDGE_PA") = TrialThresholds{}.off_edge_pa;
  m.attr("GRASP_PA") = TrialThresholds{}.grasp_pa;
  m.attr("LOOP_SWEEP_DEG") = kLoopSweepDeg;
}
