// Variants of the tool model for fidelity studies: the same cup with a different number of lip
// segments (same total lip stiffness, same ring radius), written with tinyxml2.
#ifndef SSC_STUDIES_TOOL_VARIANTS_H_
#define SSC_STUDIES_TOOL_VARIANTS_H_

#include <string>

namespace ssc {

// Rewrites the MJCF text of models/ssc_tool.xml (`tool_xml`) with `segments` lip segments
// (4..256, a multiple of 4 so each chamber gets the same share). Empty + *error on failure.
std::string ToolWithLipSegments(const std::string& tool_xml, int segments, std::string* error);

}  // namespace ssc

#endif  // SSC_STUDIES_TOOL_VARIANTS_H_
