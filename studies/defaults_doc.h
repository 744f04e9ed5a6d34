// docs/defaults.md, generated from the code's own tables: the law's defaults (ContourLawParams{}),
// the trial loop's (TrialConfig{}), and every robot-effect key (EffectKeys()) with its valid
// range, its default (FittedRobotEffects()) and the range `ssc calibrate --dynamic` searches;
// the scene tiers (RigTiers()) with the files each tier's scene is built from.
// Regenerate: build/bin/ssc_defaults_doc > docs/defaults.md (a test fails when it is stale).
#ifndef SSC_STUDIES_DEFAULTS_DOC_H_
#define SSC_STUDIES_DEFAULTS_DOC_H_

#include <string>

namespace ssc {

std::string DefaultsMarkdown();

}  // namespace ssc

#endif  // SSC_STUDIES_DEFAULTS_DOC_H_
