"""MuJoCo's OpenGL backend on a machine without a display (docs/gym.md, "Without a display").

MuJoCo chooses its backend from MUJOCO_GL once, when ``mujoco`` is first imported. Without a
display GLFW cannot start, so where MUJOCO_GL is unset this picks EGL (Mesa's, in Debian's libegl1
and libegl-mesa0) before that import; a process that imported mujoco first keeps its choice.
"""

import os
import sys

CLASSIC_GL = "mujoco.rendering.classic.gl_context"


def no_display():
    return sys.platform.startswith("linux") and not (
        os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
    )


def choose_headless_backend():
    """Sets MUJOCO_GL=egl when there is no display, MUJOCO_GL is unset and mujoco has not
    chosen yet. Returns why rendering without a display cannot work in this process, or ""."""
    if not no_display() or os.environ.get("MUJOCO_GL"):
        return ""
    if CLASSIC_GL in sys.modules or "mujoco" in sys.modules:
        return (
            "there is no display and mujoco was imported before ssc_twin with MUJOCO_GL "
            "unset (GLFW): set MUJOCO_GL=egl before importing mujoco, or run under xvfb-run"
        )
    os.environ["MUJOCO_GL"] = "egl"
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")
    return ""


def render_fix():
    """What to do when no OpenGL context can be made."""
    problem = choose_headless_backend()
    return problem or (
        "without a display set MUJOCO_GL=egl (Debian: libegl1, libegl-mesa0) or "
        "MUJOCO_GL=osmesa (libosmesa6) before importing mujoco, or run under "
        "xvfb-run"
    )
