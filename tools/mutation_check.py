#!/usr/bin/env python3
"""Mutation check: does the test suite notice small deliberate bugs?

Each mutation below is one small source edit (a sign flip, a threshold moved, a check removed,
a documented default moved by 20 %). The tree is copied to a scratch directory (never the
working tree), each mutation is applied there alone, the targets of the tests that should catch
it are rebuilt incrementally in the scratch build directory, and those tests run through CTest
(each test executable is a CTest label of its own name). A mutation is *caught* when the tests
fail and *survives* when they pass. Not part of CI: a full run takes tens of minutes on 2 cores.

  tools/mutation_check.py                    # all mutations, their own test labels
  tools/mutation_check.py --only outcome-    # mutations whose id starts with a prefix
  tools/mutation_check.py --full             # the whole CTest suite for every mutation
  tools/mutation_check.py --list             # print the mutations and exit

Run it niced (nice -n 10) on a shared machine. The result table (markdown) goes to stdout and,
with --table FILE, to a file; docs/testing.md carries the last one. Exit status 1 when a mutation
survives or a listed edit no longer applies (the list must follow the code).
"""

import argparse
import dataclasses
import filecmp
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


@dataclasses.dataclass
class Mutation:
    id: str
    module: str
    file: str
    find: str  # must occur exactly once in the file
    replace: str
    what: str
    labels: tuple  # CTest labels (= test executable names) expected to catch it


