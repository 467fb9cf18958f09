"""Typical bug of 03-intersect-box: slabs not swapped for negative directions. raylab check must name it."""

import math

import numpy as np


def intersect_box(origin, direction, box_min, box_max, t_min, t_max):
    near, far = -math.inf, math.inf
    for axis in range(3):
        if direction[axis] == 0:
            if not box_min[axis] <= origin[axis] <= box_max[axis]:
                return None
            continue
        t0 = (box_min[axis] - origin[axis]) / direction[axis]
        t1 = (box_max[axis] - origin[axis]) / direction[axis]
        near, far = max(near, t0), min(far, t1)
    if near > far:
        return None
    for t in (near, far):
        if t_min <= t <= t_max:
            return float(t)
    return None
