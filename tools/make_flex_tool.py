#!/usr/bin/env python3
"""Writes models/ssc_tool_flex.xml: models/ssc_tool.xml with its lip (16 segments on slides and
their carrier) and its rigid 23 mm body replaced by the real cup's lower part: a chamber body on
the bellows (one axial spring), its four chamber walls ending at the 11 mm throat, and from the
throat a flared skirt out to the 23 mm rim that MuJoCo deforms (a 2-D flex shell with the
engine's own elasticity, pinned along the throat, free at its rim), loaded by each chamber's
vacuum (the plugin's lip_vacuum_load).

The skirt's shape, material and bellows are the one home of those facts (SKIRT below); the
published cup fixes the throat and the rim (Fig. 1b, 1c); the rest is argued from the photos in
docs/flex_skirt.md with its range. Run after changing either:
tools/make_flex_tool.py (a test checks the file is current).

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
    "throat_radius_mm": (
        5.5,
        "mm",
        "published: the 11 mm opening (Fig. 1c), where the chamber walls end and the skirt starts",
    ),
    "rim_radius_mm": (11.5, "mm", "published: the 23 mm outer diameter is the lip's rim (Fig. 1b)"),
    "height_mm": (
        4.0,
        "mm",
        "2-4: the throat stands this far above the rim plane; in Fig. 1b "
        "the lip below the bellows flange is about a quarter to a third of its 23 mm "
        "rim as tall (6-7 mm with the flange), and the walls end about that far above "
        "the lip plane (Fig. 1c); the tall end, with flare and thickness at theirs, is "
        "the bell that carries the 1.5 N preload standing, as in Fig. 11 "
        "(docs/flex_skirt.md)",
    ),
    "flare": (
        2.0,
        "",
        "1-2: the profile's exponent, z = -height (1 - s)^flare from throat (s 0) "
        "to rim (s 1); 1 is a straight cone; Fig. 1b and 11 show a bell that leaves the "
        "throat steeply and meets the object nearly flat at the rim",
    ),
    "thickness_mm": (
        1.0,
        "mm",
        "0.5-1.0: translucent in Fig. 1c (the walls show through), so "
        "not over 1 mm; a cast lip thinner than 0.5 mm tears",
    ),
    "young_mpa": (
        2.0,
        "MPa",
        "1.2-2.0: Shore 40A (Mold Max 40, the lab's default cup); "
        "Gent's relation gives 1.69 MPa at 40A, 1.2-2.0 over 35-45A; the range's end "
        "at which issue 25's corner push folds a lobe over the facing chamber and "
        "blocks it, as Fig. 11 shows (at 1.7 only part-covered; docs/flex_skirt.md)",
    ),
    # MuJoCo's 2-D shell bends this much more than a Kirchhoff plate of the same E, t and nu
    # (a clamped strip under uniform load, mesh-converged; tests/plugin/flex_lip_test.py measures it):
    # the MJCF modulus is the material's times this, so the skirt bends as the silicone would.
    "shell_bending_correction": (1.70, "", "measured: MuJoCo 4.0.0 shell vs plate theory"),
    "poisson": (0.45, "", "0.45-0.49: nearly incompressible rubber (0.45 keeps shells unlocked)"),
    "damping_s": (0.002, "s", "Rayleigh damping: keeps the discrete step stable at 2 ms"),
    "mass_g": (2.0, "g", "numerical: heavier than the ~0.3 g of silicone so contacts stay stiff"),
    "friction": (0.6, "", "0.5-1.0: silicone on acrylic or aluminium"),
    # A soft contact's force scales with the mass behind it; a skirt vertex weighs milligrams, so
    # the usual time-constant solref lets the rim sink through the object under a 1 N press. A
    # direct stiffness (MuJoCo's negative solref, critically damped) holds it on the surface.
    "contact_stiffness": (1e8, "1/s^2", "rim held within 0.01 mm of the surface under 1.4 N"),
    # The bellows between the cup's flange and the chamber body: one axial spring (Fig. 1b: a
    # single convolution above the lip). The approach presses until the transducer reads the
    # preload; this spring and the skirt share it.
    "bellows_n_per_mm": (
        1.5,
        "N/mm",
        "0.5-3: the 1.5 N preload compresses a single-convolution "
        "silicone bellows by 0.5-3 mm; 1.5 N/mm is the segment lip's axial "
        "stiffness (1 mm at 1.5 N)",
    ),
    "bellows_travel_mm": (
        3.0,
        "mm",
        "2-4: the bellows' free travel either way before it bottoms out or stretches taut",
    ),
    "chamber_body_g": (5.0, "g", "3-8: the silicone chamber body and walls below the bellows"),
    # The four chamber walls (the cross that splits the throat into quadrants) are moulded with
    # the chamber body: stiff in their own plane, so the model makes each a rigid plate that ends
    # at the throat (Fig. 1c: the "+" stands only inside the 11 mm opening).
    "wall_thickness_mm": (0.8, "mm", "0.6-1.0: the lab's 2-D model uses 0.8 mm"),
    "rings": (
        5,
        "",
        "vertex rings from the pinned throat to the rim: 4 rows of elements across "
        "the 6 mm span, so a lobe can fold; at 4 rings (3 rows) the corner push no longer "
        "blocks the facing chamber (docs/flex_skirt.md; cost grows with rings x sectors)",
    ),
    "sectors": (
        24,
        "",
        "vertices per ring: 3 mm apart on the rim, 1.4 mm at the throat; at 16 the corner "
        "push's lobe is too coarse to cover the facing chamber (docs/flex_skirt.md)",
    ),
}


def value(key):
    return SKIRT[key][0]


LIP_PLANE_M = 0.1206  # the tool site in the cup body (models/ssc_tool.xml)


def contact_radius_m():
    """The skirt's surface stands half its thickness off its mid-surface."""
    return 0.5 * value("thickness_mm") * 1e-3


