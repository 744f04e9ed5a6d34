"""The twin behind the stand-ins: one simulated world per process.

Everything the lab's ROS graph and UR controller would be (the pressure board, the F/T node, the
tf/pose publisher, the pump on the PWM topic, the data logger service, the arm behind RTDE) is
served here from one ``SilPlant`` (the C++ scene, its servo and sensors). Time is the simulation's:
in virtual mode a sleep steps the simulation instead of the clock; in real-time mode it steps the
simulation and waits until the wall clock has caught up. Messages are delivered to subscribers
synchronously, in time order, while the simulation advances.

Frames (docs/sil.md): the scene's world is the UR Base frame (RTDE) moved so that the lab's disk
lands on the scene's disk; base_link (tf, /endEffectorPose) is the Base frame turned 180 deg about
z, as on the lab's robot. The TCP is tool0 plus the offset set with setTcp.
"""

import heapq
import math
import os
import time as _time

import numpy as np

from .current import current, install, set_factory  # noqa: F401  (world.current, world.install)
from .logger import DEFAULT_TOPICS, DataLogger  # noqa: F401  (world.DEFAULT_TOPICS)
from .rostime import Time
from .verdict import Verdict

AMBIENT_PA = 101325.0
# Each chamber's sensor reads the ambient with its own offset (what the lab's host tares in air);
# the values are the spread of the example row in lab-logs.md.
CHAMBER_OFFSET_PA = (-22.75, 14.67, -12.49, 73.59)
FT_RATE_HZ = 100.0  # netft_data publish rate (the lab's is not recorded)
POSE_RATE_HZ = 120.0  # /endEffectorPose (lab-logs.md: about 120 Hz)
# The UR servoL look-ahead the lab used (0.2 s) is the twin's servo smoothing of 0.15 s
# (docs/trials.md); other look-ahead times scale with it.
LAB_LOOKAHEAD_S = 0.2
TWIN_SMOOTHING_S = 0.15
SERVO_MAX_SPEED_M_S = 0.25
MOVEL_SMOOTHING_S = 0.02
REACHED_M = 0.1e-3  # moveL returns once the tool is this close and slow
MEASURED = "measured"  # pause_cost_s: charge the script's measured CPU time instead
# What one plt.pause of the lab's disk loop costs beyond its argument: building and drawing its
# 8x4 in arrow plot with the real matplotlib, measured (`ssc sil --plots --pause-cost measured`,
# TkAgg under Xvfb: median 12.7 ms building + 51.8 ms drawing CPU per iteration, the 10 ms
# argument's timer running while it draws). docs/sil_measured.md has the measurement and its spread.
DEFAULT_PAUSE_COST_S = 0.055


def _rot_z180(v):
    return np.array([-v[0], -v[1], v[2]])


def _quat_from_matrix(R):
    """(x, y, z, w) of a rotation matrix."""
    t = R[0, 0] + R[1, 1] + R[2, 2]
    if t > 0:
        s = math.sqrt(t + 1.0) * 2
        w, x, y, z = (
            0.25 * s,
            (R[2, 1] - R[1, 2]) / s,
            (R[0, 2] - R[2, 0]) / s,
            (R[1, 0] - R[0, 1]) / s,
        )
    elif R[0, 0] > R[1, 1] and R[0, 0] > R[2, 2]:
        s = math.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2]) * 2
        w, x, y, z = (
            (R[2, 1] - R[1, 2]) / s,
            0.25 * s,
            (R[0, 1] + R[1, 0]) / s,
            (R[0, 2] + R[2, 0]) / s,
        )
    elif R[1, 1] > R[2, 2]:
        s = math.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2]) * 2
        w, x, y, z = (
            (R[0, 2] - R[2, 0]) / s,
            (R[0, 1] + R[1, 0]) / s,
            0.25 * s,
            (R[1, 2] + R[2, 1]) / s,
        )
    else:
        s = math.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1]) * 2
        w, x, y, z = (
            (R[1, 0] - R[0, 1]) / s,
            (R[0, 2] + R[2, 0]) / s,
            (R[1, 2] + R[2, 1]) / s,
            0.25 * s,
        )
    q = np.array([x, y, z, w])
    return q / np.linalg.norm(q)


def rotvec_from_matrix(R):
    q = _quat_from_matrix(R)
    if q[3] < 0:
        q = -q
    angle = 2 * math.atan2(np.linalg.norm(q[:3]), q[3])
    n = np.linalg.norm(q[:3])
    return (q[:3] / n * angle) if n > 1e-12 else np.zeros(3)


def matrix_from_rotvec(v):
    v = np.asarray(v, dtype=float)
    a = np.linalg.norm(v)
    if a < 1e-12:
        return np.eye(3)
    k = v / a
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K


class _Event:
    __slots__ = ("t", "seq", "fn", "period")


