#!/usr/bin/env python
"""One revolution around the 35 mm disk, written the way the lab's edge-following scripts are
(a ROS 1 node: pressure and F/T callbacks, the pump on /pwm, the data logger service, the UR
through ur_rtde) so that it runs on the robot and, unchanged, under `ssc sil` (docs/sil.md).
It saves DataLog_<stamp>_seb_testEdgeFollowing_..._deleteMe.mat as the lab's saver does
(pandas reads the logger's CSVs in /tmp, SciPy's savemat writes them with the arguments)."""

import argparse
import os
import re
import time
from datetime import datetime

import numpy as np
import rospy
import rtde_control
import rtde_receive
from geometry_msgs.msg import WrenchStamped
from std_msgs.msg import Int8
from suction_cup.msg import SensorPacket, cmdPacket
from suction_cup.srv import Enable

DUTYCYCLE_0, DUTYCYCLE_30, DUTYCYCLE_100 = 0, 30, 100
START_CMD, IDLE_CMD = 2, 3


class PressureHelp:
    """7-sample moving average of the chambers' absolute pressure minus the in-air offset."""

    def __init__(self):
        self.buffer = []
        self.offset = np.zeros(4)
        self.four_pressure = np.zeros(4)
        self.packets = 0
        rospy.Subscriber("SensorPacket", SensorPacket, self.callback)
        self.cmd = rospy.Publisher("cmdPacket", cmdPacket, queue_size=10)

    def callback(self, msg):
        self.packets += 1
        self.buffer = (self.buffer + [np.array(msg.data, dtype=float) - self.offset])[-7:]
        self.four_pressure = np.mean(self.buffer, axis=0)

    def start_sampling(self):
        self.cmd.publish(cmdPacket(cmdInput=START_CMD))

    def stop_sampling(self):
        self.cmd.publish(cmdPacket(cmdInput=IDLE_CMD))

    def set_now_as_offset(self):
        self.offset = self.offset + np.mean(self.buffer, axis=0)
        self.buffer = []
        rospy.sleep(0.1)


class ForceHelp:
    """7-sample average of the F/T, tared when asked."""

    def __init__(self):
        self.buffer = []
        self.bias = np.zeros(6)
        rospy.Subscriber("netft_data", WrenchStamped, self.callback)

    def callback(self, msg):
        f, t = msg.wrench.force, msg.wrench.torque
        self.buffer = (self.buffer + [np.array([f.x, f.y, f.z, t.x, t.y, t.z])])[-7:]

    def wrench(self):
        return np.mean(self.buffer, axis=0) - self.bias

    def set_now_as_bias(self):
        self.bias = np.mean(self.buffer, axis=0)


def rotation(rotvec):
    a = np.linalg.norm(rotvec)
    if a < 1e-12:
        return np.eye(3)
    k = np.asarray(rotvec) / a
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


def moved_in_tool_frame(pose, d):
    """The TCP pose moved by d = [dx, dy, dz] along the tool's own axes."""
    p = np.array(pose[:3]) + rotation(pose[3:]) @ np.asarray(d)
    return list(p) + list(pose[3:])


def save_data_params(args, append_txt):
    """The lab's saver: every CSV in /tmp into one .mat with the arguments."""
    import pandas as pd
    from scipy.io import savemat

    files = sorted(os.path.join("/tmp", f) for f in os.listdir("/tmp") if f.endswith(".csv"))
    saving = {}
    parts = []
    for name in files:
        try:
            df = pd.read_csv(name)
        except Exception as e:  # a topic with no message: an empty file
            print(e)
            continue
        parts = re.split(r"_|\.", name)
        topic = "".join(parts[4:-1])
        saving[topic + "_columnName"] = df.columns.tolist()
        saving[topic + "_data"] = df.values
    saving.update(vars(args))
    folder = os.path.join(
        os.path.expanduser("~"), "SuctionExperiment", datetime.now().strftime("%y%m%d")
    )
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "DataLog_" + "_".join(parts[1:4]) + "_" + append_txt + ".mat")
    savemat(path, saving)
    print("saved", path)
    return path


