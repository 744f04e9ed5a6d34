"""ROS 1 message and service types as plain Python (what genpy generates, minus serialisation).

A message class lists its fields in ``__slots__`` (the lab's data logger walks them) with their
defaults; positional or keyword arguments set them, as genpy's constructors do.
"""

import copy


class Message:
    __slots__ = ()
    _type = ""
    _factories = ()  # one per field: makes its default (a fresh sub-message or list)

    def __init__(self, *args, **kwargs):
        if args and kwargs:
            raise TypeError("%s: give fields by position or by name, not both" % self._type)
        slots = self.__slots__
        if len(args) > len(slots):
            raise TypeError("%s takes %d fields, got %d" % (self._type, len(slots), len(args)))
        for i, name in enumerate(slots):
            if i < len(args):
                value = args[i]
            elif name in kwargs:
                value = kwargs.pop(name)
            else:
                value = self._factories[i]()
            setattr(self, name, value)
        if kwargs:
            raise AttributeError("%s has no field %s" % (self._type, ", ".join(kwargs)))

    def __eq__(self, other):
        return type(self) is type(other) and all(
            getattr(self, n) == getattr(other, n) for n in self.__slots__
        )

    def __repr__(self):
        return "%s(%s)" % (
            self._type,
            ", ".join("%s=%r" % (n, getattr(self, n)) for n in self.__slots__),
        )

    __str__ = __repr__

    def __deepcopy__(self, memo):
        return type(self)(*[copy.deepcopy(getattr(self, n), memo) for n in self.__slots__])

    def __copy__(self):
        return type(self)(*[getattr(self, n) for n in self.__slots__])


def _factory(v):
    if isinstance(v, type):
        return v
    if isinstance(v, list):
        return lambda: list(v)
    return lambda: v


def message(type_name, fields):
    """A message class: fields is [(name, default value, or a class made fresh per message)]."""
    names = tuple(f[0] for f in fields)
    cls = type(
        type_name.split("/")[-1],
        (Message,),
        {"__slots__": names, "_type": type_name, "_slot_types": names},
    )
    cls._factories = tuple(_factory(f[1]) for f in fields)
    return cls


class ServiceType:
    """A service type: _request_class and _response_class, as genpy's."""

    _request_class = None
    _response_class = None


def service(type_name, request_fields, response_fields):
    base = type_name.split("/")[-1]
    req = message(type_name + "Request", request_fields)
    res = message(type_name + "Response", response_fields)
    req.__name__, res.__name__ = base + "Request", base + "Response"
    srv = type(
        base, (ServiceType,), {"_type": type_name, "_request_class": req, "_response_class": res}
    )
    return srv, req, res
