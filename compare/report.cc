#include "compare/report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "common/output_file.h"

namespace ssc {
namespace {

using nlohmann::json;

// NaN and infinity have no JSON form: null.
json Num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json Array4(const std::array<double, 4>& a) {
  return json::array({Num(a[0]), Num(a[1]), Num(a[2]), Num(a[3])});
}

json Metrics(const DiskTrialMetrics& m) {
  return {{"dr_mm", Num(m.dr_mm)},
          {"sigma_r_mm", Num(m.sigma_r_mm)},
          {"s_c", Num(m.s_c)},
          {"duration_s", Num(m.duration_s)},
          {"speed_mm_s", Num(m.speed_mm_s)},
          {"path_length_mm", Num(m.s_mm)}};
}

json SetupJson(const ComparisonSetup& s) {
  json frames = {
      {"log_frame", s.log_frame},
      {"scene_object",
       {{"name", s.scene_object.name},
        {"x_m", s.scene_object.x_m},
        {"y_m", s.scene_object.y_m},
        {"top_z_m", s.scene_object.top_z_m},
        {"radius_m", Num(s.scene_object.radius_m)},
        {"half_size_m", {s.scene_object.half_size_m[0], s.scene_object.half_size_m[1]}}}},
      {"closest_approach_mm", Num(s.reach.closest_m * 1e3)},
      {"closest_approach_t_s", Num(s.reach.t_s)},
      {"closest_approach_tcp_m", {s.reach.tcp_m[0], s.reach.tcp_m[1], s.reach.tcp_m[2]}},
      {"twin_contact_depth_mm", Num(s.contact_depth_m * 1e3)}};
  if (s.object.known) {
    frames["object_pose"] = {{"x_m", s.object.x_m},
                             {"y_m", s.object.y_m},
                             {"top_z_m", s.object.top_z_m},
                             {"yaw_deg", s.object.yaw_rad * 180 / M_PI},
                             {"radius_m", Num(s.object.radius_m)},
                             {"source", s.object.source},
                             {"note", s.object.note}};
  }
  json X = json::array();
  for (int r = 0; r < 4; ++r) {
    json row = json::array();
    for (int c = 0; c < 4; ++c) row.push_back(s.X_scene_log.matrix()(r, c));
    X.push_back(row);
  }
  frames["X_scene_log"] = X;
  return frames;
}

std::string Fmt(const char* format, double a, double b = 0, double c = 0, double d = 0,
                double e = 0) {
  char buf[512];
  // The format uses as many of a..e as it names; the rest are passed and ignored.
  // cppcheck-suppress wrongPrintfScanfArgNum
  std::snprintf(buf, sizeof(buf), format, a, b, c, d, e);
  return buf;
}

json ReplayJson(const ReplayComparison& c) {
  json chambers = json::array();
  for (int k = 0; k < 4; ++k) {
    chambers.push_back({{"rms_pa", Num(c.rms_pa[k])},
                        {"rms_log10", Num(c.rms_log10[k])},
                        {"correlation", Num(c.correlation[k])},
                        {"mean_ratio", Num(c.mean_ratio[k])}});
  }
  return {{"chambers", chambers},
          {"pbar_rms_pa", Num(c.pbar_rms_pa)},
          {"pbar_bias_pa", Num(c.pbar_bias_pa)},
          {"direction_rms_deg", Num(c.direction_rms_deg)},
          {"direction_median_deg", Num(c.direction_median_deg)},
          {"direction_samples", c.direction_samples}};
}

// report.md's head: the log, the frames and the replay's pressure table.
void WriteReplayMarkdown(const ComparisonSetup& setup, const ReplayComparison& c, double duration_s,
                         std::ostream& md) {
  md << "# Twin against robot log: " << setup.log_path << "\n\n"
     << "Format: " << setup.format << ". Replay of the logged tool path; " << c.t_s.size()
     << " pressure samples over " << Fmt("%.1f", duration_s)
     << " s.\n\n## Frames\n\nLog frame: " << setup.log_frame << ". ";
  if (setup.object.known) {
    md << Fmt("Object in the log frame: centre (%.4f, %.4f) m, top z %.4f m, yaw %.1f deg",
              setup.object.x_m, setup.object.y_m, setup.object.top_z_m,
              setup.object.yaw_rad * 180 / M_PI)
       << ", from " << setup.object.source << (setup.object.note.empty() ? "" : "; ")
       << setup.object.note << ". ";
  } else if (setup.log_frame != "scene") {
    md << "No object pose (the log's base frame is placed at the scene origin). ";
  }
  md << "Scene object '" << setup.scene_object.name << "'"
     << Fmt(" at (%.4f, %.4f) m, top z %.4f m; closest approach of the tool centre %.1f mm.\n\n",
            setup.scene_object.x_m, setup.scene_object.y_m, setup.scene_object.top_z_m,
            setup.reach.closest_m * 1e3)
     << "| chamber | RMS error (Pa) | RMS error (log10) | correlation | mean sim / mean log |\n"
     << "| --- | --- | --- | --- | --- |\n";
  for (int k = 0; k < 4; ++k) {
    md << Fmt("| %.0f | %.1f | %.3f | ", k + 1, c.rms_pa[k], c.rms_log10[k])
       << CorrelationText(c.correlation[k]) << Fmt(" | %.3f |\n", c.mean_ratio[k]);
  }
  md << Fmt("\nMean pressure: RMS error %.1f Pa, bias (sim - log) %.1f Pa.\n", c.pbar_rms_pa,
            c.pbar_bias_pa)
     << Fmt("Direction the controller would compute (g): RMS angle error %.1f deg, median %.1f "
            "deg over %.0f samples with both differentials above P_n.\n",
            c.direction_rms_deg, c.direction_median_deg, c.direction_samples);
}

json HistoryJson(const HistoryComparison& h) {
  return {{"iterations", h.iterations},
          {"time_offset_s", h.time_offset_s},
          {"match_rms_mm", h.match_rms_mm},
          {"history_in_ur_base", h.history_in_ur_base},
          {"r_p_median_deg", Num(h.r_p_median_deg)},
          {"r_p_rms_deg", Num(h.r_p_rms_deg)},
          {"corr_p_median_deg", Num(h.corr_p_median_deg)},
          {"corr_p_samples", h.corr_p_samples},
          {"r_p_final_median_deg", Num(h.r_p_final_median_deg)},
          {"p_rms_pa", Array4(h.p_rms_pa)},
          {"p_correlation", Array4(h.p_correlation)},
          {"p_mean_ratio", Array4(h.p_mean_ratio)},
          {"f_normal_rms_n", Num(h.f_normal_rms_n)},
          {"f_normal_bias_n", Num(h.f_normal_bias_n)}};
}

void WriteHistoryMarkdown(const HistoryComparison& h, std::ostream& md) {
  md << "\n## Controller, iteration by iteration (edgeFollowing_history)\n\n"
     << Fmt("%.0f iterations; log time = history time + %.3f s (x, y on the logged path to "
            "%.2f mm RMS)",
            h.iterations, h.time_offset_s, h.match_rms_mm)
     << (h.history_in_ur_base ? "; the history's x, y are in the UR Base frame" : "")
     << ".\n\n| quantity | twin vs lab |\n| --- | --- |\n"
     << Fmt("| r_p direction | median %.1f deg, RMS %.1f deg |\n", h.r_p_median_deg, h.r_p_rms_deg)
     << Fmt("| corr_p direction | median %.1f deg over %.0f iterations |\n", h.corr_p_median_deg,
            h.corr_p_samples)
     << Fmt("| r_p_final direction | median %.1f deg |\n", h.r_p_final_median_deg)
     << Fmt("| F_normal | RMS %.2f N, bias %.2f N |\n", h.f_normal_rms_n, h.f_normal_bias_n);
  for (int k = 0; k < 4; ++k) {
    md << Fmt("| P%.0f | RMS %.1f Pa, correlation ", k + 1, h.p_rms_pa[k])
       << CorrelationText(h.p_correlation[k]) << Fmt(", mean ratio %.3f |\n", h.p_mean_ratio[k]);
  }
}

void WriteHistoryCsv(const HistoryComparison& h, std::ostream& hist) {
  hist << "t_log_s,x_m,y_m,lab_r_p_y,lab_r_p_x,twin_r_p_y,twin_r_p_x,r_p_deg,corr_p_deg,"
          "r_p_final_deg,lab_f_normal_n,twin_f_normal_n,lab_p1_pa,lab_p2_pa,lab_p3_pa,"
          "lab_p4_pa,twin_p1_pa,twin_p2_pa,twin_p3_pa,twin_p4_pa\n";
  for (const HistoryPair& p : h.rows) {
    hist << p.t_log_s << ',' << p.lab.x_m << ',' << p.lab.y_m << ',' << p.lab.r_p[0] << ','
         << p.lab.r_p[1] << ',' << p.twin.r_p[0] << ',' << p.twin.r_p[1] << ',' << p.r_p_deg << ','
         << p.corr_p_deg << ',' << p.r_p_final_deg << ',' << p.lab.f_normal_n << ','
         << p.twin_f_normal_n;
    for (int k = 0; k < 4; ++k) hist << ',' << -p.lab.p_pa[k];
    for (int k = 0; k < 4; ++k) hist << ',' << p.twin_vacuum_pa[k];
    hist << '\n';
  }
}

json ClosedLoopJson(const ClosedLoopComparison& closed) {
  return {{"twin_outcome", closed.twin_outcome},
          {"start_t_s", closed.start_t_s},
          {"parameters", closed.parameters},
          {"controller", closed.controller},
          {"log", Metrics(closed.log)},
          {"twin", Metrics(closed.twin)},
          {"path_distance_mean_mm", Num(closed.path_distance_mean_mm)},
          {"path_distance_max_mm", Num(closed.path_distance_max_mm)}};
}

void WriteClosedLoopMarkdown(const ClosedLoopComparison& closed, std::ostream& md) {
  const DiskTrialMetrics& a = closed.log;
  const DiskTrialMetrics& b = closed.twin;
  md << "\n## Closed loop\n\nThe twin's controller `" << closed.controller
     << "` from the log's start (t = " << Fmt("%.2f", closed.start_t_s) << " s) with "
     << closed.parameters << "; outcome " << closed.twin_outcome
     << ".\n\n| metric | robot log | twin |\n| --- | --- | --- |\n"
     << Fmt("| dr (mm) | %.2f | %.2f |\n", a.dr_mm, b.dr_mm)
     << Fmt("| sigma_r (mm) | %.2f | %.2f |\n", a.sigma_r_mm, b.sigma_r_mm)
     << Fmt("| s_c | %.3f | %.3f |\n", a.s_c, b.s_c)
     << Fmt("| duration (s) | %.1f | %.1f |\n", a.duration_s, b.duration_s)
     << Fmt("| speed (mm/s) | %.1f | %.1f |\n", a.speed_mm_s, b.speed_mm_s)
     << Fmt("\nTwin path to logged path: mean %.2f mm, max %.2f mm.\n",
            closed.path_distance_mean_mm, closed.path_distance_max_mm);
}

void WriteSeriesCsv(const ReplayComparison& c, std::ostream& series) {
  series << "t_s,x_m,y_m,z_m,sim_p1_pa,sim_p2_pa,sim_p3_pa,sim_p4_pa,log_p1_pa,log_p2_pa,"
            "log_p3_pa,log_p4_pa\n";
  char buf[512];
  for (size_t i = 0; i < c.t_s.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%.4f,%.6f,%.6f,%.6f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f\n",
                  c.t_s[i], c.tcp_m[i][0], c.tcp_m[i][1], c.tcp_m[i][2], c.sim_pa[i][0],
                  c.sim_pa[i][1], c.sim_pa[i][2], c.sim_pa[i][3], c.log_pa[i][0], c.log_pa[i][1],
                  c.log_pa[i][2], c.log_pa[i][3]);
    series << buf;
  }
}

}  // namespace

