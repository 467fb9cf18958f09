"""Typical bug of 04-intersect-triangle: third edge not checked (u + v > 1). raylab check must name it."""

import math

import numpy as np


def intersect_triangle(origin, direction, v0, v1, v2, t_min, t_max):
    e1, e2 = v1 - v0, v2 - v0
    p = np.cross(direction, e2)
    det = np.dot(e1, p)
    if det == 0:
        return None
    s = origin - v0
    u = np.dot(s, p) / det
    q = np.cross(s, e1)
    v = np.dot(direction, q) / det
    if u < 0 or v < 0:
        return None
    t = np.dot(e2, q) / det
    return t if t_min <= t <= t_max else None