def main(args):
    rospy.init_node("lab_style_disk")
    P_help = PressureHelp()
    FT_help = ForceHelp()
    rtde_c = rtde_control.RTDEControlInterface("10.0.0.1", 125)
    rtde_r = rtde_receive.RTDEReceiveInterface("10.0.0.1", 125)
    rtde_c.setTcp([0, 0, 0.146, 0, 0, 0])
    pwm = rospy.Publisher("pwm", Int8, queue_size=1)
    pwm.publish(DUTYCYCLE_0)
    rospy.wait_for_service("data_logging")
    data_logger = rospy.ServiceProxy("data_logging", Enable)
    data_logger(False)

    # The script starts with the cup above the disk's centre: lift, tare in air at 30 % PWM.
    centre = rtde_r.getActualTCPPose()
    rtde_c.moveL(moved_in_tool_frame(centre, [0, 0, -args.lift]), 0.05, 0.1)
    pwm.publish(DUTYCYCLE_30)
    P_help.start_sampling()
    rospy.sleep(0.5)
    FT_help.set_now_as_bias()
    P_help.set_now_as_offset()
    data_logger(True)
    rospy.sleep(0.2)

    start = moved_in_tool_frame(centre, [0, args.start_offset, -args.lift])
    rtde_c.moveL(start, 0.05, 0.1)
    pwm.publish(DUTYCYCLE_100)

    # Down along the tool axis until the normal force is in the band.
    target = rtde_r.getActualTCPPose()
    while FT_help.wrench()[2] > -args.Fz_set[0] and not rospy.is_shutdown():
        target = moved_in_tool_frame(target, [0, 0, args.d_z])
        t0 = rtde_c.initPeriod()
        rtde_c.servoL(target, 0, 0, 0.1, 0.2, 100)
        rtde_c.waitPeriod(t0)
        rospy.sleep(0.01)
    rtde_c.servoStop()

    x0, y0 = centre[0], centre[1]
    history = []
    swept = 0.0
    start_time = time.time()
    rate = rospy.Rate(1.0 / args.period)
    # The lab's correction scale: lines through (P_ref, 0) and (10 Pa, beta) below P_ref, and
    # (15000 Pa, beta) above it, in log10 of the mean vacuum.
    m_below = args.beta / (np.log10(10.0) - np.log10(args.Pref))
    m_above = args.beta / (np.log10(15000.0) - np.log10(args.Pref))
    for i in range(args.max_iterations):
        P = np.array(P_help.four_pressure)
        P0, P1, P2, P3 = P
        dP_WE = (P3 + P2) / 2 - (P1 + P0) / 2
        dP_SN = (P0 + P3) / 2 - (P1 + P2) / 2
        r_p = np.array([-dP_SN, dP_WE]) / np.hypot(dP_SN, dP_WE)
        corr_p = np.array([-dP_WE, -dP_SN]) / np.hypot(dP_SN, dP_WE)
        P_mean = abs(np.mean(P))
        if P_mean > args.Pref:
            corr_p, scale = -corr_p, m_above * (np.log10(P_mean) - np.log10(args.Pref))
        elif P_mean < args.Pref:
            scale = m_below * (np.log10(P_mean) - np.log10(args.Pref))
        else:
            corr_p, scale = np.zeros(2), 0.0
        r_final = r_p + corr_p * scale
        r_final = r_final / np.linalg.norm(r_final)
        pose = rtde_r.getActualTCPPose()
        history.append(
            [
                time.time() - start_time,
                pose[0],
                pose[1],
                r_p,
                corr_p,
                r_final,
                FT_help.wrench()[2],
                *P,
            ]
        )
        swept = (
            np.degrees(
                np.arctan2(pose[1] - y0, pose[0] - x0) - np.arctan2(start[1] - y0, start[0] - x0)
            )
            % 360
        )
        if i > 10 and swept > 355:
            args.success = 1
            break
        if all(P < -10000) or P_mean < 5:
            break
        step = [r_final[1] * args.d_lat, r_final[0] * args.d_lat, 0]
        rtde_c.servoL(moved_in_tool_frame(pose, step), 0, 0, 0.01, 0.2, 100)
        rate.sleep()

    rtde_c.servoStop()
    pwm.publish(DUTYCYCLE_0)
    rospy.sleep(0.2)
    args.edgeFollowing_history = history
    args.swept_deg = swept
    save_data_params(
        args,
        "seb_testEdgeFollowing_refP_%s_beta_%s_step_%s_deleteMe"
        % (args.Pref, args.beta, args.d_lat),
    )
    data_logger(False)
    P_help.stop_sampling()
    print(
        "lab_style_disk: success %d after %d iterations, swept %.1f deg, %d pressure packets"
        % (args.success, len(history), swept, P_help.packets)
    )


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--Pref", type=float, default=100.0)
    parser.add_argument("--beta", type=float, default=2.0)
    parser.add_argument("--dl-mm", type=float, default=7.5)
    parser.add_argument("--max-iterations", type=int, default=150)
    args = parser.parse_args()
    args.d_lat = args.dl_mm * 1e-3
    del args.dl_mm
    args.diskRadius = 35
    args.start_offset = 31e-3
    args.lift = 5e-3
    args.d_z = 0.05e-3
    args.period = 0.15
    args.Fz_set = [1.1, 1.2]
    args.P_lims = [args.Pref, args.Pref]
    args.alpha_beta = [0.0, args.beta, 0.0, args.beta]
    args.success = 0
    main(args)
