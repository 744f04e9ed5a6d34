"""std_msgs stand-ins (ssc_twin.sil)."""

from ssc_twin.sil.messages import message as _m


from ssc_twin.sil.rostime import Time as _Time

Header = _m("std_msgs/Header", [("seq", 0), ("stamp", _Time), ("frame_id", "")])
String = _m("std_msgs/String", [("data", "")])
Bool = _m("std_msgs/Bool", [("data", False)])
Empty = _m("std_msgs/Empty", [])
Int8 = _m("std_msgs/Int8", [("data", 0)])
Int16 = _m("std_msgs/Int16", [("data", 0)])
Int32 = _m("std_msgs/Int32", [("data", 0)])
Int64 = _m("std_msgs/Int64", [("data", 0)])
UInt8 = _m("std_msgs/UInt8", [("data", 0)])
UInt16 = _m("std_msgs/UInt16", [("data", 0)])
Float32 = _m("std_msgs/Float32", [("data", 0.0)])
Float64 = _m("std_msgs/Float64", [("data", 0.0)])
Float32MultiArray = _m("std_msgs/Float32MultiArray", [("data", [])])
Float64MultiArray = _m("std_msgs/Float64MultiArray", [("data", [])])
Int32MultiArray = _m("std_msgs/Int32MultiArray", [("data", [])])
