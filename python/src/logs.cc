// ssc_twin._core, logs: the comparison with a robot log, a twin trial written as one, and the
// lab's merged .mat from a logger recording.
#include "python/src/binding_common.h"
#include "python/src/binding_topics.h"

namespace ssc {
namespace {

double DictNumber(const nb::dict& d, const char* key) {
  return d.contains(key) ? nb::cast<double>(d[key]) : kNoValue;
}
std::vector<double> DictNumbers(const nb::dict& d, const char* key) {
  return d.contains(key) ? nb::cast<std::vector<double>>(d[key]) : std::vector<double>{};
}

// The lab's merged .mat from one logger recording (its per-topic CSVs) and the script's
// arguments, written by the C++ MAT writer (robotlog/mat_log.h) as the lab's saver lays it out.
std::string WriteLabMat(const std::string& recording, const std::string& mat_dir,
                        const std::string& append_txt, const nb::dict& args) {
  RobotLog log;
  LoadError error;
  if (!LoadTopicCsvRecording(recording, &log, &error)) Fail(error.ToString());
  LabRunArgs& a = log.args;
  a.p_ref_pa = DictNumber(args, "Pref");
  a.beta = DictNumber(args, "beta");
  a.d_lat_m = DictNumber(args, "d_lat");
  a.disk_radius_mm = DictNumber(args, "diskRadius");
  a.start_offset_m = DictNumber(args, "start_offset");
  a.success = DictNumber(args, "success");
  a.p_lims_pa = DictNumbers(args, "P_lims");
  a.alpha_beta = DictNumbers(args, "alpha_beta");
  a.fz_set_n = DictNumbers(args, "Fz_set");
  if (args.contains("edgeFollowing_history")) {
    for (nb::handle row : nb::iter(args["edgeFollowing_history"])) {
      const std::vector<double> v = nb::cast<std::vector<double>>(row);
      if (v.size() != kHistoryRowNumbers) {
        Fail(
            "edgeFollowing_history: each row needs 14 numbers [t, x, y, r_p(2), corr_p(2), "
            "r_p_final(2), F_normal, P1..P4], got " +
            std::to_string(v.size()));
      }
      a.history.push_back(HistoryRowFromNumbers(v.data()));
    }
  }
  const std::string stamp = RecordingStamp(log.t0_ns);
  const std::string path =
      mat_dir + "/DataLog_" + stamp + (append_txt.empty() ? "" : "_" + append_txt) + ".mat";
  std::string werr;
  if (!WriteRobotLogMat(path, log, &werr)) Fail(werr);
  return path;
}

}  // namespace

void BindLogs(nb::module_& m) {
  const ContourLawParams law;  // the law's defaults have one home: ContourLawParams{}
  m.def(
      "compare",
      [](const std::string& log_path, const std::string& scene, const std::string& out_dir,
         double tcp_offset_mm, int average) {
        CompareOptions options;
        options.log_path = log_path;
        options.scene = scene;
        options.out_dir = out_dir;
        options.processing.tcp_offset_m = tcp_offset_mm * 1e-3;
        options.processing.moving_average = average;
        CompareResult result;
        std::string error;
        bool ok = false;
        {
          nb::gil_scoped_release release;
          ok = RunComparison(options, &result, &error);
        }
        if (!ok) Fail(error);
        const ReplayComparison& c = result.replay;
        nb::dict d;
        d["rms_pa"] = PerChamber(c.rms_pa);
        d["rms_log10"] = PerChamber(c.rms_log10);
        d["correlation"] = PerChamber(c.correlation);
        d["mean_ratio"] = PerChamber(c.mean_ratio);
        d["pbar_rms_pa"] = c.pbar_rms_pa;
        d["pbar_bias_pa"] = c.pbar_bias_pa;
        d["direction_rms_deg"] = c.direction_rms_deg;
        d["direction_median_deg"] = c.direction_median_deg;
        d["direction_samples"] = c.direction_samples;
        d["t_s"] = Column(c.t_s);
        d["sim_pa"] = Rows(c.sim_pa);
        d["log_pa"] = Rows(c.log_pa);
        d["tcp_m"] = Rows(c.tcp_m);
        d["report_dir"] = out_dir;
        d["warnings"] = nb::cast(result.log_warnings);  // e.g. a replay off the object
        return d;
      },
      "log"_a, "scene"_a = RigTierFor(RigUse::kReplay).scene, "out_dir"_a = "out/compare",
      "tcp_offset_mm"_a = kToolCentreOffsetM * 1e3, "average"_a = ProcessOptions().moving_average,
      "Replays a robot log (lab per-topic CSVs, .mat or plain CSV) in the twin and compares the "
      "pressures, as `ssc compare` without the closed loop (report files into out_dir). "
      "average: the host's moving-average window applied to the log, samples (1 = none; a twin "
      "log already carries the host's filter).");

  m.def(
      "write_robot_log",
      [](const std::string& dir, const std::string& scene, double pref, double beta, double step_mm,
         const nb::object& seed, const std::string& effects) {
        std::string scene_path = scene;
        const TrialConfig config =
            MakeConfig(pref, beta, step_mm, SeedArg(seed), "", effects, &scene_path);
        ModelPtr model = Load(scene_path);
        std::string error;
        TrialResult r;
        {
          nb::gil_scoped_release release;
          r = RunTrial(model.get(), config, true, &error);
        }
        std::vector<std::string> written;
        if (!WriteLabRecordingFromTrial(model.get(), r, config, dir, &written, &error)) {
          Fail(error);
        }
        return std::string(OutcomeName(r.outcome));
      },
      "dir"_a, "scene"_a = DefaultScene(), "pref"_a = law.p_ref_pa, "beta"_a = law.beta,
      "step_mm"_a = law.step_mm, "seed"_a = 1, "effects"_a = "default",
      "Runs a trial and writes it as a lab recording (ssc trial --robot-log).");

  m.def("write_lab_mat", &WriteLabMat, "recording"_a, "mat_dir"_a, "append_txt"_a, "args"_a,
        "The lab's DataLog_<stamp>_<append_txt>.mat from a logger recording (folder or one of "
        "its CSVs) and the script's arguments (Pref, beta, d_lat, ..., edgeFollowing_history "
        "rows of 14 numbers); returns its path.");
}

}  // namespace ssc
