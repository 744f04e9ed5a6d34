// ssc objects as a library function: write the test objects' scenes and contours, run the
// contour-following trial on each object and seed on the job runner (studies/jobs/job_runner.h),
// and write the table (objects.csv), the cup-centre paths (paths/) and the fillet's along-edge
// profile (fillet_profile.csv, first fillet seed).
#ifndef SSC_STUDIES_OBJECT_STUDY_H_
#define SSC_STUDIES_OBJECT_STUDY_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "controller/contour_law.h"
#include "controller/controller_registry.h"
#include "objects/object_spec.h"
#include "studies/object_trials.h"
#include "trial/robot_effects.h"

namespace ssc {

struct ObjectStudySpec {
  std::vector<ObjectSpec> objects;
  int seeds = 1;  // trials per object: seeds seed, seed + 1, ...
  std::uint64_t seed = 1;
  ObjectSceneKind scene_kind = ObjectSceneKind::kGantry;  // which of each object's scenes
  ContourLawParams law;  // the published primitive-geometry controller: dL 0.5 mm
  RobotEffectsParams effects = FittedRobotEffects();  // the robot effects (docs/fidelity.md)
  ControllerChoice controller;  // what decides while following (the published law by default)
  StallRule stall;              // when a trial held in place ends (window 0: never)
  int threads = 1;
  std::string out_dir;      // scenes in OUT/scenes, paths in OUT/paths
  bool write_only = false;  // only the scenes and contours
};

struct ObjectStudySummary {
  int trials = 0;            // trials asked for
  int finished = 0;          // trials whose rows are in the table (all but on an interruption)
  int skipped = 0;           // of those, rows kept from an earlier run (not run again)
  bool interrupted = false;  // SIGINT/SIGTERM: the table holds the finished rows only
  std::string table_csv, paths_dir, fillet_profile_csv;  // paths written ("" if none)
  std::string fillet_line;  // where the fillet trial ended, in words ("" without a fillet)
};

// `progress` (optional) gets one line per trial run, in the runner's delivery order. The table
// (OUT/objects.csv) resumes as a sweep does (studies/sweep_io.h, ResumableTable): the same study
// run again skips the trials whose rows are in it, reruns rows it cannot trust, refuses other
// options (OUT/objects.json) and a second run on the same OUT; each row is appended as its trial
// finishes. Interrupted (studies/jobs/job_runner.h), the table keeps the finished rows and
// summary->interrupted is set; complete, the rows are rewritten in object and seed order. False +
// *error when a file cannot be read or written, or the table cannot be resumed.
bool RunObjectStudy(const ObjectStudySpec& spec,
                    const std::function<void(const std::string&)>& progress,
                    ObjectStudySummary* summary, std::string* error);

// Objects by comma-separated names, or all of them for "all". False + *error naming the
// unknown or repeated name.
bool ObjectsByNames(const std::string& names, std::vector<ObjectSpec>* objects, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_OBJECT_STUDY_H_
