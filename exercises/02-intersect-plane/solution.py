"""Reference solution of 02-intersect-plane (a test: it passes every case)."""

import math

import numpy as np


def intersect_plane(origin, direction, point, normal, t_min, t_max):
    denom = np.dot(direction, normal)
    if denom == 0:                        # parallel: no crossing
        return None
    t = np.dot(point - origin, normal) / denom
    return t if t_min <= t <= t_max else None