def profile(f):
    """(radius, height above the rim's centre line) in metres at s = f from throat to rim."""
    r_throat, r_rim = value("throat_radius_mm") * 1e-3, value("rim_radius_mm") * 1e-3
    return r_throat + f * (r_rim - r_throat), value("height_mm") * 1e-3 * (1.0 - f) ** value(
        "flare"
    )


def skirt_flexcomp():
    rings, sectors = int(value("rings")), int(value("sectors"))
    points, elements = [], []
    for i in range(rings):
        r, up = profile(i / (rings - 1))
        for j in range(sectors):
            # Rim vertices on the middle of each of the sectors' arcs; rings alternate by half.
            a = 2.0 * math.pi * (j + 0.5 * ((i + rings - 1) % 2)) / sectors + math.pi / sectors
            points.append((r * math.cos(a), r * math.sin(a), -up))  # +z of the tool is down

    def vid(i, j):
        return i * sectors + j % sectors

    for i in range(rings - 1):
        for j in range(sectors):
            a, b, c, d = vid(i, j), vid(i, j + 1), vid(i + 1, j), vid(i + 1, j + 1)
            elements += (
                [(a, b, c), (b, d, c)] if (i + rings - 1) % 2 == 0 else [(a, b, d), (a, d, c)]
            )
    point = " ".join("%.6f %.6f %.6f" % p for p in points)
    element = " ".join("%d %d %d" % e for e in elements)
    pin = " ".join(str(vid(0, j)) for j in range(sectors))
    return f"""            <!-- The lip: a skirt MuJoCo deforms (tools/make_flex_tool.py; docs/flex_skirt.md).
                 Pinned along the throat to the chamber body, free out to the rim at the lip
                 plane; the pressure plugin reads its columns and loads it with each chamber's
                 vacuum. -->
            <flexcomp name="skirt" type="direct" dim="2" pos="0 0 {LIP_PLANE_M - contact_radius_m():.6f}"
                      radius="{contact_radius_m():.6f}" mass="{value("mass_g") * 1e-3:.6f}"
                      rgba="0.15 0.35 0.85 1" group="4" point="{point}" element="{element}">
              <elasticity young="{value("young_mpa") * value("shell_bending_correction") * 1e6:.6g}"
                          poisson="{value("poisson")}"
                          thickness="{value("thickness_mm") * 1e-3:.6f}" damping="{value("damping_s")}"
                          elastic2d="both"/>
              <contact condim="3" selfcollide="none" contype="1" conaffinity="0"
                       friction="{value("friction")} 0.005 0.0001"
                       solref="{contact_solref()}"
                       solimp="0.95 0.99 0.0005"/>
              <pin id="{pin}"/>
            </flexcomp>
"""


