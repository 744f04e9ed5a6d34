"""The lab's data logger (its data_logger.py node, newer version) as a service of the world.

``data_logging`` (suction_cup/Enable): True opens one CSV per listed topic that has a publisher,
False closes them. Files, header and rows as shared/reference/lab-logs.md describes (and
robotlog/topic_csv.h reads): ``/tmp/dataLog_<YYYY>_<MMDD>_<HHMMSS>_<topic, '/' -> '_'>.csv``,
``ROStimestamp`` then ``<topic>.<field>`` per numeric field in alphabetical order (arrays as
``<field>[i]``), the header written on the topic's first message; the stamp is the message's
``header.stamp`` (else the time of receipt) in integer ns; values as Python's ``str``, an array's
elements separated by ", ". Each row is flushed, so the script's own saver can read the files
while logging runs (the lab's saves before it stops the logger).
"""

import numbers
import os
from datetime import datetime


def _numeric_fields(msg, prefix, out):
    """(path, length) of each numeric field, recursing through messages; header skipped."""
    if hasattr(msg, "__slots__"):
        for name in msg.__slots__:
            if name == "header":
                continue
            _numeric_fields(getattr(msg, name), prefix + "." + name, out)
    elif isinstance(msg, numbers.Number):
        out[prefix[1:]] = 1
    elif isinstance(msg, (list, tuple)) and msg and isinstance(msg[0], numbers.Number):
        out[prefix[1:]] = len(msg)


def _get(msg, path):
    for part in path.split("."):
        msg = getattr(msg, part)
    return msg


# The topics the lab's logger records unless its topic file names others.
DEFAULT_TOPICS = ("/netft_data", "/SensorPacket", "/pwm", "/endEffectorPose", "/sync")


class DataLogger:
    def __init__(self, world, topics_file=None):
        self.world = world
        self.topics = self._read_topics(topics_file)
        self.enabled = False
        self.files = {}  # topic -> open file
        self.fields = {}  # topic -> sorted [(path, length)]
        self.paths = []
        self.started = 0

    @staticmethod
    def _read_topics(path):
        if not path:
            return list(DEFAULT_TOPICS)
        with open(path) as f:
            return [line.strip() for line in f if line.strip()]

    def set_enabled(self, on):
        """The service handler; returns the files' names separated by spaces (as the lab's)."""
        if on and not self.enabled:
            stamp = datetime.fromtimestamp(self.world.ros_time_s()).strftime("%Y_%m%d_%H%M%S")
            self.paths = []
            for topic in self.topics:
                if topic not in self.world.published_types:
                    continue  # the lab's logger finds no type for an unpublished topic
                name = "dataLog_{}_{}.csv".format(stamp, topic.replace("/", "_"))
                path = os.path.join(self.world.tmp_dir, name)
                self.files[topic] = open(path, "w")
                self.paths.append("/tmp/" + name)
            self.fields = {}
            self.enabled = True
            self.started += 1
            if self.world.verbose:
                print("[sil] data logging started: " + " ".join(self.paths))
        elif not on and self.enabled:
            for f in self.files.values():
                f.close()
            self.files = {}
            self.enabled = False
            if self.world.verbose:
                print("[sil] data logging stopped")
        return " ".join(self.paths) + (" " if self.paths else "")

    def on_message(self, topic, msg):
        if not self.enabled:
            return
        f = self.files.get(topic)
        if f is None:
            return
        if topic not in self.fields:
            found = {}
            _numeric_fields(msg, "", found)
            self.fields[topic] = sorted(found.items())
            header = "ROStimestamp"
            for path, n in self.fields[topic]:
                if n > 1:
                    header += "".join(",{}.{}[{}]".format(topic, path, i) for i in range(n))
                else:
                    header += ",{}.{}".format(topic, path)
            f.write(header + "\n")
        stamp = None
        header = getattr(msg, "header", None)
        if header is not None and header.stamp.secs > 0:
            stamp = header.stamp
        if stamp is None:
            from .rostime import Time

            stamp = Time.from_sec(self.world.ros_time_s())
        line = "{}".format(stamp)
        for path, n in self.fields[topic]:
            text = str(_get(msg, path))
            line += "," + (text[1:-1] if n > 1 else text)
        f.write(line + "\n")
        f.flush()
