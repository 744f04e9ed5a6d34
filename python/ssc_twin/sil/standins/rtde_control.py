"""ur_rtde's rtde_control stand-in (ssc_twin.sil): the calls the lab's rtde_helper makes, served by
the twin's arm. Poses are the TCP in the UR Base frame, [x, y, z, rx, ry, rz] (m, rotation
vector). The twin holds the tool's orientation: commanded rotations are not realised."""

import warnings

from ssc_twin.sil.world import current as _world


class RTDEControlInterface:
    FLAG_VERBOSE = 1
    FLAG_UPLOAD_SCRIPT = 2
    FLAG_USE_EXT_UR_CAP = 4

    def __init__(self, hostname="", frequency=500.0, flags=0, ur_cap_port=50002, rt_priority=0):
        self.frequency = float(frequency) if frequency and frequency > 0 else 500.0
        self._warned = False

    def _orientation(self, pose):
        w = _world()
        err = w.orientation_error_deg(pose)
        if err > 1.0 and not self._warned:
            self._warned = True
            warnings.warn(
                "ssc sil: the commanded tool orientation differs from the twin's by "
                "%.1f deg; the twin holds its orientation (positions are followed)" % err
            )

    # --- motion ---
    def moveL(self, pose, speed=0.25, acceleration=1.2, asynchronous=False):
        self._orientation(pose)
        return _world().move_to(list(pose), speed)

    def moveJ_IK(self, pose, speed=1.05, acceleration=1.4, asynchronous=False):
        return self.moveL(pose, 0.25, acceleration, asynchronous)

    def servoL(self, pose, speed, acceleration, time, lookahead_time, gain):
        self._orientation(pose)
        _world().servo_to(list(pose), lookahead_time)
        return True

    def speedL(self, xd, acceleration=0.25, time=0.0):
        _world().speed(list(xd), time if time > 0 else 1e9)
        return True

    def servoStop(self, a=10.0):
        _world().stop()
        return True

    def speedStop(self, a=10.0):
        _world().stop()
        return True

    def stopL(self, a=10.0, asynchronous=False):
        _world().stop()
        return True

    def stopScript(self):
        _world().stop()

    def initPeriod(self):
        return _world().sim_time

    def waitPeriod(self, t_cycle_start):
        w = _world()
        w.advance_to(t_cycle_start + 1.0 / self.frequency)

    # --- TCP, payload, limits ---
    def setTcp(self, tcp_offset):
        w = _world()
        w.tcp_offset[:] = [float(v) for v in tcp_offset]
        return True

    def getTCPOffset(self):
        return [float(v) for v in _world().tcp_offset]

    def setPayload(self, mass, cog=None):
        return True

    set_payload = setPayload

    def isPoseWithinSafetyLimits(self, pose):
        return True

    def isJointsWithinSafetyLimits(self, q):
        return True

    def isConnected(self):
        return True

    def reconnect(self):
        return True

    def disconnect(self):
        pass

    def isProgramRunning(self):
        return True

    def isSteady(self):
        return True

    def zeroFtSensor(self):
        return True

    def getActualToolFlangePose(self):
        w = _world()
        p, R = w.tool0_in_base()
        from ssc_twin.sil.world import rotvec_from_matrix

        return [float(v) for v in p] + [float(v) for v in rotvec_from_matrix(R)]

    def __getattr__(self, name):
        raise AttributeError(
            "rtde_control.RTDEControlInterface.%s: not emulated by ssc_twin.sil "
            "(the twin's arm takes Cartesian moves: moveL, servoL, speedL)" % name
        )
