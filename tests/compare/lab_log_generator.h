// Test generator: a twin trial written exactly as the lab records it, in all three forms the
// lab produces (the newer and the older logger's per-topic CSVs, and the saver's DataLog .mat),
// with known perturbations (sensor scale, offsets and noise, a pressure clock of its own, late
// pose stamps, the disk elsewhere in base_link, a history clock offset).
#ifndef SSC_TESTS_LAB_LOG_GENERATOR_H_
#define SSC_TESTS_LAB_LOG_GENERATOR_H_

#include <string>

#include "compare/twin_log.h"

namespace ssc::testing {

struct LabForms {
  std::string newer_dir, older_dir, mat_path;  // what a lab user would hand to ssc compare
  std::string newer_file;                      // one file of the newer recording
  RobotLog log;                                // what was written
};

// Writes the three forms under `dir` (created). False with `error` on a write failure.
bool WriteLabForms(const TrialResult& trial, const TrialConfig& config,
                   const SceneObject& scene_disk, const LabSetup& setup,
                   const LogPerturbation& perturbation, const std::string& dir, LabForms* out,
                   std::string* error);

}  // namespace ssc::testing

#endif  // SSC_TESTS_LAB_LOG_GENERATOR_H_
