#!/usr/bin/env python3
"""Writes models/ssc_tool_flex.xml: models/ssc_tool.xml with its lip (16 segments on slides and
their carrier) replaced by a skirt that MuJoCo deforms: a 2-D flex shell with the engine's own
elasticity, pinned along its top ring to the cup and free at its rim, leaning on the four
chamber walls, and loaded by each chamber's vacuum (the plugin's lip_vacuum_load).

The skirt's shape and material are the one home of those facts (SKIRT below); the published cup
fixes the rim (the 11 mm opening); the rest is argued in docs/pneumatics.md (the flex skirt) with
its range. Run after changing either: tools/make_flex_tool.py (a test checks the file is current).

A variant for a sensitivity run: tools/make_flex_tool.py --set height_mm=2.5 --set friction=1.0
--out PATH writes the model with those values to PATH (and nothing else; the values must be
numbers, the keys SKIRT's).
"""
import math
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]

# name: (value, unit, range argued from the hardware)
SKIRT = {
    "rim_radius_mm": (5.5, "mm", "published: the 11 mm opening"),
    "top_radius_mm": (4.0, "mm", "3.5-5: the skirt flares out to its rim (one narrowing to its rim "
                      "folds inward under its own press, and no real cup does); 4 mm gives about "
                      "2 N at 1 mm of press, near the segment lip's 1.5 N"),
    "height_mm": (3.0, "mm", "2-4: the lip's free height below the rigid body"),
    "thickness_mm": (1.0, "mm", "0.6-1.5: a cast lip that holds its shape"),
    "young_mpa": (1.0, "MPa", "0.6-1.5: Shore 20A-30A silicone"),
    # MuJoCo's 2-D shell bends this much more than a Kirchhoff plate of the same E, t and nu
    # (a clamped strip under uniform load, mesh-converged; tests/plugin/flex_lip_test.py measures it):
    # the MJCF modulus is the material's times this, so the skirt bends as the silicone would.
    "shell_bending_correction": (1.70, "", "measured: MuJoCo 4.0.0 shell vs plate theory"),
    "poisson": (0.45, "", "0.45-0.49: nearly incompressible rubber (0.45 keeps shells unlocked)"),
    "damping_s": (0.002, "s", "Rayleigh damping: keeps the discrete step stable at 2 ms"),
    "mass_g": (2.0, "g", "numerical: heavier than the ~0.15 g of silicone so contacts stay stiff"),
    "contact_radius_mm": (0.5, "mm", "half the thickness"),
    "friction": (0.6, "", "0.5-1.0: silicone on acrylic or aluminium"),
    # A soft contact's force scales with the mass behind it; a skirt vertex weighs milligrams, so
    # the usual time-constant solref lets the rim sink through the object under a 1 N press. A
    # direct stiffness (MuJoCo's negative solref, critically damped) holds it on the surface.
    "contact_stiffness": (1e8, "1/s^2", "rim held within 0.01 mm of the surface under 1.4 N"),
    # The four chamber walls (the cross that splits the opening into quadrants) are moulded with
    # the skirt: a wall is stiff in its own plane (a silicone plate loaded edgewise) and soft
    # across it, so the model makes each a rigid plate whose edge runs along the skirt's inside;
    # the skirt leans on that edge and slides along it. Their lower edges are the stop that
    # carries a grasp: pressed beyond them, the skirt would buckle under the chambers' vacuum.
    "wall_thickness_mm": (1.0, "mm", "0.6-1.5: moulded like the lip"),
    "wall_recess_mm": (0.5, "mm", "0.3-1: the walls' lower edge above the lip plane: clear of "
                       "the object at the approach's press (0.2 mm), reached before the skirt "
                       "buckles under a sealed cup's vacuum (0.7-1 mm)"),
    "rings": (3, "", "vertex rings from the pinned top to the rim (cost grows with rings x sectors)"),
    "sectors": (16, "", "vertices per ring: the rim has as many points as the segment lip"),
}


def value(key):
    return SKIRT[key][0]