bool WriteComparisonReport(const std::string& dir, const ComparisonSetup& setup,
                           const ReplayComparison& c, const HistoryComparison* history,
                           const ClosedLoopComparison* closed, std::string* error) {
  namespace fs = std::filesystem;
  if (!CreateRecordedDirectories(dir, error)) return false;
  const double duration_s = c.t_s.empty() ? 0.0 : c.t_s.back() - c.t_s.front();
  json report;
  report["log"] = {{"path", setup.log_path},
                   {"format", setup.format},
                   {"samples", c.t_s.size()},
                   {"duration_s", duration_s}};
  report["frames"] = SetupJson(setup);
  report["replay"] = ReplayJson(c);

  // Each file whole or not at all (common/output_file.h), committed together at the end.
  OutputFile md_file((fs::path(dir) / "report.md").string());
  WriteReplayMarkdown(setup, c, duration_s, md_file.stream());
  std::unique_ptr<OutputFile> hist_file;
  if (history && history->ran) {
    report["history"] = HistoryJson(*history);
    WriteHistoryMarkdown(*history, md_file.stream());
    hist_file = std::make_unique<OutputFile>((fs::path(dir) / "history.csv").string());
    WriteHistoryCsv(*history, hist_file->stream());
  }
  if (closed && closed->ran) {
    report["closed_loop"] = ClosedLoopJson(*closed);
    WriteClosedLoopMarkdown(*closed, md_file.stream());
  }
  OutputFile js_file((fs::path(dir) / "report.json").string());
  js_file.Write(report.dump(2) + "\n");
  OutputFile series_file((fs::path(dir) / "series.csv").string());
  WriteSeriesCsv(c, series_file.stream());
  return md_file.Commit(error) && js_file.Commit(error) && series_file.Commit(error) &&
         (!hist_file || hist_file->Commit(error));
}

}  // namespace ssc