M = Mutation
MUTATIONS = [
    # --- the three survivors of the issue-16 review ---
    M(
        "outcome-grasp-threshold+20",
        "outcomes",
        "trial/trial_outcome.h",
        "double grasp_pa = 10000.0;",
        "double grasp_pa = 12000.0;",
        "failure II threshold raised by 20 %",
        ("trial_metrics_test",),
    ),
    M(
        "plainlog-accepts-backwards-time",
        "robotlog",
        "robotlog/plain_log.cc",
        "if (!log.t_s.empty() && !(v[kT] > log.t_s.back())) {",
        "if (!log.t_s.empty() && v[kT] == log.t_s.back()) {",
        "plain CSV accepts a time stamp before the previous one",
        ("plain_log_test",),
    ),
    M(
        "robotlog-stream-time-unchecked",
        "robotlog",
        "robotlog/robot_log.cc",
        "if (!std::isfinite(s.t_s[i]) || (i > 0 && !(s.t_s[i] > s.t_s[i - 1]))) {",
        "if (!std::isfinite(s.t_s[i])) {",
        "monotonic-time check removed from the stream check",
        ("robot_log_test",),
    ),
    # --- outcomes ---
    M(
        "goal-loop-354",
        "outcomes",
        "trial/trial_goal.h",
        "inline constexpr double kLoopSweepDeg = 355;",
        "inline constexpr double kLoopSweepDeg = 354;",
        "success declared 1 deg early",
        ("trial_metrics_test",),
    ),
    M(
        "goal-loop-half",
        "outcomes",
        "trial/trial_goal.h",
        "inline constexpr double kLoopSweepDeg = 355;",
        "inline constexpr double kLoopSweepDeg = 180;",
        "success declared after half a loop (disk trials only)",
        ("trial_test",),
    ),
    M(
        "goal-band+20",
        "outcomes",
        "trial/trial_goal.h",
        "inline constexpr double kFollowBandM = 0.5e-3 * kCupBodyDiameterMm;",
        "inline constexpr double kFollowBandM = 0.6e-3 * kCupBodyDiameterMm;",
        "band of following 20 % wider",
        ("trial_metrics_test",),
    ),
    M(
        "goal-small-disk-rule",
        "outcomes",
        "trial/trial_goal.cc",
        "if (2 * radius_m < kCupOpeningDiameterMm * 1e-3) {",
        "if (2 * radius_m < 0.9 * kCupOpeningDiameterMm * 1e-3) {",
        "disks down to 9.9 mm count as followable",
        ("trial_metrics_test",),
    ),
    M(
        "outcome-off-edge-threshold+20",
        "outcomes",
        "trial/trial_outcome.h",
        "double off_edge_pa = 5.0;",
        "double off_edge_pa = 6.0;",
        "failure I threshold raised by 20 %",
        ("trial_metrics_test",),
    ),
    M(
        "outcome-grasp-any-chamber",
        "outcomes",
        "trial/trial_outcome.cc",
        "all_grasped = all_grasped && v > t.grasp_pa;",
        "all_grasped = all_grasped || v > t.grasp_pa;",
        "failure II when any (not all) chamber is over the threshold",
        ("trial_metrics_test",),
    ),
    M(
        "outcome-sweep-sign",
        "outcomes",
        "trial/trial_outcome.cc",
        "swept_rad_ += std::remainder(a - last_angle_, 2 * M_PI);",
        "swept_rad_ -= std::remainder(a - last_angle_, 2 * M_PI);",
        "swept angle counted clockwise positive",
        ("trial_metrics_test",),
    ),
    M(
        "robotlog-topic-duplicate-time",
        "robotlog",
        "robotlog/topic_csv.cc",
        "if (!table->t_ns.empty() && t <= table->t_ns.back()) {",
        "if (!table->t_ns.empty() && t < table->t_ns.back()) {",
        "per-topic CSV accepts a duplicate time stamp",
        ("topic_csv_test",),
    ),
    M(
        "robotlog-mat-backwards-time",
        "robotlog",
        "robotlog/mat_log.cc",
        "if (!table->t_ns.empty() && stamp <= table->t_ns.back()) {",
        "if (!table->t_ns.empty() && stamp == table->t_ns.back()) {",
        ".mat log accepts a time stamp before the previous one",
        ("mat_log_test",),
    ),
    M(
        "robotlog-plain-kpa-unchecked",
        "robotlog",
        "robotlog/plain_log.cc",
        "if (peak < kPeakVacuumMinPa) {",
        "if (peak < 0) {",
        "plain CSV in kPa under a _pa column accepted",
        ("plain_log_test",),
    ),
    # --- pneumatics: the documented defaults, each moved by 20 % ---
    M(
        "pneu-pump-max-vacuum+20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double pump_max_vacuum_pa = 40000.0;",
        "double pump_max_vacuum_pa = 48000.0;",
        "pump maximum vacuum +20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-pump-free-flow-20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double pump_free_flow_m3_s = 2.15e-4;",
        "double pump_free_flow_m3_s = 1.72e-4;",
        "pump free flow -20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-jet-area+20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double jet_area_m2 = 7.0e-6;",
        "double jet_area_m2 = 8.4e-6;",
        "tap jet area +20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-neighbour-area+20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double neighbour_area_m2 = 0.5e-6;",
        "double neighbour_area_m2 = 0.6e-6;",
        "neighbour restriction area +20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-neighbour-area-20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double neighbour_area_m2 = 0.5e-6;",
        "double neighbour_area_m2 = 0.4e-6;",
        "neighbour restriction area -20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-port-area-20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double port_area_m2 = 22.0e-6;",
        "double port_area_m2 = 17.6e-6;",
        "port restriction area -20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-tap-recovery-20",
        "pneumatics",
        "plugin/pneumatics/flow_network.h",
        "double tap_recovery = 0.97;",
        "double tap_recovery = 0.776;",
        "tap recovery -20 %",
        ("flow_network_test",),
    ),
    M(
        "pneu-lip-roughness+20",
        "pneumatics",
        "plugin/pneumatics/cup_geometry.h",
        "double lip_roughness_gap_m = 18e-6;",
        "double lip_roughness_gap_m = 21.6e-6;",
        "lip roughness gap +20 %",
        ("flow_network_test", "cup_geometry_test"),
    ),
    M(
        "pneu-pump-curve-sign",
        "pneumatics",
        "plugin/pneumatics/flow_network.cc",
        "r[kNumChambers] -= q_max * (1.0 - port / p_max);",
        "r[kNumChambers] -= q_max * (1.0 - 0.9 * port / p_max);",
        "pump curve slope 10 % shallower in the solver only",
        ("flow_network_test",),
    ),
    M(
        "pneu-tap-adds-jet",
        "pneumatics",
        "plugin/pneumatics/flow_network.cc",
        "sol.tap_pa[i] = x[i] - recovered;",
        "sol.tap_pa[i] = x[i] - 0.5 * recovered;",
        "tap recovers half the jet it should",
        ("flow_network_test",),
    ),
    M(
        "pneu-roughness-leak-dropped",
        "pneumatics",
        "plugin/pneumatics/cup_geometry.cc",
        "double a = curtain_per_m * (z + roughness);",
        "double a = curtain_per_m * z;",
        "lip segments on a surface stop leaking",
        ("cup_geometry_test", "flow_network_test"),
    ),
    M(
        "pneu-jet-share-linear",
        "pneumatics",
        "plugin/pneumatics/cup_geometry.cc",
        "leak.jet_area_m2 += s.area_m2 * w * w;",
        "leak.jet_area_m2 += s.area_m2 * w;",
        "partly open stretches count fully as jet",
        ("cup_geometry_test", "flow_network_test"),
    ),
    M(
        "pneu-chamber-layout-swap",
        "pneumatics",
        "plugin/pneumatics/cup_geometry.cc",
        "if (a >= 0.0) return a < kHalfPi ? 3 : 2;",
        "if (a >= 0.0) return a < kHalfPi ? 2 : 3;",
        "chambers 3 and 4 swapped",
        ("cup_geometry_test",),
    ),
    # --- sensor chain ---
    M(
        "sensor-noise-doubled",
        "sensor chain",
        "plugin/pneumatics/sensor_chain.cc",
        "return clean_pa + params.noise_pa * CounterGaussian(params.seed, sample_index, chamber);",
        "return clean_pa + 2 * params.noise_pa * CounterGaussian(params.seed, sample_index, chamber);",
        "sensor noise twice its sigma",
        ("sensor_chain_test",),
    ),
    M(
        "sensor-lag-sign",
        "sensor chain",
        "plugin/pneumatics/sensor_chain.cc",
        "1.0 - std::exp(-dt / params.lag_s)",
        "1.0 - std::exp(-2 * dt / params.lag_s)",
        "lag time constant halved",
        ("sensor_chain_test",),
    ),
    M(
        "sensor-window-short",
        "sensor chain",
        "plugin/pneumatics/sensor_chain.cc",
        "for (int s = 0; s < n; ++s) {",
        "for (int s = 0; s + 1 < n; ++s) {",
        "moving average drops one sample of the window",
        ("sensor_chain_test",),
    ),
    # --- control law ---
    M(
        "law-correction-sign",
        "control law",
        "controller/contour_law.cc",
        "const double fx = s.along_edge[0] + s.cf * s.correction[0];",
        "const double fx = s.along_edge[0] - s.cf * s.correction[0];",
        "correction term's x part flipped",
        ("contour_law_test",),
    ),
    M(
        "law-cf-above-ref-sign",
        "control law",
        "controller/contour_law.cc",
        "return -params.beta * (x - xr) / (xg - xr);",
        "return params.beta * (x - xr) / (xg - xr);",
        "above P_ref the cup is steered further in",
        ("contour_law_test",),
    ),
    M(
        "law-dpy-sign",
        "control law",
        "controller/contour_law.cc",
        "s.dpy_pa = s.p_west_pa - s.p_east_pa;",
        "s.dpy_pa = s.p_east_pa - s.p_west_pa;",
        "west-east differential flipped",
        ("contour_law_test",),
    ),
    # --- geometry, objects, trial supervisor, studies ---
    M(
        "geom-signed-distance-sign",
        "geometry",
        "geometry/contour_path.cc",
        "return side > 0 ? -pr.distance_m : pr.distance_m;",
        "return side > 0 ? pr.distance_m : -pr.distance_m;",
        "signed distance to a contour with the wrong sign",
        ("objects_test",),
    ),
    M(
        "objects-start-inset",
        "objects",
        "objects/object_spec.h",
        "inline constexpr double kStartInsetM = 0.003;",
        "inline constexpr double kStartInsetM = 0.004;",
        "object trials start 4 mm inside the edge, not the documented 3 mm",
        ("objects_test",),
    ),
    M(
        "runtime-disk-lands-on-centre",
        "trial supervisor",
        "runtime/trial.cc",
        "t.approach = landing == DiskLanding::kAtStart ? t.start : Point2{centre_x_m, centre_y_m};",
        "t.approach = Point2{centre_x_m, centre_y_m};",
        "the disk's cup lands on the centre, not where it starts",
        ("trial_test",),
    ),
    M(
        "plugin-max-press-unchecked",
        "pressure plugin",
        "plugin/chamber_pressure_sensor.cc",
        "if (c.lip_max_press_m > sensor->lip_.max_press_m() + 1e-9) {",
        "if (false) {",
        "a lip_max_press_mm deeper than the tool's lip can take is accepted",
        ("pressure_plugin_test",),
    ),
    M(
        "objects-auto-ignores-step",
        "object tiers",
        "studies/object_trials.cc",
        "return spec.kind == ObjectKind::kCorner && spec.param > 180.0 && step_mm > kCrimpFreeStepMm;",
        "return false;",
        "--scene-kind auto keeps the concave corners on the segment lip at every step",
        ("objects_test",),
    ),
    M(
        "runtime-approach-force-x2",
        "trial supervisor",
        "runtime/trial.cc",
        "if (FtNormalForce() >= config_.approach_force_n || deep_enough) {",
        "if (FtNormalForce() >= 2 * config_.approach_force_n || deep_enough) {",
        "approach stops at twice the start-up force",
        ("trial_test",),
    ),
    M(
        "sweep-resume-ignored",
        "sweep resume",
        "studies/sweep.cc",
        "return done.count(MakeKey(k.p_ref_pa, k.beta, k.step_mm, jobs[i].repeat)) > 0;",
        "return false;",
        "a resumed sweep runs finished rows again",
        ("trial_test",),
    ),
    M(
        "wander-cost-scale",
        "studies",
        "studies/wander_fit.cc",
        "if (t.sigma_r_mm >= 0) cost += std::pow((sigma - t.sigma_r_mm) / 0.2, 2);",
        "if (t.sigma_r_mm >= 0) cost += std::pow((sigma - t.sigma_r_mm) / 0.25, 2);",
        "wander objective scales sigma_r misses by 0.25 mm, not 0.2",
        ("wander_fit_test",),
    ),
    # --- plugin config parsing and checks ---
    M(
        "config-lower-bound-unchecked",
        "plugin config",
        "common/strict_number.cc",
        "if (lo_open ? !(v > lo) : !(v >= lo)) return false;",
        ";",
        "config values below their range accepted",
        ("pressure_plugin_test", "plugin_config_test", "strict_number_test"),
    ),
    M(
        "config-roughness-unit",
        "plugin config",
        "plugin/chamber_pressure_config.cc",
        "SSC_KEY_SCALED(geometry.lip_roughness_gap_m, 1e6, 1e-6)",
        "SSC_KEY_SCALED(geometry.lip_roughness_gap_m, 1e6, 1.2e-6)",
        "lip_roughness_um converted 20 % off",
        ("plugin_config_test", "pressure_plugin_test"),
    ),
    M(
        "plugin-no-lip-accepted",
        "plugin config",
        "plugin/chamber_pressure_sensor.cc",
        "if (sensor->lip_geoms_.empty() || sensor->lip_geoms_.size() > kMaxLipSegments) {",
        "if (sensor->lip_geoms_.size() > kMaxLipSegments) {",
        "a cup without lip segments accepted",
        ("pressure_plugin_test",),
    ),
    # --- metrics ---
    M(
        "metrics-dr-sign",
        "metrics",
        "trial/trial_metrics.cc",
        "m.dr_mm = (r_mean - radius) * 1e3;",
        "m.dr_mm = (radius - r_mean) * 1e3;",
        "radial offset sign flipped",
        ("trial_metrics_test",),
    ),
    M(
        "metrics-sc-offset",
        "metrics",
        "trial/trial_metrics.cc",
        "m.s_c = s / (2 * M_PI * radius) - 1;",
        "m.s_c = s / (2 * M_PI * radius);",
        "path-length ratio not minus one",
        ("trial_metrics_test",),
    ),
]


