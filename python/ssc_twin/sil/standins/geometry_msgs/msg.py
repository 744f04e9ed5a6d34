"""geometry_msgs stand-ins (ssc_twin.sil)."""

from ssc_twin.sil.messages import message as _m
from std_msgs.msg import Header

Vector3 = _m("geometry_msgs/Vector3", [("x", 0.0), ("y", 0.0), ("z", 0.0)])
Point = _m("geometry_msgs/Point", [("x", 0.0), ("y", 0.0), ("z", 0.0)])
Quaternion = _m("geometry_msgs/Quaternion", [("x", 0.0), ("y", 0.0), ("z", 0.0), ("w", 1.0)])
Pose = _m("geometry_msgs/Pose", [("position", Point), ("orientation", Quaternion)])
PoseStamped = _m("geometry_msgs/PoseStamped", [("header", Header), ("pose", Pose)])
Transform = _m("geometry_msgs/Transform", [("translation", Vector3), ("rotation", Quaternion)])
TransformStamped = _m(
    "geometry_msgs/TransformStamped",
    [("header", Header), ("child_frame_id", ""), ("transform", Transform)],
)
Wrench = _m("geometry_msgs/Wrench", [("force", Vector3), ("torque", Vector3)])
WrenchStamped = _m("geometry_msgs/WrenchStamped", [("header", Header), ("wrench", Wrench)])
Twist = _m("geometry_msgs/Twist", [("linear", Vector3), ("angular", Vector3)])
TwistStamped = _m("geometry_msgs/TwistStamped", [("header", Header), ("twist", Twist)])
