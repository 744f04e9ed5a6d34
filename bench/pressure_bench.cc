// ssc_bench (`ssc bench`): where the time of a step goes, per scene, in one run.
//
// Machines here are shared and noisy, so every figure is paired within one process: the scenes
// and their variants run in alternating blocks of steps from the same following state (cup on
// the disk edge), and each ratio is the median over rounds of the ratio within a round.
//   trial     the scene as sweeps run it: the trial controller in the loop; MuJoCo's own timers
//             (mjData.timer via mjcb_time) split the step into collision, constraint, ...
//   held      the same scene and state with the controls held (no controller): the reference
//   -sensor   held, without the pressure sensor (its plugin removed through mjSpec)
//   floor     held, without the sensor and without the lip's slide joints (a rigid lip)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/ssc/cli.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"
#include "runtime/rig.h"
#include "runtime/trial.h"

namespace {

using Clock = std::chrono::steady_clock;

mjtNum NowMicros() {
  static const auto t0 = Clock::now();
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

// Times the control callback (the trial controller) inside mj_step.
mjfGeneric g_inner_control = nullptr;
double g_control_us = 0;
void TimedControl(const mjModel* m, mjData* d) {
  const mjtNum t0 = NowMicros();
  g_inner_control(m, d);
  g_control_us += NowMicros() - t0;
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

// A compiled variant of a scene: without the pressure sensor, and optionally without the lip's
// slide joints.
mjModel* CompileVariant(const std::string& path, bool lip_joints, std::string* error) {
  char parse_error[1024] = "";
  mjSpec* spec = mj_parseXML(path.c_str(), nullptr, parse_error, sizeof(parse_error));
  if (!spec) {
    *error = parse_error;
    return nullptr;
  }
  if (!ssc::RemoveListedJoints(spec, error)) {
    mj_deleteSpec(spec);
    return nullptr;
  }
  auto remove_all = [&](mjtObj type, auto keep) {
    for (mjsElement* e = mjs_firstElement(spec, type); e;) {
      mjsElement* next = mjs_nextElement(spec, e);
      if (!keep(e)) mjs_delete(spec, e);
      e = next;
    }
  };
  remove_all(mjOBJ_SENSOR, [](mjsElement* e) { return mjs_asSensor(e)->type != mjSENS_PLUGIN; });
  remove_all(mjOBJ_PLUGIN, [](mjsElement*) { return false; });
  if (!lip_joints) {
    remove_all(mjOBJ_JOINT, [](mjsElement* e) {
      return std::string(mjs_getString(mjs_getName(e))).rfind("ssc_lip_", 0) != 0;
    });
    remove_all(mjOBJ_KEY, [](mjsElement*) { return false; });  // their qpos lists the lip joints
  }
  mjModel* m = mj_compile(spec, nullptr);
  if (!m) *error = mjs_getError(spec);
  mj_deleteSpec(spec);
  return m;
}

// Copies the state of `from` into `to` joint by joint (by name), plus controls and mocap.
void CopyStateByName(const mjModel* fm, const mjData* from, const mjModel* tm, mjData* to) {
  to->time = from->time;
  for (int j = 0; j < tm->njnt; ++j) {
    // A flex's vertex joints have no names: matched by index when both models hold them.
    const char* name = mj_id2name(tm, mjOBJ_JOINT, j);
    const int k =
        name != nullptr ? mj_name2id(fm, mjOBJ_JOINT, name) : (fm->njnt == tm->njnt ? j : -1);
    if (k < 0) continue;
    const int nq = tm->jnt_type[j] == mjJNT_FREE ? 7 : tm->jnt_type[j] == mjJNT_BALL ? 4 : 1;
    const int nv = tm->jnt_type[j] == mjJNT_FREE ? 6 : tm->jnt_type[j] == mjJNT_BALL ? 3 : 1;
    mju_copy(to->qpos + tm->jnt_qposadr[j], from->qpos + fm->jnt_qposadr[k], nq);
    mju_copy(to->qvel + tm->jnt_dofadr[j], from->qvel + fm->jnt_dofadr[k], nv);
  }
  mju_copy(to->ctrl, from->ctrl, static_cast<int>(std::min(tm->nu, fm->nu)));
  if (tm->nmocap && tm->nmocap == fm->nmocap) {
    mju_copy(to->mocap_pos, from->mocap_pos, static_cast<int>(3 * tm->nmocap));
    mju_copy(to->mocap_quat, from->mocap_quat, static_cast<int>(4 * tm->nmocap));
  }
  mj_forward(tm, to);
}

struct Variant {
  std::string label;
  const mjModel* m = nullptr;
  mjData* d = nullptr;
  std::vector<double> block_us;  // mean step cost of each block
};

// One scene: the trial variant (controller in the loop) and the held variants.
struct Scene {
  std::string name, path;
  ssc::ModelPtr model;
  ssc::DataPtr data;
  std::unique_ptr<ssc::ContourTrial> trial;
  mjModel* bare = nullptr;
  mjModel* floor = nullptr;
  std::vector<Variant> held;  // held, -sensor, floor
  std::vector<double> trial_us;
  double timer_us[mjNTIMER] = {};
  double control_us = 0;
  long trial_steps = 0;
  double solver_iterations = 0, contacts = 0;  // summed over timed trial steps
  double first_follow_s = 0;

  ~Scene() {
    trial.reset();
    for (Variant& v : held) mj_deleteData(v.d);
    mj_deleteModel(bare);
    mj_deleteModel(floor);
  }

  // Runs the trial (untimed) until the cup has followed the edge for a second.
  bool ToFollowing() {
    trial->Reset();
    trial->SetResultOnly(true);  // as sweeps run it: the F/T only where the controller reads it
    while (trial->phase() != ssc::TrialPhase::kFollow && trial->Step()) {
    }
    for (int i = 0; i < 500 && trial->Step(); ++i) {
    }
    return trial->phase() == ssc::TrialPhase::kFollow;
  }
};

// Loads a scene, its trial (brought to the follow phase) and the held variants from the same
// state; null with the message printed.
std::unique_ptr<Scene> OpenScene(const std::string& name) {
  auto s = std::make_unique<Scene>();
  s->name = name;
  s->path = ssc::ResolveScenePath(name);
  std::string error;
  s->model = ssc::LoadModel(s->path, &error);
  if (s->model) s->data = ssc::MakeData(s->model.get(), &error);
  if (s->data) {
    s->trial =
        ssc::ContourTrial::Create(s->model.get(), s->data.get(), ssc::TrialConfig(), false, &error);
  }
  if (s->trial) s->bare = CompileVariant(s->path, true, &error);
  if (s->bare) s->floor = CompileVariant(s->path, false, &error);
  if (!s->floor) {
    std::fprintf(stderr, "ssc bench: %s: %s\n", s->path.c_str(), error.c_str());
    return nullptr;
  }
  if (!s->ToFollowing()) {
    std::fprintf(stderr, "ssc bench: %s: the trial never reached the follow phase\n", name.c_str());
    return nullptr;
  }
  s->first_follow_s = s->data->time;
  const mjModel* models[3] = {s->model.get(), s->bare, s->floor};
  const char* labels[3] = {"held", "-sensor", "floor"};
  for (int v = 0; v < 3; ++v) {
    Variant var;
    var.label = labels[v];
    var.m = models[v];
    var.d = mj_makeData(var.m);
    CopyStateByName(s->model.get(), s->data.get(), var.m, var.d);
    s->held.push_back(var);
  }
  return s;
}

// One block of each of a scene's variants; `record` false for the warm-up.
void RunBlocks(Scene* s, int block, bool record) {
  // Trial variant: first plain (the headline cost), then with MuJoCo's timers on and the
  // control callback timed (the breakdown; timing adds a little to each step).
  mjData* d = s->data.get();
  if (s->trial->phase() != ssc::TrialPhase::kFollow || d->time > s->first_follow_s + 15) {
    s->ToFollowing();
  }
  const auto t0 = Clock::now();
  int steps = 0;
  while (steps < block && s->trial->Step()) ++steps;
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  if (record && steps > 0) s->trial_us.push_back(us / steps);
  std::memset(d->timer, 0, sizeof(d->timer));
  mjcb_time = NowMicros;
  g_inner_control = mjcb_control;
  mjcb_control = TimedControl;
  g_control_us = 0;
  steps = 0;
  while (steps < block && s->trial->Step()) {
    ++steps;
    if (record) {
      s->solver_iterations += d->solver_niter[0];
      s->contacts += d->ncon;
    }
  }
  mjcb_control = g_inner_control;
  mjcb_time = nullptr;
  if (record && steps > 0) {
    for (int t = 0; t < mjNTIMER; ++t) s->timer_us[t] += d->timer[t].duration;
    s->control_us += g_control_us;
    s->trial_steps += steps;
  }
  for (Variant& v : s->held) {
    const auto t1 = Clock::now();
    for (int i = 0; i < block; ++i) mj_step(v.m, v.d);
    const double held_us = std::chrono::duration<double, std::micro>(Clock::now() - t1).count();
    if (record) v.block_us.push_back(held_us / block);
  }
}

// The cost table: per scene the trial step, the held step and its variants, paired ratios.
void PrintCostTable(const std::vector<std::unique_ptr<Scene>>& scenes, int rounds, int block) {
  const Scene& ref = *scenes.front();
  std::printf(
      "MuJoCo %s; %d rounds of %d-step blocks, scenes and variants alternating; "
      "medians over rounds (ratios paired within a round)\n",
      mj_versionString(), rounds, block);
  std::printf("\n%-26s %8s %7s %8s %6s %6s %6s %8s %8s %9s %8s\n", "scene", "trial us", "vs ref",
              "us/sim-s", "nv", "ncon", "dt ms", "held us", "vs ref", "-sensor", "floor");
  for (const auto& s : scenes) {
    std::vector<double> trial_vs_ref, held_vs_ref, no_sensor, floor;
    for (int r = 0; r < rounds; ++r) {
      const double held = s->held[0].block_us[r];
      if (r < static_cast<int>(s->trial_us.size()) && r < static_cast<int>(ref.trial_us.size())) {
        trial_vs_ref.push_back(s->trial_us[r] / ref.trial_us[r]);
      }
      held_vs_ref.push_back(held / ref.held[0].block_us[r]);
      no_sensor.push_back(s->held[1].block_us[r] / held);
      floor.push_back(s->held[2].block_us[r] / held);
    }
    const double trial_us = Median(s->trial_us);
    std::printf("%-26s %8.1f %7.3f %8.0f %6ld %6d %6.2f %8.1f %8.3f %9.3f %8.3f\n", s->name.c_str(),
                trial_us, Median(trial_vs_ref), trial_us / s->model->opt.timestep,
                static_cast<long>(s->model->nv), s->held[0].d->ncon, s->model->opt.timestep * 1e3,
                Median(s->held[0].block_us), Median(held_vs_ref), Median(no_sensor), Median(floor));
  }
  std::printf(
      "  trial: a step with the controller in the loop while following the edge (what "
      "sweeps run); us/sim-s: wall us per simulated second;\n  held: the same scene from "
      "the same state with the controls held; -sensor, floor: held without the pressure "
      "sensor,\n  and also without the lip joints, / held. vs ref: / %s in the same "
      "round.\n",
      ref.name.c_str());
}

// Where a trial step goes, from MuJoCo's timers summed over the recorded rounds.
void PrintStepBreakdown(const std::vector<std::unique_ptr<Scene>>& scenes) {
  std::printf("\nwhere a trial step goes (MuJoCo timers, share of the step):\n");
  std::printf("%-26s %7s %7s %7s %7s %7s %7s %7s %7s %6s %6s\n", "scene", "step us", "collide",
              "constr", "integr", "kin+M", "sensor*", "control", "other", "ncon", "iters");
  for (const auto& s : scenes) {
    const double* t = s->timer_us;
    const double step = t[mjTIMER_STEP];
    if (step <= 0) continue;
    const double collide = t[mjTIMER_POS_COLLISION];
    const double constr = t[mjTIMER_POS_MAKE] + t[mjTIMER_POS_PROJECT] + t[mjTIMER_CONSTRAINT];
    const double integr = t[mjTIMER_ADVANCE];
    const double kin = t[mjTIMER_POS_KINEMATICS] + t[mjTIMER_POS_INERTIA];
    const double control = s->control_us;
    // Inside mj_forward but outside its stage timers: sensors (the pressure plugin dominates),
    // the control callback, energy.
    const double outside = t[mjTIMER_FORWARD] - t[mjTIMER_POSITION] - t[mjTIMER_VELOCITY] -
                           t[mjTIMER_ACTUATION] - t[mjTIMER_CONSTRAINT];
    const double sensor = std::max(0.0, outside - control);
    const double other = step - collide - constr - integr - kin - sensor - control;
    const double n = static_cast<double>(s->trial_steps);
    std::printf("%-26s %7.1f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %6.1f %6.1f\n",
                s->name.c_str(), step / n, collide / step, constr / step, integr / step, kin / step,
                sensor / step, control / step, other / step, s->contacts / n,
                s->solver_iterations / n);
  }
  std::printf(
      "  collide: broad+narrow phase; constr: make, project, solve; integr: the "
      "integrator; kin+M: kinematics, inertia;\n  sensor*: the rest of mj_forward "
      "(sensors; the pressure plugin dominates); other: velocity, actuation, checks;\n  ncon: "
      "contacts per step; iters: constraint solver iterations per step\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenes_arg = std::string(ssc::RigTierFor(ssc::RigUse::kReference).scene) + "," +
                           ssc::RigTierNamed("gantry")->scene;
  long block_arg = 500, rounds_arg = 11;
  ssc::cli::Command cmd(
      "bench",
      "Per scene (names under scenes/ or paths; the first is the reference): the cost of a step\n"
      "and where it goes, in alternating blocks within one run; medians over rounds.");
  cmd.Text("scenes", &scenes_arg, "comma-separated scenes, the first the reference");
  cmd.Integer("block", &block_arg, "steps per block", ssc::NumberRange::Closed(100, 1e7));
  cmd.Integer("rounds", &rounds_arg, "rounds of blocks (medians over them)",
              ssc::NumberRange::Closed(1, 1000));
  // Bounded work: each scene steps (rounds + 1) x 5 blocks (the trial twice, three variants);
  // beyond 2e6 steps per variant a run takes hours on one core.
  cmd.Check([&]() -> std::string {
    const double per_variant = static_cast<double>(block_arg) * static_cast<double>(rounds_arg + 1);
    if (per_variant > 2e6) {
      return "--block " + std::to_string(block_arg) + " x (--rounds " + std::to_string(rounds_arg) +
             " + 1 warm-up) = " + ssc::FormatNumber(per_variant) +
             " steps per variant, more than 2e6 (hours of stepping): use fewer";
    }
    return "";
  });
  if (int rc = 0; !cmd.Parse(argc - 1, argv + 1, &rc)) return rc;
  const int block = static_cast<int>(block_arg), rounds = static_cast<int>(rounds_arg);
  std::vector<std::unique_ptr<Scene>> scenes;
  for (const std::string& name : Split(scenes_arg)) {
    std::unique_ptr<Scene> s = OpenScene(name);
    if (!s) return 1;
    scenes.push_back(std::move(s));
  }
  // Warm-up, then rounds of alternating blocks; progress on stderr (a terminal only).
  const bool progress = isatty(STDERR_FILENO);
  for (int r = -1; r < rounds; ++r) {
    if (progress) {
      std::fprintf(stderr, "\rbench: %s %d/%d ", r < 0 ? "warm-up" : "round", r < 0 ? 0 : r + 1,
                   rounds);
      std::fflush(stderr);
    }
    for (auto& s : scenes) RunBlocks(s.get(), block, r >= 0);
  }
  if (progress) std::fprintf(stderr, "\n");
  PrintCostTable(scenes, rounds, block);
  PrintStepBreakdown(scenes);
  return 0;
}
