"""The flex-skirt rig of tests/plugin/flex_lip_test.py for the tools that script it
(corner_push.py, flex_edge_table.py, flex_solve_check.py): the plugin loaded into MuJoCo and
the rig's module, and the skirt variants and MuJoCo options they take."""

import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]


def load(parser):
    """(mujoco, the rig module) with the built plugin loaded; a parser error when
    SSC_PLUGIN_LIB does not name it."""
    if "SSC_PLUGIN_LIB" not in os.environ:
        parser.error("set SSC_PLUGIN_LIB to the built plugin (build/lib/libssc_plugin.so)")
    os.environ.setdefault("SSC_SOURCE_DIR", str(ROOT))
    sys.path.insert(0, str(ROOT / "tests" / "plugin"))
    import mujoco
    import flex_lip_test

    mujoco.mj_loadPluginLibrary(os.environ["SSC_PLUGIN_LIB"])
    return mujoco, flex_lip_test


def add_variant_arguments(parser, option_help):
    """--set (a skirt parameter of make_flex_tool.py) and --option (a MuJoCo <option> field)."""
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="a skirt parameter of tools/make_flex_tool.py (repeatable)",
    )
    parser.add_argument(
        "--option", action="append", default=[], metavar="KEY=VALUE", help=option_help
    )


def parse_options(parser, items):
    """--option's KEY=NUMBER items as a dict; a parser error names a malformed one."""
    options = {}
    for item in items:
        key, _, text = item.partition("=")
        try:
            options[key] = float(text)
        except ValueError:
            parser.error(f"--option {item!r}: expected KEY=NUMBER")
    return options


def check_options(mujoco, options, error):
    """error(message) for a key that is not a MuJoCo option field."""
    for key in options:
        if not hasattr(mujoco.MjOption(), key):
            error(f"--option {key}: not a MuJoCo option field")


def apply_options(model, options):
    """Sets each option on model.opt in the field's own type."""
    for key, number in options.items():
        setattr(model.opt, key, type(getattr(model.opt, key))(number))


def variant_tool(set_items, prefix):
    """(the flex tool's path, its temporary folder or None): the skirt as it is, or the variant
    make_flex_tool.py writes for --set, in a folder of its own (the repository's models/ holds
    the scenes' models only; the rig picks the flex integrator by the file's name)."""
    if not set_items:
        return "ssc_tool_flex.xml", None
    folder = tempfile.TemporaryDirectory(prefix=prefix)
    tool = os.path.join(folder.name, "ssc_tool_flex_variant.xml")
    cmd = [sys.executable, str(ROOT / "tools" / "make_flex_tool.py"), "--out", tool]
    for item in set_items:
        cmd += ["--set", item]
    subprocess.run(cmd, check=True)
    return tool, folder
