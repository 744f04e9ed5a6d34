"""tf stand-in (ssc_twin.sil): lookups of tool0 in base_link from the twin's robot."""

from . import transformations  # noqa: F401
from ssc_twin.sil.world import current as _world


class Exception(Exception):  # noqa: A001  tf.Exception, as tf names it
    pass


class LookupException(Exception):
    pass


class ConnectivityException(Exception):
    pass


class ExtrapolationException(Exception):
    pass


_FRAMES = ("base_link", "tool0")


def _frame(name):
    return name.lstrip("/")


class TransformListener:
    def __init__(self, *args, **kwargs):
        pass

    def waitForTransform(self, target, source, time, timeout, polling_sleep_duration=None):
        self.lookupTransform(target, source, time)

    def canTransform(self, target, source, time):
        return _frame(target) in _FRAMES and _frame(source) in _FRAMES

    def getLatestCommonTime(self, source, dest):
        from rospy import Time

        return Time.from_sec(_world().ros_time_s())

    def lookupTransform(self, target, source, time):
        """(translation, quaternion x y z w) of `source` in `target`."""
        t, s = _frame(target), _frame(source)
        if (t, s) == ("base_link", "tool0"):
            p, q = _world().tool0_in_base_link()
            return [float(v) for v in p], [float(v) for v in q]
        if (t, s) == ("tool0", "base_link"):
            p, q = _world().tool0_in_base_link()
            T = transformations.inverse_matrix(
                transformations.concatenate_matrices(
                    transformations.translation_matrix(p), transformations.quaternion_matrix(q)
                )
            )
            return list(T[:3, 3]), list(transformations.quaternion_from_matrix(T))
        raise LookupException(
            "the twin knows the frames base_link and tool0, not %s -> %s" % (target, source)
        )


class TransformBroadcaster:
    def sendTransform(self, translation, rotation, time, child, parent):
        pass
