"""Harmless stand-ins for what the lab's scripts import that is not the twin's business: plots,
cameras, learned models, MoveIt, controller managers. Each is a module whose names are inert
objects: calling one, or anything it returns, does nothing. ``plt.pause`` and ``cv2.waitKey``
advance the simulation as the real calls take time."""

import importlib.abc
import importlib.machinery
import sys
import types

# Top-level modules served as no-ops (and every submodule under them).
NOOP_MODULES = {
    "cv2",
    "keras",
    "tensorflow",
    "icecream",
    "moveit_commander",
    "moveit_msgs",
    "controller_manager_msgs",
    "dynamic_reconfigure",
    "autolab_core",
    "visualization",
    "gqcnn_ros",
    "pyrealsense2",
    "perception",
    "catkin",
    "pykalman",
    "roslib",
    "rosgraph",
    "actionlib",
    "sklearn",
    "torch",
}
PLOT_MODULES = {"matplotlib", "mpl_toolkits"}


class NoOp:
    """An inert object: attributes, calls, items and arithmetic give more of the same."""

    def __init__(self, name="noop"):
        object.__setattr__(self, "_name", name)

    def __call__(self, *args, **kwargs):
        return NoOp(self._name + "()")

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return NoOp(self._name + "." + name)

    def __setattr__(self, name, value):
        pass

    def __getitem__(self, key):
        return NoOp(self._name + "[]")

    def __setitem__(self, key, value):
        pass

    def __iter__(self):
        return iter(())

    def __len__(self):
        return 0

    def __bool__(self):
        return False

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def __mro_entries__(self, bases):
        return (object,)

    def __repr__(self):
        return "<ssc sil no-op %s>" % self._name


class NoOpModule(types.ModuleType):
    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return NoOp(self.__name__ + "." + name)


def _pause(interval=0.0):
    from .current import current

    current().pause(interval)


def real_pause(pyplot):
    """The real matplotlib's plt.pause with the figure drawn for real and its time simulated:
    the redraw's CPU time is measured, then World.pause advances the simulation (the GUI event
    loop's own wait would pass wall time, not simulated time)."""
    import time
    from matplotlib import _pylab_helpers

    def pause(interval=0.0):
        from .current import current

        t0 = time.process_time()
        manager = _pylab_helpers.Gcf.get_active()
        if manager is not None:
            canvas = manager.canvas
            if canvas.figure.stale:
                canvas.draw_idle()
            pyplot.show(block=False)
            canvas.flush_events()
        current().pause(interval, time.process_time() - t0, t0)

    return pause


def _subplots(nrows=1, ncols=1, **kwargs):
    import numpy as np

    if nrows * ncols == 1:
        return NoOp("figure"), NoOp("axes")
    axes = np.empty((nrows, ncols) if nrows > 1 and ncols > 1 else (nrows * ncols,), dtype=object)
    for i in range(axes.size):
        axes.flat[i] = NoOp("axes")
    return NoOp("figure"), axes


def _ic(*args):
    if not args:
        return None
    return args[0] if len(args) == 1 else args


def _wait_key(delay=0):
    from .current import current

    current().sleep(max(delay, 1) * 1e-3)
    return -1


SPECIAL = {
    "matplotlib": {"use": lambda *a, **k: None, "rcParams": {}, "get_backend": lambda: "agg"},
    "matplotlib.pyplot": {
        "pause": _pause,
        "subplots": _subplots,
        "ion": lambda: None,
        "ioff": lambda: None,
        "show": lambda *a, **k: None,
        "close": lambda *a, **k: None,
    },
    "icecream": {"ic": _ic},
    "cv2": {"waitKey": _wait_key},
    "controller_manager_msgs.utils": {
        "ControllerLister": NoOp("ControllerLister"),
        "ControllerManagerLister": NoOp("ControllerManagerLister"),
        "get_rosparam_controller_names": lambda *a, **k: [],
    },
}


class NoOpFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def __init__(self, plots=False):
        self.roots = set(NOOP_MODULES) | (set() if plots else set(PLOT_MODULES))

    def find_spec(self, fullname, path=None, target=None):
        if fullname.split(".")[0] in self.roots:
            return importlib.machinery.ModuleSpec(fullname, self, is_package=True)
        return None

    def create_module(self, spec):
        m = NoOpModule(spec.name)
        m.__path__ = []
        m.__all__ = list(SPECIAL.get(spec.name, {}))
        for k, v in SPECIAL.get(spec.name, {}).items():
            setattr(m, k, v)
        return m

    def exec_module(self, module):
        pass


def install(plots=False):
    finder = NoOpFinder(plots)
    for name in list(sys.modules):
        if name.split(".")[0] in finder.roots:
            del sys.modules[name]
    sys.meta_path.insert(0, finder)
    return finder
