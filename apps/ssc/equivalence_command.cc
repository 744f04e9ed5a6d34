// ssc equivalence: two models of the cup on the same map cells and seeds, compared by statistics.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

#include "apps/ssc/cli.h"
#include "apps/ssc/commands.h"
#include "apps/ssc/trial_options.h"
#include "runtime/rig.h"
#include "studies/equivalence_study.h"
#include "studies/jobs/job_runner.h"

namespace ssc {
namespace {

// "key=value,key=value" -> plugin config; "" or the problem.
std::string ParsePluginKeys(const std::string& text, PluginConfig* config) {
  config->clear();
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const std::size_t eq = item.find('=');
    if (item.empty() || eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      return "--plugin: '" + item + "' is not key=value (e.g. lip_bending_nmm2=1.2)";
    }
    const std::string key = item.substr(0, eq);
    if (config->count(key)) return "--plugin: key '" + key + "' is given twice";
    (*config)[key] = item.substr(eq + 1);
  }
  return "";
}

void PrintArm(const char* role, const EquivalenceArm& arm, const MapScore& score,
              const SweepSummary& summary) {
  double busy = 0;
  for (double b : summary.rank_busy_s) busy += b;
  std::string plugin;
  for (const auto& [k, v] : arm.plugin) plugin += (plugin.empty() ? " plugin " : ",") + k + "=" + v;
  std::printf(
      "%-10s %s%s (seed %llu): expected agreement %.3f (%.3f-%.3f), %d trials run in %.1f "
      "s wall, %.1f trial-s\n",
      role, arm.scene_name.c_str(), plugin.c_str(), static_cast<unsigned long long>(arm.seed),
      score.expected_agreement, score.agreement_interval[0], score.agreement_interval[1],
      summary.ran, summary.wall_s, busy);
  if (const std::string note = AgreementIntervalNote(score); !note.empty()) {
    std::printf("%-10s (%s)\n", "", note.c_str());
  }
}

}  // namespace

