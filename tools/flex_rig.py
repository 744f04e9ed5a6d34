"""The flex-skirt rig of tests/plugin/flex_lip_test.py for the tools that script it
(corner_push.py, flex_solve_check.py): the plugin loaded into MuJoCo and the rig's module."""

import os
import pathlib
import sys

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