def chamber_walls():
    """The four chamber walls in the chamber body: each a rigid plate from the axis to the throat,
    its lower face level with the skirt's underside at the throat."""
    cr = contact_radius_m()
    r_throat, height = value("throat_radius_mm") * 1e-3, value("height_mm") * 1e-3
    half_t = 0.5 * value("wall_thickness_mm") * 1e-3
    z_edge = LIP_PLANE_M - height  # the skirt's underside at the throat
    z_top = z_edge - 3e-3
    half_r = 0.5 * (r_throat - cr)
    lines = [
        "            <!-- The chamber walls (tools/make_flex_tool.py): rigid in their plane;"
        " they end at the throat. -->"
    ]
    for k in range(4):
        a = 0.5 * math.pi * k  # the quadrant boundaries (plugin/pneumatics/cup_geometry.h)
        c, s = math.cos(a), math.sin(a)
        lines.append(
            f'            <geom name="wall_{k}" type="box" size="{half_r:.6f} {half_t:.6f} '
            f'{0.5 * (z_edge - z_top):.6f}" pos="{half_r * c:.6f} {half_r * s:.6f} '
            f'{0.5 * (z_edge + z_top):.6f}" quat="{math.cos(a / 2):.6f} 0 0 {math.sin(a / 2):.6f}" {wall_contact()}/>'
        )
    return "\n".join(lines) + "\n"


def chamber_body():
    """The body below the bellows that carries the walls and the skirt's throat: on one axial
    slide, the bellows' spring."""
    k = value("bellows_n_per_mm") * 1e3
    mass = value("chamber_body_g") * 1e-3
    throat_z = LIP_PLANE_M - value("height_mm") * 1e-3
    r_body = value("throat_radius_mm") * 1e-3 + value("wall_thickness_mm") * 1e-3
    return (
        f"""          <!-- The bellows (tools/make_flex_tool.py): the chamber body hangs from the cup on one
               axial spring; negative = pushed up (compressed). -->
          <body name="chamber_body" gravcomp="1">
            <joint name="bellows" type="slide" axis="0 0 1" range="{-value("bellows_travel_mm") * 1e-3:.6f} {value("bellows_travel_mm") * 1e-3:.6f}"
                   stiffness="{k:.6g}" springref="0" damping="2" armature="0.002" limited="true"/>
            <inertial pos="0 0 {throat_z - 2e-3:.6f}" mass="{mass:.6f}" diaginertia="1e-7 1e-7 1e-7"/>
            <geom name="chamber_wall" class="rigid" type="cylinder" size="{r_body:.6f} 0.0070"
                  pos="0 0 {throat_z - 0.0070:.6f}" mass="0" rgba="0.45 0.8 0.7 0.6"/>
"""
        + chamber_walls()
        + skirt_flexcomp()
        + "          </body>\n"
    )


def contact_solref():
    return f"{-value('contact_stiffness'):.6g} {-2 * math.sqrt(value('contact_stiffness')):.6g}"


