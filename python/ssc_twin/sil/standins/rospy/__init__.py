"""rospy stand-in (ssc_twin.sil): the node's API over the twin's world.

Topics, services and time are the world's (ssc_twin.sil.world): callbacks run in the caller's
thread while time advances (inside sleep, Rate.sleep and the robot's blocking calls), in time
order, never concurrently. Names resolve as rospy's do for a node in the root namespace.
"""

import sys as _sys

from ssc_twin.sil.rostime import Duration, Time  # noqa: F401
from ssc_twin.sil.world import current as _world


class ROSException(Exception):
    pass


class ROSInterruptException(ROSException, KeyboardInterrupt):
    pass


class ROSTimeMovedBackwardsException(ROSInterruptException):
    pass


class ServiceException(ROSException):
    pass


_node = {"name": "/unnamed", "params": {}}
_shutdown_hooks = []


def _resolve(name):
    if name.startswith("~"):
        return _node["name"] + "/" + name[1:]
    return name if name.startswith("/") else "/" + name


def resolve_name(name, caller_id=None):
    return _resolve(name)


def init_node(name, argv=None, anonymous=False, log_level=None, disable_signals=False, **kwargs):
    _node["name"] = "/" + name.lstrip("/")
    _world()


def get_name():
    return _node["name"]


def get_caller_id():
    return _node["name"]


def get_time():
    return _world().ros_time_s()


def get_rostime():
    return Time.from_sec(_world().ros_time_s())


def is_shutdown():
    return _world().shutdown


def signal_shutdown(reason=""):
    w = _world()
    if not w.shutdown:
        for hook in list(_shutdown_hooks):
            hook()
    w.shutdown = True


def on_shutdown(hook):
    _shutdown_hooks.append(hook)


def _check():
    if _world().shutdown:
        raise ROSInterruptException("rospy shutdown")


def sleep(duration):
    """Advances the world by `duration` (s, or a Duration)."""
    _check()
    if isinstance(duration, Duration):
        duration = duration.to_sec()
    _world().sleep(float(duration))


def spin():
    """Runs the world until shutdown (in virtual time: until the simulation's time limit)."""
    w = _world()
    while not w.shutdown:
        w.sleep(0.1)


class Rate:
    def __init__(self, hz, reset=False):
        self.period = 1.0 / float(hz)
        self.last = _world().sim_time

    def sleep(self):
        _check()
        w = _world()
        target = self.last + self.period
        if target > w.sim_time:
            w.advance_to(target)
            self.last = target
        else:
            self.last = w.sim_time

    def remaining(self):
        return Duration(max(0.0, self.last + self.period - _world().sim_time))


class Timer:
    def __init__(self, period, callback, oneshot=False, reset=False):
        raise NotImplementedError("rospy.Timer: not emulated by ssc_twin.sil")


def _log(level, msg, *args):
    if args:
        msg = msg % args
    stream = _sys.stderr if level in ("WARN", "ERROR", "FATAL") else _sys.stdout
    stream.write("[%s] [%.3f]: %s\n" % (level, _world().ros_time_s(), msg))


def loginfo(msg, *args, **kwargs):
    _log("INFO", msg, *args)


def logwarn(msg, *args, **kwargs):
    _log("WARN", msg, *args)


def logerr(msg, *args, **kwargs):
    _log("ERROR", msg, *args)


def logfatal(msg, *args, **kwargs):
    _log("FATAL", msg, *args)


def logdebug(msg, *args, **kwargs):
    pass


loginfo_throttle = lambda period, msg, *a, **k: loginfo(msg, *a)  # noqa: E731
logwarn_throttle = lambda period, msg, *a, **k: logwarn(msg, *a)  # noqa: E731
loginfo_once = loginfo
logwarn_once = logwarn


def get_param(name, default=KeyError):
    key = _resolve(name)
    if key in _node["params"]:
        return _node["params"][key]
    if default is KeyError:
        raise KeyError(name)
    return default


def set_param(name, value):
    _node["params"][_resolve(name)] = value


def has_param(name):
    return _resolve(name) in _node["params"]


def delete_param(name):
    _node["params"].pop(_resolve(name), None)


def _make(msg_class, args, kwargs):
    if len(args) == 1 and not kwargs and isinstance(args[0], msg_class):
        return args[0]
    return msg_class(*args, **kwargs)


class Publisher:
    def __init__(
        self,
        name,
        data_class,
        subscriber_listener=None,
        tcp_nodelay=False,
        latch=False,
        headers=None,
        queue_size=None,
    ):
        self.name = _resolve(name)
        self.resolved_name = self.name
        self.data_class = data_class
        _world().advertise(self.name, data_class)

    def publish(self, *args, **kwargs):
        _world().publish(self.name, _make(self.data_class, args, kwargs))

    def get_num_connections(self):
        return len(_world().subscribers.get(self.name, []))

    def unregister(self):
        pass


class Subscriber:
    def __init__(
        self,
        name,
        data_class,
        callback=None,
        callback_args=None,
        queue_size=None,
        buff_size=65536,
        tcp_nodelay=False,
    ):
        self.name = _resolve(name)
        self.resolved_name = self.name
        self.data_class = data_class
        self.callback = callback
        if callback is not None:
            _world().subscribe(self.name, callback, callback_args)

    def unregister(self):
        if self.callback is not None:
            _world().unsubscribe(self.name, self.callback)
            self.callback = None


def wait_for_message(topic, topic_type, timeout=None):
    got = []
    sub = Subscriber(topic, topic_type, got.append)
    w = _world()
    limit = w.sim_time + (timeout if timeout is not None else 60.0)
    while not got and w.sim_time < limit:
        w.sleep(0.001)
    sub.unregister()
    if not got:
        raise ROSException("timeout exceeded while waiting for a message on topic %s" % topic)
    return got[0]


def _service_handler(name):
    w = _world()
    name = _resolve(name)
    if name == "/data_logging":
        return lambda req: w.logger.set_enabled(bool(req.EnableDataLogging))
    return w.services.get(name)


def wait_for_service(service, timeout=None):
    if _service_handler(service) is None:
        raise ROSException(
            "timeout exceeded while waiting for service %s: the twin serves "
            "data_logging and the services this node advertises" % _resolve(service)
        )


class ServiceProxy:
    def __init__(self, name, service_class, persistent=False, headers=None):
        self.resolved_name = _resolve(name)
        self.service_class = service_class

    def __call__(self, *args, **kwargs):
        return self.call(*args, **kwargs)

    def call(self, *args, **kwargs):
        handler = _service_handler(self.resolved_name)
        if handler is None:
            raise ServiceException(
                "service [%s] unavailable (not served by the twin)" % self.resolved_name
            )
        req = _make(self.service_class._request_class, args, kwargs)
        res = handler(req)
        if isinstance(res, self.service_class._response_class):
            return res
        if isinstance(res, (tuple, list)):
            return self.service_class._response_class(*res)
        if isinstance(res, dict):
            return self.service_class._response_class(**res)
        return self.service_class._response_class(res)

    def close(self):
        pass

    def wait_for_service(self, timeout=None):
        wait_for_service(self.resolved_name, timeout)


class Service:
    def __init__(self, name, service_class, handler, buff_size=65536, error_handler=None):
        self.resolved_name = _resolve(name)
        _world().services[self.resolved_name] = handler

    def shutdown(self, reason=""):
        _world().services.pop(self.resolved_name, None)


from . import msg  # noqa: E402,F401
