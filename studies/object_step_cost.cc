#include "studies/object_step_cost.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <limits>

#include "common/tool_names.h"
#include "plugin/chamber_pressure_sensor.h"
#include "runtime/mujoco_model.h"

namespace ssc {

std::optional<StepCost> MeasureStepCost(const ObjectSpec& spec, const std::string& probe_scene,
                                        const StepCostOptions& options, std::string* error) {
  ModelPtr m = LoadModel(probe_scene, error);
  if (!m) return std::nullopt;
  DataPtr d = MakeData(m.get(), error);
  if (!d) return std::nullopt;
  const int probe = mj_name2id(m.get(), mjOBJ_BODY, "probe");
  const int site = mj_name2id(m.get(), mjOBJ_SITE, kToolSiteName);
  if (probe < 0 || m->body_mocapid[probe] < 0 || site < 0) {
    *error = probe_scene + ": no mocap body 'probe' holding the tool site '" + kToolSiteName + "'";
    return std::nullopt;
  }
  if (!FindChamberPressureDiagnostics(m.get(), d.get())) {
    *error = probe_scene + ": no ssc.chamber_pressure sensor (the cost includes it)";
    return std::nullopt;
  }
  mjtNum* mocap = d->mocap_pos + 3 * m->body_mocapid[probe];
  mj_forward(m.get(), d.get());
  const double tool_length_m = mocap[2] - d->site_xpos[3 * site + 2];  // flange to lip plane
  const ObjectTrialSetup& t = spec.trial;
  const double z = t.surface_top_z_m - options.press_m + tool_length_m;
  // Along the edge at the start's inset; open edges stop at their end.
  auto place = [&](double time_s) {
    double s = t.start_arc_m + options.speed_m_s * time_s;
    if (!spec.closed()) s = std::min(s, spec.edge.Length());
    const Point2 p = spec.edge.PointAt(s), n = spec.edge.LeftNormalAt(s);
    mocap[0] = p[0] + t.start_inset_m * n[0];
    mocap[1] = p[1] + t.start_inset_m * n[1];
    mocap[2] = z;
  };
  StepCost cost;
  cost.object = spec.name;
  for (int g = 0; g < m->ngeom; ++g) cost.object_geoms += m->geom_group[g] == 2;
  cost.step_us = std::numeric_limits<double>::infinity();
  using Clock = std::chrono::steady_clock;
  for (int run = 0; run < std::max(1, options.repeats); ++run) {
    mj_resetData(m.get(), d.get());
    place(0);
    mj_forward(m.get(), d.get());
    for (int i = 0; i < options.warmup_steps; ++i) mj_step(m.get(), d.get());
    Clock::duration total{};
    long contacts = 0;
    const double t0 = d->time;
    for (int i = 0; i < options.steps; ++i) {
      place(d->time - t0);
      const Clock::time_point begin = Clock::now();
      mj_step(m.get(), d.get());
      total += Clock::now() - begin;
      contacts += d->ncon;
    }
    const double step_us = std::chrono::duration<double, std::micro>(total).count() / options.steps;
    if (step_us < cost.step_us) {
      cost.step_us = step_us;
      cost.contacts = static_cast<double>(contacts) / options.steps;
      cost.sim_s = d->time - t0;
    }
  }
  return cost;
}

}  // namespace ssc
