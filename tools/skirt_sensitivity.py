#!/usr/bin/env python3
"""Sensitivity of the flex skirt lip to its unpublished parameters (docs/flex_cost.md, "Sensitivity
of the flex lip").

Each variant is the skirt of tools/make_flex_tool.py with one parameter at an end of its argued
range (the SKIRT table), the others at their values; the baseline is the model as it stands. Per
variant, seed 1, the flex tier:
  - the straight-edge static reading: the cup held 0.3 mm into a plate, its centre 2.5 mm inside
    the edge (`ssc probe --scene probe_edge_flex`, 0.1 s to settle): mean P and |(dPx, dPy)|;
  - the approach compression: the lip plane below the top face when following starts;
  - one concave corner (corner_a270) and the fillet (`ssc objects --scene-kind flex`): outcome,
    and on the fillet |dP| at the sharp start (mean over 10-20 mm along the edge) and where
    tracking ended (arc position and fillet radius there).

Usage: tools/skirt_sensitivity.py [--ssc build/bin/ssc] [--out out/skirt_sensitivity]
                                  [--threads 2] [--params height_mm,friction,...]
                                  [--static-only]  (the probe only: seconds per variant)
Writes OUT/sensitivity.md (a Markdown table) and OUT/<variant>/ (its runs). Variants run in a
copy of the resources (SSC_RESOURCE_DIR) whose models/ssc_tool_flex.xml is the variant.
"""

import argparse
import csv
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import make_flex_tool  # noqa: E402  (the one home of the skirt's parameters)

# The argued range of each unpublished parameter (the SKIRT table's "range and why").
RANGES = {
    "height_mm": (2.0, 4.0),
    "flare": (1.0, 2.0),
    "thickness_mm": (0.5, 1.0),
    "young_mpa": (1.2, 2.0),
    "friction": (0.5, 1.0),
    "bellows_n_per_mm": (0.5, 3.0),
}
OBJECTS = "corner_a270,fillet"
PRESS_MM = 0.3  # the approach's press with the skirt (docs/flex_skirt.md)


def resources(variant_dir, overrides):
    """A resource dir: the repository's models and scenes with the variant skirt model."""
    res = variant_dir / "res"
    if res.exists():
        shutil.rmtree(res)
    (res / "models").mkdir(parents=True)
    for f in (ROOT / "models").iterdir():
        (res / "models" / f.name).symlink_to(f)
    (res / "models" / "ssc_tool_flex.xml").unlink()
    args = [
        sys.executable,
        str(ROOT / "tools" / "make_flex_tool.py"),
        "--out",
        str(res / "models" / "ssc_tool_flex.xml"),
    ]
    for k, v in overrides.items():
        args += ["--set", f"{k}={v}"]
    subprocess.run(args, check=True)
    # A copy, not a link: scenes written from these templates (ssc objects) resolve the tool's
    # path through the template's real folder, and a linked folder leads back to the repository's
    # own skirt.
    shutil.copytree(ROOT / "scenes", res / "scenes")
    return res


