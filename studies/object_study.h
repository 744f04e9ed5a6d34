// ssc objects as a library function: write the test objects' scenes and contours, run the
// contour-following trial on each object and seed on the job runner (studies/job_runner.h), and
// write the table (objects.csv), the cup-centre paths (paths/) and the fillet's along-edge
// profile (fillet_profile.csv, first fillet seed).
#ifndef SSC_STUDIES_OBJECT_STUDY_H_
#define SSC_STUDIES_OBJECT_STUDY_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "controller/pure/contour_law.h"
#include "controller/pure/controller_registry.h"
#include "controller/pure/robot_effects.h"
#include "objects/object_spec.h"
#include "studies/object_trials.h"

namespace ssc {

struct ObjectStudySpec {
  std::vector<ObjectSpec> objects;
  int seeds = 1;  // trials per object: seeds seed, seed + 1, ...
  std::uint64_t seed = 1;
  ObjectSceneKind scene_kind = ObjectSceneKind::kGantry;  // which of each object's scenes
  ContourLawParams law;  // the published primitive-geometry controller: dL 0.5 mm
  RobotEffectsParams effects = FittedRobotEffects();  // the robot effects (docs/fidelity.md)
  ControllerChoice controller;  // what decides while following (the published law by default)
  int threads = 1;
  std::string out_dir;      // scenes in OUT/scenes, paths in OUT/paths
  bool write_only = false;  // only the scenes and contours
};

struct ObjectStudySummary {
  int trials = 0;            // trials asked for
  int finished = 0;          // trials whose rows are in the table (all but on an interruption)
  bool interrupted = false;  // SIGINT/SIGTERM: the table holds the finished rows only
  std::string table_csv, paths_dir, fillet_profile_csv;  // paths written ("" if none)
  std::string fillet_line;  // where the fillet trial ended, in words ("" without a fillet)
};

// `progress` (optional) gets one line per finished trial, in the runner's delivery order.
// False + *error when a file cannot be written. Interrupted (studies/job_runner.h), the table
// is written with the finished trials' rows and summary->interrupted is set; it does not resume.
bool RunObjectStudy(const ObjectStudySpec& spec,
                    const std::function<void(const std::string&)>& progress,
                    ObjectStudySummary* summary, std::string* error);

// Objects by comma-separated names, or all of them for "all". False + *error naming the
// unknown or repeated name.
bool ObjectsByNames(const std::string& names, std::vector<ObjectSpec>* objects, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_OBJECT_STUDY_H_
