// ssc_twin._core, studies: sweep, validate, objects and the kinematic probe.
#include "python/src/binding_common.h"
#include "python/src/binding_controller.h"
#include "python/src/binding_topics.h"

namespace ssc {
namespace {

// The per-cell results of a validation as cells.csv has them (one entry per cell, map order):
// NumPy arrays of numbers and counts, lists of class / failure names.
nb::dict CellsDict(const std::vector<CellScore>& cells) {
  std::vector<double> step, beta, pref, p, p_low, p_high, agreement, surface_p;
  std::vector<std::int64_t> of3, successes, trials, off_edge, grasp, timeout, unstable, lost;
  std::vector<bool> match, opposite;
  std::vector<std::string> published, twin, main_failure;
  for (const CellScore& c : cells) {
    step.push_back(c.cell.step_mm);
    beta.push_back(c.cell.beta);
    pref.push_back(c.cell.pref_pa);
    published.emplace_back(MapClassName(c.cell.published));
    twin.emplace_back(MapClassName(c.twin_class));
    of3.push_back(c.successes_of_3);
    match.push_back(c.class_match);
    successes.push_back(c.successes);
    trials.push_back(c.trials);
    p.push_back(c.p_success);
    p_low.push_back(c.p_interval[0]);
    p_high.push_back(c.p_interval[1]);
    agreement.push_back(c.expected_agreement);
    opposite.push_back(c.opposite);
    off_edge.push_back(c.failure_off_edge);
    grasp.push_back(c.failure_grasp);
    timeout.push_back(c.timeout);
    unstable.push_back(c.unstable);
    lost.push_back(c.lost_edge);
    main_failure.push_back(c.main_failure);
    surface_p.push_back(c.surface_p);
  }
  nb::dict d;
  d["step_mm"] = Column(step);
  d["beta"] = Column(beta);
  d["pref_pa"] = Column(pref);
  d["published"] = nb::cast(published);  // "3", "2" or "<=1"
  d["twin_class"] = nb::cast(twin);      // from the first 3 seeds
  d["successes_of_3"] = Column(of3);
  d["class_match"] = Flags(match);
  d["successes"] = Column(successes);
  d["trials"] = Column(trials);
  d["p_success"] = Column(p);
  d["p_low"] = Column(p_low);  // Wilson 95 % interval
  d["p_high"] = Column(p_high);
  d["expected_agreement"] = Column(agreement);
  d["opposite"] = Flags(opposite);
  d["failure_I"] = Column(off_edge);
  d["failure_II"] = Column(grasp);
  d["timeout"] = Column(timeout);
  d["unstable"] = Column(unstable);
  d["lost_edge"] = Column(lost);
  d["main_failure"] = nb::cast(main_failure);  // "" when every trial succeeded
  d["surface_p"] = Column(surface_p);          // the smooth surface's rate (NaN: none fitted)
  return d;
}

// A study's progress for Python: None (quiet), True (a line on sys.stderr each time another 5 %
// of the trials is done) or a callable progress(done, total, elapsed_s). Called from the
// study's worker threads, which hold no GIL: it takes the GIL for each call. An exception in
// the callable stops further calls and is raised once the study returns (Raise()).
class PyProgress {
 public:
  PyProgress(nb::object progress, std::string name)
      : progress_(std::move(progress)), name_(std::move(name)) {
    if (!progress_.is_none() && !nb::isinstance<nb::bool_>(progress_) &&
        !PyCallable_Check(progress_.ptr())) {
      throw nb::type_error("progress must be None, True or a callable (done, total, elapsed_s)");
    }
  }
  std::function<void(const SweepProgress&)> Callback() {
    if (progress_.is_none() || (nb::isinstance<nb::bool_>(progress_) && !nb::cast<bool>(progress_)))
      return nullptr;
    return [this](const SweepProgress& s) { Report(s); };
  }
  void Raise() {
    if (error_) {
      std::unique_ptr<nb::python_error> e = std::move(error_);
      e->restore();
      throw nb::python_error();
    }
  }

