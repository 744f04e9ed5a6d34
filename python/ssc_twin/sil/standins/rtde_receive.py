"""ur_rtde's rtde_receive stand-in (ssc_twin.sil): the twin arm's state."""

from ssc_twin.sil.world import current as _world


class RTDEReceiveInterface:
    def __init__(
        self,
        hostname="",
        frequency=-1.0,
        variables=None,
        verbose=False,
        use_upper_range_registers=False,
    ):
        pass

    def getActualTCPPose(self):
        return _world().tcp_pose()

    def getTargetTCPPose(self):
        return _world().tcp_pose()

    def getActualTCPForce(self):
        """The force at the TCP in Base (the twin's F/T reading turned into the base frame)."""
        import numpy as np

        w = _world()
        ft = np.asarray(w.plant.force_torque())
        R = w.tool0_rotation()
        # The force the tool feels from its surroundings: minus the transducer's push on the cup.
        return [float(v) for v in np.concatenate([R @ -ft[:3], R @ -ft[3:]])]

    def getActualTCPSpeed(self):
        return [0.0] * 6

    def getTimestamp(self):
        return _world().sim_time

    def isConnected(self):
        return True

    def disconnect(self):
        pass

    def __getattr__(self, name):
        raise AttributeError(
            "rtde_receive.RTDEReceiveInterface.%s: not emulated by ssc_twin.sil "
            "(the twin's arm reports its TCP pose and force)" % name
        )