def run(cmd, cwd=None, timeout=None, env=None):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)


def tree_files():
    out = run(["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"], cwd=ROOT)
    return [f for f in out.stdout.split("\0") if f and os.path.isfile(os.path.join(ROOT, f))]


def sync_tree(src):
    """Copies the working tree into src, touching only files whose content changed."""
    files = set(tree_files())
    for rel in files:
        a, b = os.path.join(ROOT, rel), os.path.join(src, rel)
        if os.path.exists(b) and filecmp.cmp(a, b, shallow=False):
            continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copy2(a, b)
        os.utime(b)  # newer than the scratch build's objects
    for dirpath, _, names in os.walk(src):
        if os.path.basename(dirpath) == ".git" or "/.venv" in dirpath:
            continue
        for n in names:
            rel = os.path.relpath(os.path.join(dirpath, n), src)
            if rel not in files and not rel.startswith(".venv"):
                os.remove(os.path.join(dirpath, n))
    venv = os.path.join(src, ".venv")
    if not os.path.lexists(venv) and os.path.exists(os.path.join(ROOT, ".venv")):
        os.symlink(os.path.realpath(os.path.join(ROOT, ".venv")), venv)


def targets_for(labels):
    targets = {"ssc_plugin"}
    for label in labels:
        targets.update(["ssc"] if label == "python" else [label])
    return sorted(targets)