 private:
  void Report(const SweepProgress& s) {
    nb::gil_scoped_acquire gil;
    if (error_ || s.total <= 0) return;
    try {
      if (nb::isinstance<nb::bool_>(progress_)) {
        const int percent = 100 * s.done / s.total;
        if (percent < next_percent_ && s.done < s.total) return;
        next_percent_ = (percent / 5 + 1) * 5;
        const int ran = s.done - s.skipped;
        const double rate = s.elapsed_s > 0 ? ran / s.elapsed_s : 0;
        const double eta = rate > 0 ? (s.total - s.done) / rate : 0;
        char line[160];
        std::snprintf(line, sizeof line,
                      "%s: %d/%d trials (%d %%), %.1f trials/s, %.0f s, ETA %.0f s\n",
                      name_.c_str(), s.done, s.total, percent, rate, s.elapsed_s, eta);
        nb::module_::import_("sys").attr("stderr").attr("write")(std::string(line));
      } else {
        progress_(s.done, s.total, s.elapsed_s);
      }
    } catch (nb::python_error& e) {
      error_ = std::make_unique<nb::python_error>(std::move(e));
    }
  }

  nb::object progress_;
  std::string name_;
  int next_percent_ = 0;
  std::unique_ptr<nb::python_error> error_;
};

}  // namespace

void BindSweep(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "sweep",
      [](const std::string& scene, std::vector<double> pref, std::vector<double> beta,
         std::vector<double> step_mm, int repeats, const nb::object& seed, int threads,
         const std::string& out_csv, const std::string& effects, const nb::object& controller,
         const std::string& controller_params, nb::object progress) {
        PyProgress reporter(std::move(progress), "ssc_twin.sweep");
        SweepSpec spec;
        if (std::string e; !ParseRobotEffects(effects, &spec.base.effects, &e)) Fail(e);
        spec.base.controller = ChoiceFrom(controller, controller_params);
        spec.scene_name = scene;
        spec.pref_pa = std::move(pref);
        spec.beta = std::move(beta);
        spec.step_mm = std::move(step_mm);
        spec.repeats = repeats;
        spec.seed = SeedArg(seed);
        spec.threads = threads;
        spec.out_csv = out_csv;
        if (out_csv.empty()) Invalid("out_csv is empty: give the sweep CSV's path");
        if (const std::string e = CheckSweepGrid(spec); !e.empty()) Invalid(e);
        ModelPtr model = Load(scene);
        SweepSummary summary;
        std::string error;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunSweep(model.get(), spec, reporter.Callback(), &summary, &error);
        }
        reporter.Raise();
        RaisePendingInterrupt();
        if (!ok) Fail(error);
        if (summary.interrupted) {
          Interrupted("sweep interrupted: " + std::to_string(summary.ran) +
                      " finished rows kept in " + out_csv + "; call it again to resume");
        }
        return Dict({{"csv", nb::cast(out_csv)},
                     {"total", nb::cast(summary.total)},
                     {"ran", nb::cast(summary.ran)},
                     {"skipped", nb::cast(summary.skipped)},
                     {"wall_s", nb::cast(summary.wall_s)}});
      },
      "scene"_a = DefaultScene(), "pref"_a, "beta"_a, "step_mm"_a, "repeats"_a = 3, "seed"_a = 1,
      "threads"_a = 1, "out_csv"_a, "effects"_a = "default", "controller"_a = "published",
      "controller_params"_a = "", "progress"_a = nb::none(),
      "A P_ref x beta x step x repeats grid of trials into a resumable CSV (ssc sweep). "
      "controller as in run_trial (a callable is called under the GIL: threads > 1 run the "
      "physics in parallel, the callable one call at a time). progress: None (quiet), True (a "
      "line on stderr per 5 % of the trials) or a callable progress(done, total, elapsed_s).");
}

