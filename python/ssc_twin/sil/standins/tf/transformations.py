"""tf.transformations stand-in: the functions of Gohlke's transformations.py the lab uses, with
its conventions (quaternions x, y, z, w; 4x4 homogeneous matrices; axes strings such as 'sxyz')."""

import math

import numpy

_EPS = numpy.finfo(float).eps * 4.0
_NEXT_AXIS = [1, 2, 0, 1]
_AXES2TUPLE = {
    "sxyz": (0, 0, 0, 0),
    "sxyx": (0, 0, 1, 0),
    "sxzy": (0, 1, 0, 0),
    "sxzx": (0, 1, 1, 0),
    "syzx": (1, 0, 0, 0),
    "syzy": (1, 0, 1, 0),
    "syxz": (1, 1, 0, 0),
    "syxy": (1, 1, 1, 0),
    "szxy": (2, 0, 0, 0),
    "szxz": (2, 0, 1, 0),
    "szyx": (2, 1, 0, 0),
    "szyz": (2, 1, 1, 0),
    "rzyx": (0, 0, 0, 1),
    "rxyx": (0, 0, 1, 1),
    "ryzx": (0, 1, 0, 1),
    "rxzx": (0, 1, 1, 1),
    "rxzy": (1, 0, 0, 1),
    "ryzy": (1, 0, 1, 1),
    "rzxy": (1, 1, 0, 1),
    "ryxy": (1, 1, 1, 1),
    "ryxz": (2, 0, 0, 1),
    "rzxz": (2, 0, 1, 1),
    "rxyz": (2, 1, 0, 1),
    "rzyz": (2, 1, 1, 1),
}


def _axes(axes):
    try:
        return _AXES2TUPLE[axes.lower()]
    except (AttributeError, KeyError):
        return axes


def identity_matrix():
    return numpy.identity(4)


def translation_matrix(direction):
    M = numpy.identity(4)
    M[:3, 3] = direction[:3]
    return M


def translation_from_matrix(matrix):
    return numpy.asarray(matrix)[:3, 3].copy()


def inverse_matrix(matrix):
    return numpy.linalg.inv(matrix)


def concatenate_matrices(*matrices):
    M = numpy.identity(4)
    for i in matrices:
        M = numpy.dot(M, i)
    return M


def quaternion_matrix(quaternion):
    q = numpy.array(quaternion[:4], dtype=numpy.float64, copy=True)
    nq = numpy.dot(q, q)
    if nq < _EPS:
        return numpy.identity(4)
    q *= math.sqrt(2.0 / nq)
    q = numpy.outer(q, q)
    return numpy.array(
        (
            (1.0 - q[1, 1] - q[2, 2], q[0, 1] - q[2, 3], q[0, 2] + q[1, 3], 0.0),
            (q[0, 1] + q[2, 3], 1.0 - q[0, 0] - q[2, 2], q[1, 2] - q[0, 3], 0.0),
            (q[0, 2] - q[1, 3], q[1, 2] + q[0, 3], 1.0 - q[0, 0] - q[1, 1], 0.0),
            (0.0, 0.0, 0.0, 1.0),
        ),
        dtype=numpy.float64,
    )


def quaternion_from_matrix(matrix):
    M = numpy.asarray(matrix, dtype=numpy.float64)[:4, :4]
    q = numpy.empty((4,), dtype=numpy.float64)
    t = numpy.trace(M[:3, :3]) + 1.0
    if t > 1.0 - _EPS or t > M[0, 0] + 1.0 and t > M[1, 1] + 1.0 and t > M[2, 2] + 1.0:
        q[3] = t
        q[2] = M[1, 0] - M[0, 1]
        q[1] = M[0, 2] - M[2, 0]
        q[0] = M[2, 1] - M[1, 2]
    else:
        i, j, k = 0, 1, 2
        if M[1, 1] > M[0, 0]:
            i, j, k = 1, 2, 0
        if M[2, 2] > M[i, i]:
            i, j, k = 2, 0, 1
        t = M[i, i] - (M[j, j] + M[k, k]) + 1.0
        q[i] = t
        q[j] = M[i, j] + M[j, i]
        q[k] = M[k, i] + M[i, k]
        q[3] = M[k, j] - M[j, k]
    q *= 0.5 / math.sqrt(t)
    return q


def euler_matrix(ai, aj, ak, axes="sxyz"):
    firstaxis, parity, repetition, frame = _axes(axes)
    i = firstaxis
    j = _NEXT_AXIS[i + parity]
    k = _NEXT_AXIS[i - parity + 1]
    if frame:
        ai, ak = ak, ai
    if parity:
        ai, aj, ak = -ai, -aj, -ak
    si, sj, sk = math.sin(ai), math.sin(aj), math.sin(ak)
    ci, cj, ck = math.cos(ai), math.cos(aj), math.cos(ak)
    cc, cs = ci * ck, ci * sk
    sc, ss = si * ck, si * sk
    M = numpy.identity(4)
    if repetition:
        M[i, i] = cj
        M[i, j] = sj * si
        M[i, k] = sj * ci
        M[j, i] = sj * sk
        M[j, j] = -cj * ss + cc
        M[j, k] = -cj * cs - sc
        M[k, i] = -sj * ck
        M[k, j] = cj * sc + cs
        M[k, k] = cj * cc - ss
    else:
        M[i, i] = cj * ck
        M[i, j] = sj * sc - cs
        M[i, k] = sj * cc + ss
        M[j, i] = cj * sk
        M[j, j] = sj * ss + cc
        M[j, k] = sj * cs - sc
        M[k, i] = -sj
        M[k, j] = cj * si
        M[k, k] = cj * ci
    return M