def build(build_dir, targets, jobs, log):
    r = run(["cmake", "--build", build_dir, "-j", str(jobs), "--target", *targets], timeout=3600)
    log.write(r.stdout[-4000:] + r.stderr[-4000:])
    return r.returncode == 0


def ctest(build_dir, labels, jobs, timeout, log):
    cmd = ["ctest", "-j", str(jobs), "--timeout", str(timeout), "--output-on-failure"]
    if labels:
        cmd += ["-L", "^(" + "|".join(labels) + ")$"]
    r = run(cmd, cwd=build_dir, timeout=7200)
    log.write(r.stdout[-6000:] + r.stderr[-2000:])
    # Summary lines: "\t  5 - FlowNetworkTest.Name (Failed)".
    failed = [
        l.split(" - ", 1)[1].strip()
        for l in r.stdout.splitlines()
        if l.startswith("\t") and " - " in l
    ]
    return r.returncode, failed, r.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument(
        "--scratch", default=os.path.join("/tmp", "ssc_mutation_" + os.path.basename(ROOT))
    )
    ap.add_argument("--only", default="", help="run mutations whose id starts with this prefix")
    ap.add_argument("--full", action="store_true", help="whole CTest suite for each mutation")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--test-timeout", type=int, default=300, help="seconds per test")
    ap.add_argument("--table", help="also write the markdown table here")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()

    chosen = [m for m in MUTATIONS if m.id.startswith(args.only)]
    if args.list:
        for m in chosen:
            print(f"{m.id:36s} {m.module:12s} {m.file}: {m.what}")
        return 0
    ids = [m.id for m in MUTATIONS]
    assert len(ids) == len(set(ids)), "duplicate mutation id"

    src, build_dir = os.path.join(args.scratch, "src"), os.path.join(args.scratch, "build")
    os.makedirs(args.scratch, exist_ok=True)
    log = open(os.path.join(args.scratch, "mutation_check.log"), "w")
    print(f"[mutation] scratch copy {src}, build {build_dir}", file=sys.stderr)
    sync_tree(src)
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        r = run(
            [
                "cmake",
                "-S",
                src,
                "-B",
                build_dir,
                "-DCMAKE_BUILD_TYPE=Release",
                "-DSSC_PYTHON=" + os.path.join(src, ".venv", "bin", "python"),
            ]
        )
        if r.returncode != 0:
            print(r.stdout + r.stderr, file=sys.stderr)
            return 2

    # Every edit must still apply: a stale list would silently test nothing.
    stale = []
    for m in chosen:
        text = (
            open(os.path.join(src, m.file)).read()
            if os.path.exists(os.path.join(src, m.file))
            else ""
        )
        if text.count(m.find) != 1:
            stale.append(f"{m.id}: '{m.find}' occurs {text.count(m.find)} times in {m.file}")
    for s in stale:
        print("[mutation] STALE " + s, file=sys.stderr)
    chosen = [m for m in chosen if not any(s.startswith(m.id + ":") for s in stale)]

    def labels_of(m):
        return None if args.full else list(m.labels)

    def targets_of(m):
        return ["all"] if args.full else targets_for(m.labels)

    # Baseline: the unmutated tree must pass the tests each mutation relies on.
    all_labels = sorted({l for m in chosen for l in m.labels})
    print("[mutation] baseline build and tests", file=sys.stderr)
    if not build(build_dir, ["all"] if args.full else targets_for(all_labels), args.jobs, log):
        print("[mutation] baseline does not build; see " + log.name, file=sys.stderr)
        return 2
    rc, failed, _ = ctest(
        build_dir, None if args.full else all_labels, args.jobs, args.test_timeout, log
    )
    if rc != 0:
        print("[mutation] baseline fails: " + "; ".join(failed), file=sys.stderr)
        return 2

    rows = []
    for m in chosen:
        path = os.path.join(src, m.file)
        original = open(path).read()
        t0 = time.time()
        try:
            open(path, "w").write(original.replace(m.find, m.replace))
            log.write(f"\n===== {m.id} =====\n")
            if not build(build_dir, targets_of(m), args.jobs, log):
                verdict, detail = "build error", "the mutant does not compile"
            else:
                rc, failed, _ = ctest(build_dir, labels_of(m), args.jobs, args.test_timeout, log)
                verdict = "caught" if rc != 0 else "SURVIVED"
                detail = "; ".join(failed[:3]) + (
                    f" (+{len(failed) - 3})" if len(failed) > 3 else ""
                )
        finally:
            open(path, "w").write(original)
        rows.append((m, verdict, detail, time.time() - t0))
        print(
            f"[mutation] {m.id:36s} {verdict:9s} {time.time() - t0:6.0f} s  {detail}",
            file=sys.stderr,
        )
    # Leave the scratch build matching the tree again.
    build(build_dir, ["all"] if args.full else targets_for(all_labels), args.jobs, log)

    lines = [
        "| mutation | module | edit | tests run | result | first failing tests |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for m, verdict, detail, _ in rows:
        scope = "all (ctest)" if args.full else ", ".join(m.labels)
        lines.append(
            f"| `{m.id}` | {m.module} | {m.what} (`{m.file}`) | {scope} | {verdict} | {detail} |"
        )
    caught = sum(1 for r in rows if r[1] == "caught")
    lines.append("")
    lines.append(
        f"{caught} of {len(rows)} caught; survived: "
        f"{', '.join(r[0].id for r in rows if r[1] == 'SURVIVED') or 'none'}; "
        f"build errors: {sum(1 for r in rows if r[1] == 'build error')}; "
        f"stale edits: {len(stale)}."
    )
    table = "\n".join(lines)
    print(table)
    if args.table:
        open(args.table, "w").write(table + "\n")
    return 1 if stale or any(r[1] != "caught" for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
