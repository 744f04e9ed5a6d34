// The published contour law from an installed ssc, without MuJoCo.
#include <array>
#include <cstdio>

#include "controller/contour_law.h"

int main() {
  ssc::ContourLawParams law;
  const ssc::ContourStep s = ssc::ComputeContourStep({120, 80, 5, 40}, law);
  std::printf("step %.6f %.6f m, c_f %.4f\n", s.step_m[0], s.step_m[1], s.cf);
  return s.moving ? 0 : 1;
}