int RunEquivalenceCommand(int argc, char** argv) {
  cli::Command cmd(
      "equivalence",
      "Runs two models of the cup on the same cells of a published map with the same seeds\n"
      "(the reference, by default the UR-10 scene, and a candidate: another scene, or other\n"
      "plugin keys or robot effects) and compares them by statistics: per cell Fisher's exact\n"
      "test of the two success rates and how many cells differ against chance, the difference\n"
      "of the map score with its 95 % interval, the Fig. 6 targets side by side. Writes\n"
      "OUT/reference/, OUT/candidate/ (each as ssc validate, resumable), OUT/equivalence.csv\n"
      "and OUT/equivalence.json. Reports figures; it does not pass or fail.");
  EquivalenceSpec spec;
  spec.map_path = SourceDir() + "/data/published/success_map_dl5.csv";
  spec.reference.scene_name = RigTierFor(RigUse::kReference).scene;
  spec.candidate.scene_name = DefaultScene();
  long seeds = 10, threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "out/equivalence", plugin_text, candidate_effects;
  std::uint64_t candidate_seed = 0;
  bool no_progress = false, no_shared_approach = false;
  TrialSettings settings;
  TrialConfig base;
  cmd.Text("map", &spec.map_path, "published map CSV (step_mm,beta,pref_pa,successes_of_3)");
  cmd.Text("reference", &spec.reference.scene_name,
           "the reference scene (name under scenes/ or a path)");
  cmd.Text("scene", &spec.candidate.scene_name, "the candidate scene (name or path)");
  cmd.Text("plugin", &plugin_text,
           "the candidate's pressure-plugin keys, key=value,... (docs/plugin.md)");
  cmd.Text("candidate-effects", &candidate_effects,
           "the candidate's robot effects, key=value,... over --effects (or 'off', 'default')");
  cmd.Integer("seeds", &seeds, "trials per cell and model", NumberRange::Closed(3, 10000));
  cmd.Seed("seed", &spec.reference.seed, "base seed, as ssc sweep --seed");
  cmd.Seed("candidate-seed", &candidate_seed,
           "the candidate's base seed (default: --seed, the same seeds as the reference)");
  cmd.Number("alpha", &spec.options.alpha, "level of each test", "",
             NumberRange::Positive(1).OpenHigh());
  AddThreadsOption(&cmd, &threads);
  cmd.OutputDir("out", &out_dir, "output directory");
  cmd.Flag("no-progress", &no_progress, "no progress bar even on a terminal");
  cmd.Flag("no-shared-approach", &no_shared_approach,
           "simulate every trial's approach itself (as ssc sweep --no-shared-approach)");
  AddTrialSettingOptions(&cmd, &base, &settings);
  cmd.Check([&]() {
    spec.reference.base = base;
    spec.candidate.base = base;
    std::string error;
    if (!candidate_effects.empty() &&
        !ParseRobotEffects(candidate_effects, &spec.candidate.base.effects, &error)) {
      return "--candidate-effects: " + error;
    }
    if (const std::string e = spec.candidate.base.Validate(); !e.empty()) {
      return "--candidate-effects: " + e;
    }
    return plugin_text.empty() ? std::string()
                               : ParsePluginKeys(plugin_text, &spec.candidate.plugin);
  });
  if (int rc = 0; !cmd.Parse(argc, argv, &rc)) return rc;
  spec.seeds = static_cast<int>(seeds);
  spec.threads = static_cast<int>(threads);
  spec.out_dir = out_dir;
  spec.share_approach = !no_shared_approach;
  spec.candidate.seed = cmd.Given("candidate-seed") ? candidate_seed : spec.reference.seed;
  if (int rc = cmd.CreateOutputs(); rc != 0) return rc;

  const bool rank0 = JobRunnerRank() == 0;
  const bool bar = rank0 && !no_progress && isatty(STDERR_FILENO);
  auto progress = [&](int arm, const SweepProgress& s) {
    if (!bar) return;
    std::fprintf(stderr, "\r%s: %d/%d trials  %.0f s ", arm == 0 ? "reference" : "candidate",
                 s.done, s.total, s.elapsed_s);
    std::fflush(stderr);
  };
  EquivalenceRun run;
  std::string error;
  if (!RunEquivalence(spec, progress, &run, &error)) {
    std::fprintf(stderr, "%sssc equivalence: %s\n", bar ? "\n" : "", error.c_str());
    return 1;
  }
  if (bar) std::fprintf(stderr, "\n");
  if (!rank0) return 0;
  const Equivalence& e = run.result;
  std::printf("%-6s %-5s %-7s %-9s %-9s %-9s %-8s %s\n", "dL_mm", "beta", "Pref_Pa", "published",
              "reference", "candidate", "Fisher p", "P(false alarm)");
  for (const CellDifference& d : e.cells) {
    std::printf("%-6g %-5g %-7g %-9s %3d/%-5d %3d/%-5d %-8.3f %.3f%s\n", d.cell.step_mm,
                d.cell.beta, d.cell.pref_pa, MapClassName(d.cell.published), d.a.successes,
                d.a.trials, d.b.successes, d.b.trials, d.p_value, d.false_alarm_chance,
                d.differs ? "  DIFFERS" : "");
  }
  std::printf("\n");
  PrintArm("reference", spec.reference, run.reference_score, run.reference_summary);
  PrintArm("candidate", spec.candidate, run.candidate_score, run.candidate_summary);
  const DifferingCells& c = e.differing;
  std::printf(
      "cells differing at %g: %d of %d; chance alone gives %.2f (exact, Fisher being discrete; "
      "%.2f for a continuous test), P(>= %d by chance) = %.3f\n",
      c.alpha, c.differing, c.cells, c.expected_by_chance, c.nominal_by_chance, c.differing,
      c.p_at_least);
  std::printf(
      "successes over all cells: reference %d of %d, candidate %d of %d; a common shift "
      "(Cochran-Mantel-Haenszel) p = %.3g\n",
      e.shift.successes_a, e.shift.trials_a, e.shift.successes_b, e.shift.trials_b,
      e.shift.p_value);
  std::printf(
      "map score (expected agreement) candidate - reference: %+.3f (95 %% interval %+.3f to "
      "%+.3f, posterior p %.3g)\n",
      e.score.difference, e.score.interval[0], e.score.interval[1], e.score.p_value);
  std::printf(
      "published Fig. 6 targets (mean over the successful trials +- standard error, "
      "successes):\n");
  std::printf("  %-30s %9s  %-24s %-24s %-18s %s\n", "target", "published", "reference",
              "candidate", "difference", "Welch p");
  for (const TargetDifference& t : e.targets) {
    if (t.a.n == 0 && t.b.n == 0) continue;  // its cell is not in this map or never succeeded
    auto measure = [](const TargetMeasure& m) {
      char text[48] = "-";
      if (m.n > 0)
        std::snprintf(text, sizeof text, "%7.3f +- %5.3f (%2d)", m.mean, m.standard_error, m.n);
      return std::string(text);
    };
    char d[48] = "-", p[16] = "-";
    if (t.tested) {
      std::snprintf(d, sizeof d, "%+7.3f +- %5.3f", t.difference, t.standard_error);
      std::snprintf(p, sizeof p, "%.3f", t.p_value);
    }
    std::printf("  %-30s %9.3g  %-24s %-24s %-18s %s%s\n", t.name.c_str(), t.published,
                measure(t.a).c_str(), measure(t.b).c_str(), d, p, t.differs ? "  DIFFERS" : "");
  }
  std::printf("targets differing at %g: %d of %d tested, P(>= %d by chance) = %.3f\n", c.alpha,
              e.targets_differing, e.targets_tested, e.targets_differing, e.targets_p_at_least);
  const double level = e.differing.alpha / e.views;
  std::printf(
      "verdict: %s (Bonferroni over %d views, each p against %.4f: cells %.3g, common shift "
      "%.3g, score %.3g%s)\n",
      e.same ? "no difference beyond chance" : "DIFFERENT", e.views, level, c.p_at_least,
      e.shift.p_value, e.score.p_value,
      e.targets_tested > 0 ? (", targets " + std::to_string(e.targets_p_at_least)).c_str() : "");
  PrintApproachSharing(spec.share_approach, run.candidate_summary);
  std::printf("wrote %s/equivalence.csv, %s/equivalence.json\n", out_dir.c_str(), out_dir.c_str());
  return 0;
}

}  // namespace ssc
