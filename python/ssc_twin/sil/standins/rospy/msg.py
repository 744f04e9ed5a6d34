"""rospy.msg stand-in."""


class AnyMsg:
    _type = "*"
    __slots__ = ("_buff",)
