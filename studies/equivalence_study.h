// `ssc equivalence`: two models of the cup (two scenes, or a scene and a variant of it: other
// pressure-plugin keys, other robot effects) on the same cells of a published map with the same
// seeds, compared by statistics (studies/equivalence.h). Each arm runs as `ssc validate` does
// (studies/validation.h: the job runner, threads and MPI ranks, resumable) into its own folder,
// OUT/reference and OUT/candidate; the comparison goes to OUT/equivalence.json and .csv.
#ifndef SSC_STUDIES_EQUIVALENCE_STUDY_H_
#define SSC_STUDIES_EQUIVALENCE_STUDY_H_

#include <cstdint>
#include <functional>
#include <string>

#include "studies/equivalence.h"
#include "studies/sweep.h"
#include "studies/tool_variants.h"
#include "studies/validation.h"

namespace ssc {

struct EquivalenceArm {
  std::string scene_name;  // a name under scenes/ or a path
  PluginConfig plugin;     // pressure-plugin keys set on the scene's tool (empty: as it is)
  TrialConfig base;        // everything but P_ref, beta, step and seed
  std::uint64_t seed = 1;  // base seed, as `ssc sweep --seed`
};

struct EquivalenceSpec {
  std::string map_path;
  EquivalenceArm reference, candidate;  // the reference is the arm (the UR-10 scene)
  int seeds = 10;                       // trials per cell and arm (>= 3)
  int threads = 1;
  std::string out_dir;
  bool share_approach = true;
  EquivalenceOptions options;
};

struct EquivalenceRun {
  Equivalence result;
  MapScore reference_score, candidate_score;
  SweepSummary reference_summary, candidate_summary;
};

// The arm's model: the scene, with its plugin keys when any. Null + *error naming the scene.
ModelPtr LoadArmModel(const EquivalenceArm& arm, std::string* error);

// Checks both arms (map, trial configs, models) before running anything; then runs the reference
// and the candidate and compares them. `progress` gets the arm (0 reference, 1 candidate) and
// that arm's progress. Collective under MPI; rank 0 fills *run and writes the files.
bool RunEquivalence(const EquivalenceSpec& spec,
                    const std::function<void(int, const SweepProgress&)>& progress,
                    EquivalenceRun* run, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_EQUIVALENCE_STUDY_H_