def run(cmd, env, log):
    with open(log, "w") as f:
        r = subprocess.run(cmd, env=env, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed (exit {r.returncode}); see {log}")


def measure(ssc, variant_dir, overrides, threads, static_only):
    res = resources(variant_dir, overrides)
    env = dict(os.environ, SSC_RESOURCE_DIR=str(res))
    c0 = os.times()
    run(
        [
            ssc,
            "probe",
            "--scene",
            "probe_edge_flex",
            "--from",
            "2.5",
            "--to",
            "2.5",
            "--compression",
            str(PRESS_MM),
            "--disk-step",
            "360",
            "--no-plot",
            "--out",
            str(variant_dir / "probe"),
        ],
        env,
        variant_dir / "probe.log",
    )
    with open(variant_dir / "probe" / "edge.csv") as f:
        edge = next(csv.DictReader(f))
    if static_only:
        c1 = os.times()
        return {
            "pbar": float(edge["pbar_pa"]),
            "diff": float(edge["diff_pa"]),
            "compression": float("nan"),
            "corner": "not run",
            "sharp": float("nan"),
            "fillet": "not run",
            "cpu_s": (c1.children_user + c1.children_system)
            - (c0.children_user + c0.children_system),
        }
    run(
        [
            ssc,
            "objects",
            "--scene-kind",
            "flex",
            "--objects",
            OBJECTS,
            "--seeds",
            "1",
            "--seed",
            "1",
            "--threads",
            str(threads),
            "--no-plot",
            "--out",
            str(variant_dir / "objects"),
        ],
        env,
        variant_dir / "objects.log",
    )
    c1 = os.times()
    cpu_s = (c1.children_user + c1.children_system) - (c0.children_user + c0.children_system)
    with open(variant_dir / "objects" / "objects.csv") as f:
        rows = {r["object"]: r for r in csv.DictReader(f)}
    sharp = []
    with open(variant_dir / "objects" / "fillet_profile.csv") as f:
        for r in csv.DictReader(f):
            if 10 <= float(r["x_mm"]) <= 20:
                sharp.append(float(r["diff_pa"]))
    fillet, corner = rows["fillet"], rows["corner_a270"]
    return {
        "pbar": float(edge["pbar_pa"]),
        "diff": float(edge["diff_pa"]),
        "compression": float(fillet["approach_compression_mm"]),
        "corner": f"{corner['outcome']} ({float(corner['end_arc_mm']):.1f} mm)",
        "sharp": sum(sharp) / len(sharp) if sharp else float("nan"),
        "fillet": f"{fillet['outcome']} at {float(fillet['end_arc_mm']):.1f} mm "
        f"(r {float(fillet['end_fillet_radius_mm']):.1f} mm)",
        "cpu_s": cpu_s,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ssc", default=str(ROOT / "build" / "bin" / "ssc"))
    p.add_argument("--out", default="out/skirt_sensitivity")
    p.add_argument("--threads", type=int, default=2, choices=range(1, 65), metavar="1-64")
    p.add_argument(
        "--params", default=",".join(RANGES), help="parameters to vary, among " + ", ".join(RANGES)
    )
    p.add_argument(
        "--static-only",
        action="store_true",
        help="only the straight-edge static reading (seconds per variant); no trials",
    )
    a = p.parse_args()
    params = a.params.split(",")
    for k in params:
        if k not in RANGES:
            p.error(f"--params: unknown parameter {k!r} (valid: {', '.join(RANGES)})")
    if not os.access(a.ssc, os.X_OK):
        p.error(f"--ssc: {a.ssc} is not an executable")
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    variants = [("baseline", {})]
    for k in params:
        for v in RANGES[k]:
            variants.append((f"{k}={v:g}", {k: v}))
    lines = [
        "| variant | P̄ / \\|ΔP\\| at 2.5 mm (Pa) | approach compression (mm) | "
        "corner_a270 | fillet \\|ΔP\\| at 10-20 mm (Pa) | fillet | CPU s |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    if a.static_only:
        lines = ["| variant | P̄ / \\|ΔP\\| at 2.5 mm (Pa) |", "| --- | --- |"]
    total = 0.0
    for name, overrides in variants:
        m = measure(a.ssc, out / name.replace("=", "_"), overrides, a.threads, a.static_only)
        total += m["cpu_s"]
        base = make_flex_tool.SKIRT
        label = name if not overrides else f"`{name}` (is {base[next(iter(overrides))][0]:g})"
        if a.static_only:
            lines.append(f"| {label} | {m['pbar']:.0f} / {m['diff']:.0f} |")
        else:
            lines.append(
                f"| {label} | {m['pbar']:.0f} / {m['diff']:.0f} | "
                f"{m['compression']:.2f} | {m['corner']} | {m['sharp']:.0f} | "
                f"{m['fillet']} | {m['cpu_s']:.0f} |"
            )
        print(lines[-1], flush=True)
    lines.append(f"\n{len(variants)} variants, {total:.0f} s of CPU.")
    (out / "sensitivity.md").write_text("\n".join(lines) + "\n")
    print(f"wrote {out / 'sensitivity.md'}")


if __name__ == "__main__":
    main()
