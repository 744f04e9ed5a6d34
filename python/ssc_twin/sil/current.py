"""The process's world, for the stand-ins (rospy's clock, the no-op modules, the lab's helpers):
the one install() set, else a virtual-time disk world made on first use by the factory that
world.py registers when it is imported. Imports nothing of the SIL: the world, the logger and the
clock depend on it, never the other way round."""

_world = None
_factory = None


def set_factory(make):
    global _factory
    _factory = make


def current():
    """The process's world (made on first use)."""
    global _world
    if _world is None:
        if _factory is None:
            raise RuntimeError("no SIL world: import ssc_twin.sil.world (ssc sil does) first")
        _world = _factory()
    return _world


def install(world):
    global _world
    _world = world
    return world
