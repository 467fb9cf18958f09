"""Typical bug of 03-intersect-box: a ray from inside the box misses it. raylab check must name it."""

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
        near, far = max(near, min(t0, t1)), min(far, max(t0, t1))
    if near > far or not t_min <= near <= t_max:
        return None
    return float(near)
