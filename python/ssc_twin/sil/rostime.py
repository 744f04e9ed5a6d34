"""rospy's Time and Duration (genpy's semantics: secs/nsecs, str() = integer nanoseconds)."""

import math


class _TVal:
    __slots__ = ("secs", "nsecs")

    def __init__(self, secs=0, nsecs=0):
        if isinstance(secs, float):
            whole = math.floor(secs)
            nsecs = int(round((secs - whole) * 1e9)) + int(nsecs)
            secs = int(whole)
        secs, nsecs = int(secs), int(nsecs)
        secs += nsecs // 1000000000
        nsecs %= 1000000000
        self.secs, self.nsecs = secs, nsecs

    @classmethod
    def from_sec(cls, s):
        return cls(float(s))

    @classmethod
    def from_seconds(cls, s):
        return cls(float(s))

    def to_sec(self):
        return self.secs + self.nsecs * 1e-9

    def to_nsec(self):
        return self.secs * 1000000000 + self.nsecs

    def is_zero(self):
        return self.secs == 0 and self.nsecs == 0

    def __str__(self):
        return str(self.to_nsec())

    def __repr__(self):
        return "%s[%d]" % (type(self).__name__, self.to_nsec())

    def __float__(self):
        return self.to_sec()

    def __hash__(self):
        return hash(self.to_nsec())

    def __eq__(self, o):
        return isinstance(o, _TVal) and self.to_nsec() == o.to_nsec()

    def __lt__(self, o):
        return self.to_nsec() < o.to_nsec()

    def __le__(self, o):
        return self.to_nsec() <= o.to_nsec()

    def __gt__(self, o):
        return self.to_nsec() > o.to_nsec()

    def __ge__(self, o):
        return self.to_nsec() >= o.to_nsec()


class Duration(_TVal):
    def __add__(self, o):
        if isinstance(o, Time):
            return Time(0, self.to_nsec() + o.to_nsec())
        return Duration(0, self.to_nsec() + o.to_nsec())

    def __sub__(self, o):
        return Duration(0, self.to_nsec() - o.to_nsec())

    def __neg__(self):
        return Duration(0, -self.to_nsec())

    def __mul__(self, k):
        return Duration(self.to_sec() * k)

    __rmul__ = __mul__


class Time(_TVal):
    @staticmethod
    def now():
        from .current import current

        return Time.from_sec(current().ros_time_s())

    def __add__(self, o):
        return Time(0, self.to_nsec() + o.to_nsec())

    def __sub__(self, o):
        if isinstance(o, Time):
            return Duration(0, self.to_nsec() - o.to_nsec())
        return Time(0, self.to_nsec() - o.to_nsec())