def skirt_flexcomp():
    rings, sectors = int(value("rings")), int(value("sectors"))
    r_top, r_rim = value("top_radius_mm") * 1e-3, value("rim_radius_mm") * 1e-3
    height = value("height_mm") * 1e-3
    points, elements = [], []
    for i in range(rings):
        f = i / (rings - 1)
        r, z = r_top + f * (r_rim - r_top), -height * (1.0 - f)  # z: +down is +z of the tool
        for j in range(sectors):
            # Rim vertices on the segment lip's angles (the middle of each of 16 arcs).
            a = 2.0 * math.pi * (j + 0.5 * ((i + rings - 1) % 2)) / sectors + math.pi / sectors
            points.append((r * math.cos(a), r * math.sin(a), z))
    vid = lambda i, j: i * sectors + j % sectors
    for i in range(rings - 1):
        for j in range(sectors):
            a, b, c, d = vid(i, j), vid(i, j + 1), vid(i + 1, j), vid(i + 1, j + 1)
            elements += [(a, b, c), (b, d, c)] if (i + rings - 1) % 2 == 0 else [(a, b, d), (a, d, c)]
    point = " ".join("%.6f %.6f %.6f" % p for p in points)
    element = " ".join("%d %d %d" % e for e in elements)
    pin = " ".join(str(vid(0, j)) for j in range(sectors))
    return f"""          <!-- The lip: a skirt MuJoCo deforms (tools/make_flex_tool.py; docs/pneumatics.md).
               Top ring pinned to the cup, rim free at the lip plane; the pressure plugin reads
               the rim's vertices and loads the skirt with each chamber's vacuum. -->
          <flexcomp name="skirt" type="direct" dim="2" pos="0 0 {0.1206 - value("contact_radius_mm") * 1e-3:.6f}"
                    radius="{value('contact_radius_mm') * 1e-3:.6f}" mass="{value('mass_g') * 1e-3:.6f}"
                    rgba="0.15 0.35 0.85 1" group="4" point="{point}" element="{element}">
            <elasticity young="{value('young_mpa') * value('shell_bending_correction') * 1e6:.6g}"
                        poisson="{value('poisson')}"
                        thickness="{value('thickness_mm') * 1e-3:.6f}" damping="{value('damping_s')}"
                        elastic2d="both"/>
            <contact condim="3" selfcollide="none" contype="1" conaffinity="0"
                     friction="{value('friction')} 0.005 0.0001"
                     solref="{contact_solref()}"
                     solimp="0.95 0.99 0.0005"/>
            <pin id="{pin}"/>
          </flexcomp>
"""


def chamber_walls():
    """The four chamber walls in the cup body: each a rigid plate from the axis to the skirt's
    inner surface (a box) with a rounded edge along the skirt's inside (a capsule) that the skirt
    leans on; both end wall_recess_mm above the lip plane."""
    lip_plane = 0.1206
    cr = value("contact_radius_mm") * 1e-3
    r_top, r_rim = value("top_radius_mm") * 1e-3, value("rim_radius_mm") * 1e-3
    height, half_t = value("height_mm") * 1e-3, 0.5 * value("wall_thickness_mm") * 1e-3
    z_top = lip_plane - cr - height  # the skirt's pinned ring: the ceiling
    z_edge = lip_plane - value("wall_recess_mm") * 1e-3  # the walls' lower edge
    z_rib = z_edge - half_t  # the edge capsule's lower end (its cap reaches z_edge)
    # The skirt's centre line runs from (r_top, z_top) to (r_rim, lip_plane - cr).
    r_at = lambda z: r_top + (r_rim - r_top) * (z - z_top) / height
    inset = cr + half_t  # the capsule touches the skirt's inner face at rest
    rib_top, rib_bottom = r_top - inset, r_at(z_rib) - inset
    lines = ["          <!-- The chamber walls (tools/make_flex_tool.py): rigid in their plane; the"
             " skirt leans on their edges. -->"]
    for k in range(4):
        a = 0.5 * math.pi * k  # the quadrant boundaries (plugin/pneumatics/cup_geometry.h)
        c, s = math.cos(a), math.sin(a)
        half_r = 0.5 * rib_top
        lines.append(
            f'          <geom name="wall_{k}" type="box" size="{half_r:.6f} {half_t:.6f} '
            f'{0.5 * (z_edge - z_top):.6f}" pos="{half_r * c:.6f} {half_r * s:.6f} '
            f'{0.5 * (z_edge + z_top):.6f}" quat="{math.cos(a / 2):.6f} 0 0 {math.sin(a / 2):.6f}" {wall_contact()}/>')
        lines.append(
            f'          <geom name="wall_edge_{k}" type="capsule" size="{half_t:.6f}" '
            f'fromto="{rib_top * c:.6f} {rib_top * s:.6f} {z_top:.6f} {rib_bottom * c:.6f} '
            f'{rib_bottom * s:.6f} {z_rib:.6f}" {wall_contact()}/>')
    return "\n".join(lines) + "\n"


def contact_solref():
    return f"{-value('contact_stiffness'):.6g} {-2 * math.sqrt(value('contact_stiffness')):.6g}"