class World:
    """One simulated robot cell: the scene, its clock and the ROS graph around it."""

    def __init__(
        self,
        scene=None,
        seed=1,
        realtime=False,
        tmp_dir=None,
        pause_cost_s=DEFAULT_PAUSE_COST_S,
        verbose=False,
        disk_geom="disk",
    ):
        import sys
        from .. import _core

        standins = os.path.join(os.path.dirname(os.path.abspath(__file__)), "standins")
        if standins not in sys.path:
            sys.path.insert(0, standins)
        self.plant = _core.SilPlant(_core.default_scene() if scene is None else scene, seed)
        self.realtime = realtime
        self.verbose = verbose
        # Seconds a plt.pause costs beyond its argument, or MEASURED: the script's own CPU time
        # since its last call into the twin (the plot built and drawn) on this machine.
        self.pause_cost_s = pause_cost_s
        self.pause_log = []  # per plt.pause: (build CPU s, draw CPU s)
        self._depth = 0  # advance_to nesting (callbacks run inside it)
        # When the script last returned from the twin, in process CPU seconds (the stand-ins run
        # in the script's thread; thread_time costs ~0.1 ms a call in some sandboxes).
        self._cpu_mark = _time.process_time()
        self.tmp_dir = tmp_dir or os.path.join(os.getcwd(), "sil_tmp")
        os.makedirs(self.tmp_dir, exist_ok=True)
        self.epoch_s = _time.time()  # ROS time at simulation time 0
        self.wall_start = _time.perf_counter()
        self.tool_centre_offset_m = float(_core.TOOL_CENTRE_OFFSET_M)
        # Placement: the lab's disk (base_link) onto the scene's disk; at the lab's engage
        # height the lip plane touches the disk top.
        lab_x, lab_y = _core.LAB_DISK_CENTRE_BASE_LINK_M
        try:
            dx, dy, dtop = self.plant.geom_top(disk_geom)
            disk_centre = (dx, dy)
        except Exception:  # a scene without the disk: the robot base at the scene origin
            dx, dy, dtop = (
                -lab_x,
                -lab_y,
                float(_core.LAB_DISK_ENGAGE_Z_M) - self.tool_centre_offset_m,
            )
            disk_centre = None
        self.verdict = Verdict(disk_centre)
        self.progress = None  # called as the simulation goes (runner's lines)
        self.base_in_scene = np.array(
            [
                dx + lab_x,
                dy + lab_y,
                dtop - (float(_core.LAB_DISK_ENGAGE_Z_M) - self.tool_centre_offset_m),
            ]
        )
        self.tcp_offset = np.zeros(6)  # RTDE setTcp: [x, y, z, rx, ry, rz] in tool0
        self.pump_duty = 0
        self.sampling = False  # the pressure board streams after its START command
        self.shutdown = False
        self.on_idle = None  # called by a sleep after shutdown (runner's limits)
        self.subscribers = {}  # topic -> [(callback, args)]
        self.published_types = {}  # topic -> message class (the master's topic list)
        self.services = {}
        self._events = []
        self._seq = 0
        self.velocity = None  # speedL: (v[3], until_s)
        self.plant.set_servo(TWIN_SMOOTHING_S, SERVO_MAX_SPEED_M_S)
        self._schedule(self._pressure_packet, 1.0 / self.plant.sample_rate_hz)
        self._schedule(self._ft_packet, 1.0 / FT_RATE_HZ)
        self._schedule(self._pose_packet, 1.0 / POSE_RATE_HZ)
        # The lab's graph runs before the script: the board, F/T and pose nodes advertise their
        # topics (the logger finds their types); /pwm exists once the script advertises it.
        from geometry_msgs.msg import PoseStamped, WrenchStamped
        from suction_cup.msg import SensorPacket

        self.published_types.update(
            {
                "/SensorPacket": SensorPacket,
                "/netft_data": WrenchStamped,
                "/endEffectorPose": PoseStamped,
            }
        )
        self.logger = DataLogger(self)
        self.viewer = None

    # ----- time -----
    @property
    def sim_time(self):
        return self.plant.time

    def ros_time_s(self):
        return self.epoch_s + self.plant.time

    def sleep(self, duration_s):
        if duration_s > 0:
            self.advance_to(self.plant.time + duration_s)

    def advance_to(self, t_s):
        """Steps the simulation to t_s, delivering every message due on the way."""
        self._depth += 1
        try:
            while True:
                if self.shutdown:
                    if self.on_idle is not None:
                        self.on_idle("a sleep after the node shut down")
                    return
                t_next = self._events[0][0] if self._events else t_s
                t_stop = min(t_next, t_s)
                self._step_plant(t_stop)
                if self._events and self._events[0][0] <= t_s + 1e-12:
                    t, _, fn, period = heapq.heappop(self._events)
                    fn()
                    if period:
                        self._push(t + period, fn, period)
                else:
                    return
        finally:
            self._depth -= 1
            if self._depth == 0:
                self._cpu_mark = _time.process_time()

    def pause(self, interval_s, draw_cpu_s=0.0, draw_start_cpu_s=None):
        """plt.pause: the figure redraw, then the GUI event loop for the interval; meanwhile the
        arm keeps servoing to its last target and the packets keep coming (the robot and the ROS
        nodes do not wait for the plot). Costs interval + pause_cost_s of simulated time, or with
        pause_cost_s = MEASURED the script's CPU time since its last twin call (building the
        plot) plus the redraw or the interval, whichever is longer (the interval's timer runs
        while the figure draws)."""
        start = _time.process_time() - draw_cpu_s if draw_start_cpu_s is None else draw_start_cpu_s
        build_cpu_s = max(0.0, start - self._cpu_mark)
        self.pause_log.append((build_cpu_s, draw_cpu_s))
        if self.pause_cost_s == MEASURED:
            self.sleep(build_cpu_s + max(float(interval_s), draw_cpu_s))
        else:
            self.sleep(float(interval_s) + self.pause_cost_s)

    def pause_summary(self):
        """Median CPU seconds per plt.pause: the script's work before it, the redraw, and the
        simulated cost charged (None without a pause)."""
        if not self.pause_log:
            return None
        a = np.asarray(self.pause_log)
        return {
            "pauses": int(len(a)),
            "build_cpu_s_median": float(np.median(a[:, 0])),
            "draw_cpu_s_median": float(np.median(a[:, 1])),
            "cost": "measured" if self.pause_cost_s == MEASURED else self.pause_cost_s,
        }

    def _step_plant(self, t_s):
        if self.velocity is not None:
            v, until = self.velocity
            t0 = self.plant.time
            t1 = min(t_s, until)
            if t1 > t0:
                self.plant.set_target(list(np.asarray(self.plant.target()) + v * (t1 - t0)))
            if t_s >= until:
                self.velocity = None
        t0 = self.plant.time
        self.plant.advance_to(t_s)
        if self.plant.time > t0:
            self._observe()
            if self.progress is not None:
                self.progress()
        if self.realtime:
            lag = self.plant.time - (_time.perf_counter() - self.wall_start)
            if lag > 0:
                _time.sleep(lag)
        if self.viewer is not None:
            self.viewer.sync(self)

    def _observe(self):
        """The trial's verdict (verdict.py) from the plant as it is now."""
        vac = self.plant.vacuum() if self.pump_duty > 0 else (0.0, 0.0, 0.0, 0.0)
        self.verdict.add(
            self.plant.time, vac, self.plant.tool_position(), self.plant.force_torque()[2]
        )

    def _push(self, t, fn, period):
        self._seq += 1
        heapq.heappush(self._events, (t, self._seq, fn, period))

    def _schedule(self, fn, period):
        self._push(self.plant.time + period, fn, period)

    # ----- the graph -----
    def advertise(self, topic, msg_class):
        self.published_types.setdefault(topic, msg_class)

    def subscribe(self, topic, callback, args):
        self.subscribers.setdefault(topic, []).append((callback, args))

    def unsubscribe(self, topic, callback):
        subs = self.subscribers.get(topic, [])
        self.subscribers[topic] = [s for s in subs if s[0] is not callback]

    def publish(self, topic, msg):
        if topic == "/pwm":
            self.pump_duty = int(msg.data)
        elif topic in ("/cmdPacket", "/cmdToPsoc"):
            # The board's commands (SuctionP_callback_helper): 2 start streaming, 3 idle.
            cmd = int(getattr(msg, "cmdInput", 0))
            if cmd == 2:
                self.sampling = True
            elif cmd == 3:
                self.sampling = False
        self.logger.on_message(topic, msg)
        for callback, args in list(self.subscribers.get(topic, [])):
            if args is None:
                callback(msg)
            else:
                callback(msg, args)

    # ----- sensors -----
    def _stamp(self, msg):
        msg.header.stamp = Time.from_sec(self.ros_time_s())

    def _pressure_packet(self):
        if not self.sampling:
            return
        from suction_cup.msg import SensorPacket

        vac = self.plant.vacuum() if self.pump_duty > 0 else (0.0, 0.0, 0.0, 0.0)
        msg = SensorPacket()
        self._stamp(msg)
        msg.ch = 4
        # The board sends float32 absolute pressures; ROS hands them to Python widened.
        msg.data = tuple(
            float(np.float32(AMBIENT_PA + CHAMBER_OFFSET_PA[i] - vac[i])) for i in range(4)
        )
        self.published_types.setdefault("/SensorPacket", SensorPacket)
        self.publish("/SensorPacket", msg)

    def _ft_packet(self):
        from geometry_msgs.msg import WrenchStamped

        ft = self.plant.force_torque()
        msg = WrenchStamped()
        self._stamp(msg)
        # The transducer reads the cup's push on it: compression negative along its z.
        msg.wrench.force.x, msg.wrench.force.y, msg.wrench.force.z = -ft[0], -ft[1], -ft[2]
        msg.wrench.torque.x, msg.wrench.torque.y, msg.wrench.torque.z = -ft[3], -ft[4], -ft[5]
        self.published_types.setdefault("/netft_data", WrenchStamped)
        self.publish("/netft_data", msg)

    def _pose_packet(self):
        from geometry_msgs.msg import PoseStamped

        p, q = self.tool0_in_base_link()
        msg = PoseStamped()
        self._stamp(msg)
        msg.header.frame_id = "base_link"
        msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = (float(v) for v in p)
        (
            msg.pose.orientation.x,
            msg.pose.orientation.y,
            msg.pose.orientation.z,
            msg.pose.orientation.w,
        ) = (float(v) for v in q)
        self.published_types.setdefault("/endEffectorPose", PoseStamped)
        self.publish("/endEffectorPose", msg)

    # ----- kinematics -----
    def tool0_rotation(self):
        """tool0's rotation in the Base (= scene) orientation: the tool site's."""
        return np.asarray(self.plant.tool_rotation()).reshape(3, 3)

    def tool0_in_base(self):
        R = self.tool0_rotation()
        site = np.asarray(self.plant.tool_position())
        tool0_scene = site - R[:, 2] * self.tool_centre_offset_m
        return tool0_scene - self.base_in_scene, R

    def tool0_in_base_link(self):
        p, R = self.tool0_in_base()
        Rz = np.diag([-1.0, -1.0, 1.0])
        return _rot_z180(p), _quat_from_matrix(Rz @ R)

    def tcp_pose(self):
        """RTDE getActualTCPPose: TCP in Base, [x, y, z, rx, ry, rz]."""
        p, R = self.tool0_in_base()
        tcp = p + R @ self.tcp_offset[:3]
        Rt = R @ matrix_from_rotvec(self.tcp_offset[3:])
        return [float(v) for v in tcp] + [float(v) for v in rotvec_from_matrix(Rt)]

    def site_target_from_tcp(self, pose6):
        """The tool-site target (scene) for a TCP pose in Base; orientation is held."""
        R = self.tool0_rotation()
        tool0 = np.asarray(pose6[:3], dtype=float) - R @ self.tcp_offset[:3]
        return tool0 + self.base_in_scene + R[:, 2] * self.tool_centre_offset_m

    def orientation_error_deg(self, pose6):
        Rc = matrix_from_rotvec(pose6[3:6]) @ matrix_from_rotvec(self.tcp_offset[3:]).T
        Rerr = Rc @ self.tool0_rotation().T
        return math.degrees(math.acos(max(-1.0, min(1.0, (np.trace(Rerr) - 1) / 2))))

    # ----- motion (RTDE) -----
    def servo_to(self, pose6, lookahead_s=LAB_LOOKAHEAD_S):
        self.velocity = None
        self.plant.set_servo(TWIN_SMOOTHING_S * lookahead_s / LAB_LOOKAHEAD_S, SERVO_MAX_SPEED_M_S)
        self.plant.set_target(list(self.site_target_from_tcp(pose6)))

    def move_to(self, pose6, speed_m_s, timeout_s=None):
        """moveL: a straight move at `speed`, returning once there."""
        self.velocity = None
        goal = self.site_target_from_tcp(pose6)
        speed = min(max(float(speed_m_s), 1e-4), 3.0)
        self.plant.set_servo(MOVEL_SMOOTHING_S, speed)
        self.plant.set_target(list(goal))
        dist = np.linalg.norm(goal - np.asarray(self.plant.tool_position()))
        limit = self.plant.time + (timeout_s or dist / speed + 5.0)
        prev = np.asarray(self.plant.tool_position())
        while self.plant.time < limit and not self.shutdown:
            self.sleep(0.008)
            now = np.asarray(self.plant.tool_position())
            if np.linalg.norm(now - goal) < REACHED_M and np.linalg.norm(now - prev) < 0.01e-3:
                break
            prev = now
        self.plant.set_servo(TWIN_SMOOTHING_S, SERVO_MAX_SPEED_M_S)
        return bool(np.linalg.norm(np.asarray(self.plant.tool_position()) - goal) < 1e-3)

    def speed(self, v6, duration_s):
        self.plant.set_servo(0.0, SERVO_MAX_SPEED_M_S)
        self.plant.set_target(list(self.plant.tool_position()))
        self.velocity = (np.asarray(v6[:3], dtype=float), self.plant.time + duration_s)

    def stop(self):
        self.velocity = None
        self.plant.stop()


set_factory(World)