void BindValidate(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "validate",
      [](const std::string& map, const std::string& out_dir, const std::string& scene, int seeds,
         const nb::object& seed, int threads, double timeout_s, const std::string& effects,
         const nb::object& controller, const std::string& controller_params, nb::object progress) {
        PyProgress reporter(std::move(progress), "ssc_twin.validate");
        ValidateSpec spec;
        spec.base.controller = ChoiceFrom(controller, controller_params);
        spec.map_path = map.empty() ? ResourceDir() + "/data/published/success_map_dl5.csv" : map;
        spec.scene_name = scene;
        spec.seed = SeedArg(seed);
        spec.out_dir = out_dir;
        if (seeds < 3 || seeds > 10000) {
          Invalid("seeds = " + std::to_string(seeds) +
                  " is out of range [3, 10000] (trials per cell)");
        }
        if (threads < 1 || threads > 256) {
          Invalid("threads = " + std::to_string(threads) + " is out of range [1, 256]");
        }
        spec.seeds = seeds;
        spec.threads = threads;
        std::string error;
        if (!ParseRobotEffects(effects, &spec.base.effects, &error)) Invalid(error);
        SetTimeout(timeout_s, &spec.base);
        // The map before anything is created (a FIFO, a device or a binary file is refused).
        if (std::vector<MapCell> cells; !ReadPublishedMap(spec.map_path, &cells, &error)) {
          Invalid(error);
        }
        if (out_dir.empty()) Invalid("out_dir is empty: give the output directory");
        std::error_code ec;
        std::filesystem::create_directories(out_dir, ec);
        if (ec || !std::filesystem::is_directory(out_dir)) {
          Fail("cannot create the output directory '" + out_dir + "'" +
               (ec ? ": " + ec.message() : std::string()));
        }
        ModelPtr model = Load(scene);
        MapScore score;
        SweepSummary summary;
        MapCeilings ceilings;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunValidation(model.get(), spec, reporter.Callback(), &score, &summary, &error,
                             nullptr, &ceilings);
        }
        reporter.Raise();
        RaisePendingInterrupt();
        if (summary.interrupted) Interrupted("validate " + error);
        if (!ok) Fail(error);
        nb::dict d;
        d["scores"] = Dict({{"cells", nb::cast(score.cells_scored)},
                            {"class_match", nb::cast(score.class_match)},
                            {"expected_agreement", nb::cast(score.expected_agreement)},
                            {"expected_agreement_interval",
                             nb::cast(std::vector<double>(score.agreement_interval.begin(),
                                                          score.agreement_interval.end()))},
                            {"opposite_cells", nb::cast(score.opposite)},
                            {"log_loss", nb::cast(score.log_loss)}});
        // What any twin can expect on this map (validate.json's "ceilings", "surface_ceilings").
        nb::list priors;
        for (const MapCeiling& c : ceilings.priors) {
          priors.append(Dict({{"prior", nb::cast(c.prior_name)},
                              {"prior_a", nb::cast(c.prior.a)},
                              {"prior_b", nb::cast(c.prior.b)},
                              {"rerun_agreement", nb::cast(c.rerun_agreement)},
                              {"oracle_agreement", nb::cast(c.oracle_agreement)},
                              {"rerun_reaches_goal", nb::cast(c.rerun_reaches_goal)},
                              {"oracle_reaches_goal", nb::cast(c.oracle_reaches_goal)}}));
        }
        d["ceilings"] = priors;
        nb::list surfaces;
        for (const SurfaceCeiling& s : ceilings.surfaces) {
          if (!s.fitted) continue;
          surfaces.append(Dict({{"step_mm", nb::cast(s.step_mm)},
                                {"rerun_agreement", nb::cast(s.rerun_agreement)},
                                {"oracle_agreement", nb::cast(s.oracle_agreement)},
                                {"loo_agreement", nb::cast(s.loo_agreement)}}));
        }
        d["surface_ceilings"] = surfaces;
        d["cells"] = CellsDict(score.cells);
        d["summary"] = Dict({{"total", nb::cast(summary.total)},
                             {"ran", nb::cast(summary.ran)},
                             {"skipped", nb::cast(summary.skipped)},
                             {"wall_s", nb::cast(summary.wall_s)}});
        d["map"] = spec.map_path;
        d["scene"] = scene;
        d["seeds_per_cell"] = seeds;
        d["base_seed"] = spec.seed;
        d["effects"] = FormatRobotEffects(spec.base.effects);
        d["out_dir"] = out_dir;
        return d;
      },
      "map"_a = "", "out_dir"_a = "out/validate", "scene"_a = DefaultScene(), "seeds"_a = 10,
      "seed"_a = 1, "threads"_a = 1, "timeout_s"_a = 0.0, "effects"_a = "default",
      "controller"_a = "published", "controller_params"_a = "", "progress"_a = nb::none(),
      "The twin on every cell of a published success map, scored (ssc validate). map: CSV "
      "step_mm,beta,pref_pa,successes_of_3 ('' = the published dL 5 mm map). Writes "
      "out_dir/trials.csv (resumable), cells.csv and validate.json; returns the scores, the "
      "per-cell results (NumPy arrays, cells.csv's columns) and the run summary. controller as "
      "in run_trial; progress as sweep's.");
}

