// Uses the installed library as a downstream program would: finds the scenes next to the
// install, loads one (the plugin registers itself), runs the first second of a trial.
#include <cstdio>

#include "runtime/mujoco_model.h"
#include "runtime/trial.h"

int main() {
  std::printf("resources %s\n", ssc::ResourceDir().c_str());
  std::string error;
  ssc::ModelPtr m = ssc::LoadModel(ssc::ResolveScenePath("disk_benchmark_gantry"), &error);
  if (!m) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  ssc::DataPtr d = ssc::MakeData(m.get(), &error);
  ssc::TrialConfig config;
  auto trial = d ? ssc::ContourTrial::Create(m.get(), d.get(), config, false, &error) : nullptr;
  if (!trial) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  while (d->time < 1.0 && trial->Step()) {
  }
  std::printf("t %.3f s phase %s\n", d->time, ssc::PhaseName(trial->phase()));
  return 0;
}
