// ssc_bench: step cost with and without the chamber-pressure sensor, in one run.
//
// Timings are ratios within one process (machines are noisy): mean mj_step cost of the scene
// (pressure sensor at its default rate) vs the same scene compiled without the pressure sensor,
// and the cost of one sensor sample (geometry + rays + network solve).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "apps/ssc/cli.h"
#include "runtime/mujoco_model.h"
#include "runtime/trial.h"
#include "plugin/chamber_pressure_sensor.h"

namespace {

using Clock = std::chrono::steady_clock;

double MeanStepMicros(const mjModel* m, mjData* d, int steps) {
  const auto t0 = Clock::now();
  for (int i = 0; i < steps; ++i) mj_step(m, d);
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / steps;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene = "disk_benchmark";
  long steps_arg = 20000;
  ssc::cli::Command cmd("bench",
                        "Prints the mean mj_step cost with and without the pressure sensor, their\n"
                        "ratio and the cost of one sensor sample.");
  cmd.Text("scene", &scene, "scene (name under scenes/ or a path)");
  cmd.Integer("steps", &steps_arg, "timed steps per model", ssc::NumberRange::Closed(100, 1e8));
  if (int rc = 0; !cmd.Parse(argc - 1, argv + 1, &rc)) return rc;
  const int steps = static_cast<int>(steps_arg);
  const std::string path = ssc::ResolveScenePath(scene);
  std::string error;
  ssc::ModelPtr model = ssc::LoadModel(path, &error);
  if (!model) {
    std::fprintf(stderr, "ssc bench: %s\n", error.c_str());
    return 1;
  }
  mjModel* m = model.get();
  ssc::DataPtr data = ssc::MakeData(m, &error);
  mjData* d = data.get();
  int instance = -1;
  ssc::ChamberPressureSensor* sensor = ssc::FindChamberPressureSensor(m, d, &instance);
  if (sensor == nullptr) {
    std::fprintf(stderr, "ssc bench: %s has no ssc.chamber_pressure sensor\n", path.c_str());
    return 1;
  }
  // The same scene without the pressure sensor (its <sensor><plugin> and plugin instance
  // removed through mjSpec); everything else, the F/T sensors included, stays.
  char parse_error[1024] = "";
  mjSpec* spec = mj_parseXML(path.c_str(), nullptr, parse_error, sizeof(parse_error));
  mjModel* bare = nullptr;
  if (spec) {
    for (mjsElement* e = mjs_firstElement(spec, mjOBJ_SENSOR); e;) {
      mjsElement* next = mjs_nextElement(spec, e);
      if (mjs_asSensor(e)->type == mjSENS_PLUGIN) mjs_delete(spec, e);
      e = next;
    }
    for (mjsElement* e = mjs_firstElement(spec, mjOBJ_PLUGIN); e;) {
      mjsElement* next = mjs_nextElement(spec, e);
      mjs_delete(spec, e);
      e = next;
    }
    bare = mj_compile(spec, nullptr);
  }
  if (bare == nullptr) {
    std::fprintf(stderr, "ssc bench: could not build the scene without the sensor: %s\n",
                 spec ? mjs_getError(spec) : parse_error);
    if (spec) mj_deleteSpec(spec);
    return 1;
  }
  mjData* bare_d = mj_makeData(bare);
  // A representative state: run the trial controller until the cup has followed the edge for
  // a second (lip on the edge, part over air), then hold the controls fixed and time steps of
  // both models from that same state.
  std::string state_note = "scene keyframe";
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  {
    ssc::TrialConfig config;
    std::string trial_error;
    auto trial = ssc::ContourTrial::Create(m, d, config, false, &trial_error);
    if (trial) {
      while (trial->phase() != ssc::TrialPhase::kFollow && trial->Step()) {
      }
      for (int i = 0; i < 500 && trial->Step(); ++i) {
      }
      state_note = std::string("cup following the disk edge (phase ") +
                   ssc::PhaseName(trial->phase()) + ")";
    }
  }  // the trial unregisters its control callback here: controls stay as they are
  bare_d->time = d->time;
  mju_copy(bare_d->qpos, d->qpos, static_cast<int>(m->nq));
  mju_copy(bare_d->qvel, d->qvel, static_cast<int>(m->nv));
  mju_copy(bare_d->ctrl, d->ctrl, static_cast<int>(m->nu));
  if (m->nmocap) {
    mju_copy(bare_d->mocap_pos, d->mocap_pos, static_cast<int>(3 * m->nmocap));
    mju_copy(bare_d->mocap_quat, d->mocap_quat, static_cast<int>(4 * m->nmocap));
  }
  // Warm up, then alternate with/without in blocks to share drifts.
  MeanStepMicros(m, d, steps / 10);
  MeanStepMicros(bare, bare_d, steps / 10);
  double with_us = 0, without_us = 0;
  const int blocks = 5;
  for (int b = 0; b < blocks; ++b) {
    with_us += MeanStepMicros(m, d, steps / blocks) / blocks;
    without_us += MeanStepMicros(bare, bare_d, steps / blocks) / blocks;
  }
  mj_deleteData(bare_d);
  mj_deleteModel(bare);
  mj_deleteSpec(spec);

  // One sensor sample: measurement + network solve, repeated at the current state.
  ssc::ChamberPressureSample sample = sensor->last_sample();
  const int reps = 20000;
  const auto t0 = Clock::now();
  double sink = 0;
  for (int i = 0; i < reps; ++i) {
    sensor->Measure(m, d, &sample);
    const ssc::FlowSolution s = ssc::SolveFlowNetwork(sensor->config().pneumatics, sample.leak_area_m2);
    sink += s.tap_pa[0];
  }
  const double sample_us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / reps;
  const auto t1 = Clock::now();
  for (int i = 0; i < reps; ++i) sensor->Measure(m, d, &sample);
  const double measure_us = std::chrono::duration<double, std::micro>(Clock::now() - t1).count() / reps;
  const double rate = sensor->config().sensor.sample_rate_hz;
  const double per_step_expected = sample_us * rate * m->opt.timestep;

  std::printf("scene: %s (MuJoCo %s, timestep %.4f s, %ld geoms, %ld DoF)\n", path.c_str(),
              mj_versionString(), m->opt.timestep, static_cast<long>(m->ngeom),
              static_cast<long>(m->nv));
  std::printf("state: %s\n", state_note.c_str());
  std::printf("mj_step without pressure sensor : %8.2f us\n", without_us);
  std::printf("mj_step with pressure sensor    : %8.2f us  (sensor at %.0f Hz)\n", with_us, rate);
  std::printf("ratio with/without              : %8.3f  (target <= 1.10)\n", with_us / without_us);
  std::printf("one sensor sample               : %8.2f us  (%d rays; %.2f us per step amortised)\n",
              sample_us, sample.rays_cast, per_step_expected);
  std::printf("  of which contacts + rays        : %8.2f us; flow network solve %.2f us\n", measure_us,
              sample_us - measure_us);
  std::printf("real-time factor with sensor    : %8.1f x\n", m->opt.timestep * 1e6 / with_us);
  if (sink == 12345.678) std::printf(" ");  // keep the loop from being optimised away
  return 0;
}
