from . import msg  # noqa: F401  (the lab's scripts use geometry_msgs.msg.X after import geometry_msgs.msg)
