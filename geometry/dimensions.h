// The twin's fixed places and sizes, one home each. World convention (all scenes): z up,
// north = +y, east = +x, the table a plane at z = 0.
#ifndef SSC_GEOMETRY_DIMENSIONS_H_
#define SSC_GEOMETRY_DIMENSIONS_H_

namespace ssc {

// The workspace point W, world m: the disk benchmark's centre and every test object's
// reference point (disk or hole centre, corner apex, start of an edge).
inline constexpr double kWorkspaceX = 0.65, kWorkspaceY = 0.0;

// The tool centre point (the lip plane's centre, site ssc_tool_site of models/ssc_tool.xml) lies
// this far from the robot's flange (tool0) along the tool z axis, m. Robot logs give tool0.
inline constexpr double kToolCentreOffsetM = 0.146;

// The cup's nominal size (published): body diameter and opening (internal) diameter, mm. The
// pressure plugin's opening_radius_mm defaults to half the opening diameter.
inline constexpr double kCupBodyDiameterMm = 23.0;
inline constexpr double kCupOpeningDiameterMm = 11.0;

// The disk benchmark of the published disk trials: a disk of this radius centred at W, m, and
// the cup's start this far east of its centre, m (3 mm inside the edge). The scene files write
// the disk in MJCF; a test (ur10_model_test) checks them against these.
inline constexpr double kBenchmarkDiskRadiusM = 0.035;
inline constexpr double kBenchmarkStartOffsetM = 0.032;

}  // namespace ssc

#endif  // SSC_GEOMETRY_DIMENSIONS_H_