def euler_from_matrix(matrix, axes="sxyz"):
    firstaxis, parity, repetition, frame = _axes(axes)
    i = firstaxis
    j = _NEXT_AXIS[i + parity]
    k = _NEXT_AXIS[i - parity + 1]
    M = numpy.asarray(matrix, dtype=numpy.float64)[:3, :3]
    if repetition:
        sy = math.sqrt(M[i, j] * M[i, j] + M[i, k] * M[i, k])
        if sy > _EPS:
            ax = math.atan2(M[i, j], M[i, k])
            ay = math.atan2(sy, M[i, i])
            az = math.atan2(M[j, i], -M[k, i])
        else:
            ax = math.atan2(-M[j, k], M[j, j])
            ay = math.atan2(sy, M[i, i])
            az = 0.0
    else:
        cy = math.sqrt(M[i, i] * M[i, i] + M[j, i] * M[j, i])
        if cy > _EPS:
            ax = math.atan2(M[k, j], M[k, k])
            ay = math.atan2(-M[k, i], cy)
            az = math.atan2(M[j, i], M[i, i])
        else:
            ax = math.atan2(-M[j, k], M[j, j])
            ay = math.atan2(-M[k, i], cy)
            az = 0.0
    if parity:
        ax, ay, az = -ax, -ay, -az
    if frame:
        ax, az = az, ax
    return ax, ay, az


def quaternion_from_euler(ai, aj, ak, axes="sxyz"):
    return quaternion_from_matrix(euler_matrix(ai, aj, ak, axes))


def euler_from_quaternion(quaternion, axes="sxyz"):
    return euler_from_matrix(quaternion_matrix(quaternion), axes)


def quaternion_about_axis(angle, axis):
    q = numpy.zeros((4,))
    q[:3] = axis[:3]
    qlen = numpy.linalg.norm(q)
    if qlen > _EPS:
        q *= math.sin(angle / 2.0) / qlen
    q[3] = math.cos(angle / 2.0)
    return q


def quaternion_multiply(quaternion1, quaternion0):
    x0, y0, z0, w0 = quaternion0
    x1, y1, z1, w1 = quaternion1
    return numpy.array(
        (
            x1 * w0 + y1 * z0 - z1 * y0 + w1 * x0,
            -x1 * z0 + y1 * w0 + z1 * x0 + w1 * y0,
            x1 * y0 - y1 * x0 + z1 * w0 + w1 * z0,
            -x1 * x0 - y1 * y0 - z1 * z0 + w1 * w0,
        ),
        dtype=numpy.float64,
    )


def quaternion_conjugate(quaternion):
    return numpy.array(
        (-quaternion[0], -quaternion[1], -quaternion[2], quaternion[3]), dtype=numpy.float64
    )


def quaternion_inverse(quaternion):
    return quaternion_conjugate(quaternion) / numpy.dot(quaternion, quaternion)


def rotation_matrix(angle, direction, point=None):
    sina, cosa = math.sin(angle), math.cos(angle)
    direction = numpy.array(direction[:3], dtype=float)
    direction /= numpy.linalg.norm(direction)
    R = numpy.array(((cosa, 0.0, 0.0), (0.0, cosa, 0.0), (0.0, 0.0, cosa)), dtype=numpy.float64)
    R += numpy.outer(direction, direction) * (1.0 - cosa)
    direction *= sina
    R += numpy.array(
        (
            (0.0, -direction[2], direction[1]),
            (direction[2], 0.0, -direction[0]),
            (-direction[1], direction[0], 0.0),
        ),
        dtype=numpy.float64,
    )
    M = numpy.identity(4)
    M[:3, :3] = R
    if point is not None:
        point = numpy.asarray(point[:3], dtype=numpy.float64)
        M[:3, 3] = point - numpy.dot(R, point)
    return M


def random_vector(size):
    return numpy.random.random(size)


def unit_vector(data, axis=None):
    data = numpy.array(data, dtype=numpy.float64, copy=True)
    if axis is None and data.ndim == 1:
        return data / math.sqrt(numpy.dot(data, data))
    return data / numpy.expand_dims(numpy.sqrt(numpy.sum(data * data, axis)), axis)


def vector_norm(data, axis=None):
    data = numpy.array(data, dtype=numpy.float64, copy=True)
    if axis is None and data.ndim == 1:
        return math.sqrt(numpy.dot(data, data))
    return numpy.sqrt(numpy.sum(data * data, axis=axis))


def random_quaternion(rand=None):
    rand = numpy.random.rand(3) if rand is None else rand
    r1, r2 = numpy.sqrt(1.0 - rand[0]), numpy.sqrt(rand[0])
    t1, t2 = 2 * math.pi * rand[1], 2 * math.pi * rand[2]
    return numpy.array(
        (numpy.sin(t1) * r1, numpy.cos(t1) * r1, numpy.sin(t2) * r2, numpy.cos(t2) * r2),
        dtype=numpy.float64,
    )


def quaternion_slerp(quat0, quat1, fraction, spin=0, shortestpath=True):
    q0 = unit_vector(quat0[:4])
    q1 = unit_vector(quat1[:4])
    if fraction == 0.0:
        return q0
    if fraction == 1.0:
        return q1
    d = numpy.dot(q0, q1)
    if abs(abs(d) - 1.0) < _EPS:
        return q0
    if shortestpath and d < 0.0:
        d = -d
        q1 *= -1.0
    angle = math.acos(d) + spin * math.pi
    if abs(angle) < _EPS:
        return q0
    isin = 1.0 / math.sin(angle)
    q0 *= math.sin((1.0 - fraction) * angle) * isin
    q1 *= math.sin(fraction * angle) * isin
    q0 += q1
    return q0
