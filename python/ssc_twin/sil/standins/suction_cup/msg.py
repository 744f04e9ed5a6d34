"""The lab's suction_cup messages (msg/SensorPacket.msg, msg/cmdPacket.msg)."""

from ssc_twin.sil.messages import message as _m
from std_msgs.msg import Header

SensorPacket = _m("suction_cup/SensorPacket", [("header", Header), ("ch", 0), ("data", [])])
cmdPacket = _m("suction_cup/cmdPacket", [("header", Header), ("cmdInput", 0)])
