"""tae_psoc messages (the older package name of the lab's pressure board messages)."""

from ssc_twin.sil.messages import message as _m
from std_msgs.msg import Header
from suction_cup.msg import SensorPacket  # noqa: F401  the same packet

cmdToPsoc = _m("tae_psoc/cmdToPsoc", [("header", Header), ("cmdInput", 0)])