def wall_contact():
    """The walls touch the skirt (and objects) with the skirt's own contact; group 3: no ray of
    the pressure sensor sees them; their mass is in the cup body's."""
    return (f'group="3" contype="0" conaffinity="1" condim="3" mass="0" rgba="0.95 0.55 0.1 0.6" '
            f'friction="{value("friction")} 0.005 0.0001" solref="{contact_solref()}" '
            f'solimp="0.95 0.99 0.0005"')


DOC = ROOT / "docs" / "pneumatics.md"
BEGIN, END = "<!-- skirt table: tools/make_flex_tool.py -->", "<!-- end skirt table -->"


def markdown_table():
    rows = ["| parameter | value | unit | range and why |", "| --- | --- | --- | --- |"]
    rows += ["| `%s` | %g | %s | %s |" % (k, v[0], v[1], v[2]) for k, v in SKIRT.items()]
    return "\n".join(rows)


def doc_with_table(doc):
    start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
    return doc[:start] + "\n" + markdown_table() + "\n" + doc[end:]


def parse_args(argv):
    """(check, overrides, out) from argv; exits with a message naming a bad argument."""
    import argparse
    parser = argparse.ArgumentParser(description="Writes models/ssc_tool_flex.xml and the skirt "
                                     "table in docs/pneumatics.md, or a variant model with --out.")
    parser.add_argument("--check", action="store_true", help="fail when either file is stale")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="override a skirt parameter (only with --out): " + ", ".join(SKIRT))
    parser.add_argument("--out", help="write the variant model here instead (docs untouched)")
    args = parser.parse_args(argv)
    overrides = {}
    for item in args.set:
        key, sep, text = item.partition("=")
        if not sep or key not in SKIRT:
            parser.error(f"--set {item!r}: expected KEY=VALUE with KEY one of {', '.join(SKIRT)}")
        try:
            number = float(text)
        except ValueError:
            parser.error(f"--set {item!r}: {text!r} is not a number")
        if not math.isfinite(number) or number <= 0:
            parser.error(f"--set {item!r}: must be a positive finite number")
        if key in ("rings", "sectors") and (number != int(number) or number < 2):
            parser.error(f"--set {item!r}: must be a whole number >= 2")
        overrides[key] = number
    if overrides and not args.out:
        parser.error("--set needs --out: the repository's model keeps the SKIRT values")
    if args.out and args.check:
        parser.error("--check compares the repository's files; it takes no --out")
    return args.check, overrides, args.out


def tool_xml(walls=True, vacuum_load=True):
    """The flex tool's MJCF; tests build variants without the walls or the vacuum load."""
    text = (ROOT / "models" / "ssc_tool.xml").read_text()
    # The segment lip and its carrier body go; the skirt takes their place.
    start = text.index('          <!-- The lip\'s carrier')
    end = text.index("        </body>\n      </body>\n    </body>\n  </worldbody>")
    text = text[:start] + (chamber_walls() if walls else "") + skirt_flexcomp() + text[end:]
    text = re.sub(r"\n  <!-- Rigid lip carrier.*?</equality>\n", "\n", text, flags=re.S)
    text = text.replace('<mujoco model="ssc_tool">', '<mujoco model="ssc_tool_flex">')
    # Each chamber's vacuum loads the skirt and the cup (the walls hold the skirt's shape).
    text = text.replace('<instance name="pressure"/>',
                        '<instance name="pressure">\n        <config key="lip_vacuum_load" '
                        f'value="{int(vacuum_load)}"/>\n      </instance>')
    text = re.sub(r"<!--\n  Smart Suction Cup tool:", "<!--\n  GENERATED by tools/make_flex_tool.py from ssc_tool.xml: do not edit.\n"
                  "  The same tool with a deformable skirt lip (a 2-D flex) instead of 16 segments,\n"
                  "  the four chamber walls it leans on, and each chamber's vacuum loading it.\n"
                  "  Scenes using it must set integrator=\"discrete\" (MuJoCo integrates 2-D flex\n"
                  "  elasticity only there).\n\n  Smart Suction Cup tool:", text, count=1)
    return text


def main():
    check, overrides, variant_out = parse_args(sys.argv[1:])
    if variant_out:
        for key, number in overrides.items():
            SKIRT[key] = (number,) + SKIRT[key][1:]
        text = tool_xml()
        pathlib.Path(variant_out).write_text(text)
        return
    text = tool_xml()
    out = ROOT / "models" / "ssc_tool_flex.xml"
    doc = DOC.read_text()
    if check:
        if out.read_text() != text:
            sys.exit(f"{out} is stale: run tools/make_flex_tool.py")
        if doc_with_table(doc) != doc:
            sys.exit(f"{DOC}'s skirt table is stale: run tools/make_flex_tool.py")
        return
    out.write_text(text)
    DOC.write_text(doc_with_table(doc))


if __name__ == "__main__":
    main()
