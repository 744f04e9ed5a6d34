"""Smart Suction Cup digital twin for MuJoCo, from Python.

The C++ twin does the work; this package hands its results back as dicts and NumPy arrays.

    import ssc_twin
    r = ssc_twin.run_trial(pref=100, beta=2, step_mm=7.5, seed=1)
    r["outcome"], r["metrics"]["sigma_r_mm"], r["log"]["p_pa"]      # (N, 4) array

Installing the package registers the pressure-sensor plugin with the mujoco package (entry point
group ``mujoco.plugins``), so ``import mujoco`` can load the bundled scenes::

    python -m mujoco.viewer --mjcf=$(python -c "import ssc_twin; print(ssc_twin.scene_path(ssc_twin.default_scene()))")

and the Gymnasium environment ``ssc_twin/EdgeFollowing-v0`` is registered when gymnasium is
installed (``pip install .[gym]``).
"""

import os as _os

from . import _gl

_HEADLESS_PROBLEM = _gl.choose_headless_backend()  # before mujoco picks its GL backend

import mujoco as _mujoco  # noqa: E402,F401  loads libmujoco, which _core links (the same library)

from . import _core  # noqa: E402  after the GL choice above
from ._core import (  # noqa: E402
    Probe,
    SilPlant,
    SteppedTrial,
    check_seed,
    compare,
    contour_step,
    controllers,
    default_scene,
    max_seed,
    mujoco_version,
    object_names,
    objects,
    phase_names,
    resource_dir,
    run_trial,
    scene_path,
    scene_tiers,
    student_t95,
    sweep,
    validate,
    wilson_interval,
    write_lab_mat,
    write_robot_log,
)

__all__ = [
    "Probe",
    "SilPlant",
    "SteppedTrial",
    "check_seed",
    "compare",
    "contour_step",
    "controllers",
    "default_scene",
    "max_seed",
    "mujoco_version",
    "object_names",
    "objects",
    "phase_names",
    "resource_dir",
    "run_trial",
    "scene_path",
    "scene_tiers",
    "student_t95",
    "wilson_interval",
    "sweep",
    "write_lab_mat",
    "write_robot_log",
    "plugin_library",
    "load_plugin",
    "read_sweep",
    "validate",
]

_core.install_message_handlers()
_version_problem = _core.check_mujoco_version()
if _version_problem:
    raise ImportError(_version_problem)


def plugin_library():
    """Path of the bundled plugin library (for hosts other than the mujoco package)."""
    return _os.path.join(_os.path.dirname(__file__), "libssc_plugin.so")


def load_plugin(path=None):
    """Makes sure the running libmujoco has the ``ssc.chamber_pressure`` plugin; safe to call
    any number of times. Returns True when this call loaded a library, False when the plugin
    was already registered (importing this package registers it, and so does ``import mujoco``
    where the package is installed).

    MuJoCo refuses a second registration of a plugin name (``mujoco.FatalError: plugin
    'ssc.chamber_pressure' is already registered``), which a bare
    ``mujoco.mj_loadPluginLibrary(path)`` after ``import mujoco`` runs into; this does not.
    ``path``: a plugin library to load when none is registered yet (default: the bundled one).
    """
    if _core.plugin_registered():
        return False
    _mujoco.mj_loadPluginLibrary(path or plugin_library())
    return True


def read_sweep(csv_path):
    """The rows of a sweep CSV (written by sweep()) as a dict of NumPy arrays, one per column:
    numbers as float arrays (whole-number columns as int64), text as str arrays with the CSV's
    quoting undone (a detail may hold commas and quotes).

    Raises ValueError naming the file when it is not a sweep CSV (another header, binary data,
    a row with another number of fields).
    """
    import csv

    path = _os.fspath(csv_path)
    if not _os.path.isfile(path):
        raise ValueError(f"{path}: not a regular file (the sweep CSV to read)")
    with open(path, "rb") as f:
        head = f.readline(4096)
    if b"\0" in head or not head.startswith(b"scene,pref_pa,beta,step_mm,repeat,seed,outcome"):
        shown = head[:60].decode("ascii", "backslashreplace").rstrip()
        raise ValueError(
            f"{path}: not a sweep CSV (its first line is {shown!r}, expected the "
            "header scene,pref_pa,beta,step_mm,repeat,seed,outcome,...)"
        )
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f, strict=True))
    except (UnicodeDecodeError, csv.Error) as e:
        raise ValueError(f"{path}: cannot read as a sweep CSV: {e}") from None
    names, body = rows[0], rows[1:]
    for line, row in enumerate(body, start=2):
        if len(row) != len(names):
            raise ValueError(
                f"{path}: line {line} has {len(row)} fields, the header "
                f"{len(names)}: not a whole sweep row"
            )
    return {name: _column([row[i] for row in body]) for i, name in enumerate(names)}


def _column(cells):
    """One CSV column as a NumPy array: int64 when every cell is a whole number, float when every
    cell is a number (nan included), str otherwise."""
    import numpy as np

    try:
        return np.array([int(c) for c in cells], dtype=np.int64)
    except ValueError:
        pass
    try:
        return np.array([float(c) for c in cells], dtype=float)
    except ValueError:
        return np.array(cells, dtype=str)


try:
    import gymnasium as _gymnasium  # noqa: F401
except ImportError:  # the environment needs gymnasium (pip install .[gym])
    pass
else:
    from .edge_following import register_envs as _register_envs

    _register_envs()