void BindObjects(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "objects",
      [](const nb::object& names, const std::string& out_dir, int seeds, const nb::object& seed,
         const std::string& scene_kind, double pref, double beta, double step_mm, int threads,
         const std::string& effects, const nb::object& controller,
         const std::string& controller_params) {
        ObjectStudySpec spec;
        std::string error;
        if (!ObjectsByNames(NameListArg(names, "objects"), &spec.objects, &error))
          Invalid("objects: " + error);
        if (seeds < 1 || seeds > 1000)
          Invalid("seeds = " + std::to_string(seeds) + " is out of range [1, 1000]");
        if (threads < 1 || threads > 256)
          Invalid("threads = " + std::to_string(threads) + " is out of range [1, 256]");
        if (!ObjectSceneKindByName(scene_kind, &spec.scene_kind, &error))
          Invalid("scene_kind: " + error);
        spec.seeds = seeds;
        spec.seed = SeedArg(seed);
        spec.law = Law(pref, beta, step_mm);
        spec.threads = threads;
        spec.out_dir = out_dir;
        if (!ParseRobotEffects(effects, &spec.effects, &error)) Invalid(error);
        spec.controller = ChoiceFrom(controller, controller_params);
        if (const std::string e = spec.controller.Validate(); !e.empty()) Invalid(e);
        std::error_code ec;
        std::filesystem::create_directories(out_dir, ec);
        if (ec || !std::filesystem::is_directory(out_dir)) {
          Fail("cannot create the output directory '" + out_dir + "'" +
               (ec ? ": " + ec.message() : std::string()));
        }
        ObjectStudySummary summary;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunObjectStudy(spec, nullptr, &summary, &error);
        }
        RaisePendingInterrupt();
        if (!ok) Fail(error);
        if (summary.interrupted) {
          Interrupted("objects interrupted: " + std::to_string(summary.finished) + " of " +
                      std::to_string(summary.trials) + " trials finished, their rows are in " +
                      summary.table_csv + "; call it again to resume");
        }
        return Dict({{"csv", nb::cast(summary.table_csv)},
                     {"paths_dir", nb::cast(summary.paths_dir)},
                     {"trials", nb::cast(summary.trials)},
                     {"skipped", nb::cast(summary.skipped)}});
      },
      "objects"_a = "all", "out_dir"_a = "out/objects", "seeds"_a = 1, "seed"_a = 1,
      "scene_kind"_a = ObjectSceneKindName(ObjectSceneKindOfTier(RigTierFor(RigUse::kTrial))),
      "pref"_a = law.p_ref_pa, "beta"_a = law.beta, "step_mm"_a = 0.5, "threads"_a = 1,
      "effects"_a = "default", "controller"_a = "published", "controller_params"_a = "",
      "The test objects' trials (ssc objects): writes out_dir/objects.csv (read it with "
      "read_sweep) and the cup paths; controller as in run_trial.");
}

void BindProbe(nb::module_& m) {
  nb::class_<EdgeProbe3d>(m, "Probe",
                          "The cup on a mocap body placed over an edge; reads the sensor.")
      .def(
          "__init__",
          [](EdgeProbe3d* self, const std::string& scene) {
            std::string error;
            std::unique_ptr<EdgeProbe3d> p = EdgeProbe3d::Create(ResolveScenePath(scene), &error);
            if (!p) Fail(error);
            new (self) EdgeProbe3d(std::move(*p));
          },
          "scene"_a = RigTierFor(RigUse::kProbe).scene)
      .def(
          "read",
          [](EdgeProbe3d& p, double x_m, double y_m, double yaw_rad, double surface_z_m,
             double compression_m, double settle_s) {
            if (const std::string e = EdgeProbe3d::CheckPlacement(x_m, y_m, yaw_rad, surface_z_m,
                                                                  compression_m, settle_s);
                !e.empty()) {
              Invalid("Probe.read: " + e);
            }
            ProbeReading r;
            {
              nb::gil_scoped_release release;
              r = p.Read(x_m, y_m, yaw_rad, surface_z_m, compression_m, settle_s);
            }
            nb::dict d;
            d["filtered_pa"] = PerChamber(r.filtered_pa);
            d["static_pa"] = PerChamber(r.static_pa);
            d["sealed_area_mm2"] = PerChamber(r.sealed_area_mm2);
            d["leak_area_mm2"] = PerChamber(r.leak_area_mm2);
            d["lip_contacts"] = r.lip_contacts;
            d["pbar_pa"] = r.pbar_pa;
            d["dpx_pa"] = r.dpx_pa;
            d["dpy_pa"] = r.dpy_pa;
            d["g_world_rad"] = r.g_world_rad;
            d["travel_world_rad"] = r.travel_world_rad;
            d["static_pbar_pa"] = r.static_pbar_pa;
            return d;
          },
          "x_m"_a, "y_m"_a, "yaw_rad"_a = 0.0, "surface_z_m"_a = 0.010, "compression_m"_a = 0.001,
          "settle_s"_a = 0.3);
}

void BindStudies(nb::module_& m) {
  BindSweep(m);
  BindValidate(m);
  BindObjects(m);
  BindProbe(m);
}

}  // namespace ssc
