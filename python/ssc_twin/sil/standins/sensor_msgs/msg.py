"""sensor_msgs stand-ins (ssc_twin.sil): camera types only, never published (no camera)."""

from ssc_twin.sil.messages import message as _m
from std_msgs.msg import Header

Image = _m(
    "sensor_msgs/Image",
    [
        ("header", Header),
        ("height", 0),
        ("width", 0),
        ("encoding", ""),
        ("is_bigendian", 0),
        ("step", 0),
        ("data", b""),
    ],
)
CameraInfo = _m(
    "sensor_msgs/CameraInfo",
    [
        ("header", Header),
        ("height", 0),
        ("width", 0),
        ("distortion_model", ""),
        ("D", []),
        ("K", [0.0] * 9),
        ("R", [0.0] * 9),
        ("P", [0.0] * 12),
    ],
)
JointState = _m(
    "sensor_msgs/JointState",
    [("header", Header), ("name", []), ("position", []), ("velocity", []), ("effort", [])],
)