def wall_contact():
    """The walls touch the skirt (and objects) with the skirt's own contact; group 3: no ray of
    the pressure sensor sees them; their mass is in the chamber body's."""
    return (
        f'group="3" contype="0" conaffinity="1" condim="3" mass="0" rgba="0.95 0.55 0.1 0.6" '
        f'friction="{value("friction")} 0.005 0.0001" solref="{contact_solref()}" '
        f'solimp="0.95 0.99 0.0005"'
    )


DOC = ROOT / "docs" / "flex_skirt.md"
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

    parser = argparse.ArgumentParser(
        description="Writes models/ssc_tool_flex.xml and the skirt "
        "table in docs/flex_skirt.md, or a variant model with --out."
    )
    parser.add_argument("--check", action="store_true", help="fail when either file is stale")
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="override a skirt parameter (only with --out): " + ", ".join(SKIRT),
    )
    parser.add_argument("--out", help="write the variant model here instead (docs untouched)")
    args = parser.parse_args(argv)
    overrides = {}
    for item in args.set:
        key, sep, text = item.partition("=")
        if not sep or key not in SKIRT:
            parser.error(f"--set {item!r}: expected KEY=VALUE with KEY one of {', '.join(SKIRT)}")
        if key in overrides:  # a typo, not an override: which value was meant is unknowable
            parser.error(f"--set {key}: given twice")
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


def max_press_mm():
    """The lip plane's deepest press: the walls end at the throat, height_mm above the rim, so
    pressed deeper than the height less the skirt's thickness the walls would land."""
    return value("height_mm") - value("thickness_mm")


def tool_xml(walls=True, vacuum_load=True):
    """The flex tool's MJCF; tests build variants without the walls or the vacuum load."""
    text = (ROOT / "models" / "ssc_tool.xml").read_text()
    # The segment lip and its carrier body go; the skirt takes their place.
    start = text.index("          <!-- The lip's carrier")
    end = text.index("        </body>\n      </body>\n    </body>\n  </worldbody>")
    body = chamber_body() if walls else chamber_body().replace(chamber_walls(), "")
    text = text[:start] + body + text[end:]
    # The rigid 23 mm body and its skirt go: the flex skirt is what is out there.
    text = re.sub(r'\n          <geom name="body" class="rigid".*?/>', "", text, flags=re.S)
    text = re.sub(r'\n          <geom name="skirt" class="rigid".*?/>', "", text, flags=re.S)
    text = re.sub(r"\n  <!-- Rigid lip carrier.*?</equality>\n", "\n", text, flags=re.S)
    text = text.replace('<mujoco model="ssc_tool">', '<mujoco model="ssc_tool_flex">')
    # Each chamber's vacuum loads the skirt and the chamber body.
    text = text.replace(
        '<instance name="pressure"/>',
        '<instance name="pressure">\n        <config key="lip_vacuum_load" '
        f'value="{int(vacuum_load)}"/>\n        <config key="lip_max_press_mm" '
        f'value="{max_press_mm():.6g}"/>\n      </instance>',
    )
    text = re.sub(
        r"<!--\n  Smart Suction Cup tool:",
        "<!--\n  GENERATED by tools/make_flex_tool.py from ssc_tool.xml: do not edit.\n"
        "  The same tool with a chamber body on a bellows spring, its walls ending at the 11 mm\n"
        "  throat, and a deformable skirt (a 2-D flex) from the throat to the 23 mm rim\n"
        "  instead of 16 segments and the rigid body; each chamber's vacuum loads it.\n"
        '  Scenes using it must set integrator="discrete" (MuJoCo integrates 2-D flex\n'
        "  elasticity only there).\n\n  Smart Suction Cup tool:",
        text,
        count=1,
    )
    return text


def main():
    check, overrides, variant_out = parse_args(sys.argv[1:])
    if variant_out:
        if pathlib.Path(variant_out).resolve().parent == (ROOT / "models").resolve():
            sys.exit(f"--out {variant_out}: write variants outside models/ (e.g. under out/)")
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
