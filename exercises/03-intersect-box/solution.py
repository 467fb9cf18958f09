"""Reference solution of 03-intersect-box (a test: it passes every case)."""

import math

import numpy as np


def intersect_box(origin, direction, box_min, box_max, t_min, t_max):
    near, far = -math.inf, math.inf
    for axis in range(3):
        if direction[axis] == 0:          # parallel to this slab: inside it or never
            if not box_min[axis] <= origin[axis] <= box_max[axis]:
                return None
            continue
        t0 = (box_min[axis] - origin[axis]) / direction[axis]
        t1 = (box_max[axis] - origin[axis]) / direction[axis]
        near, far = max(near, min(t0, t1)), min(far, max(t0, t1))
    if near > far:
        return None
    for t in (near, far):                 # entering, or leaving from inside
        if t_min <= t <= t_max:
            return float(t)
    return None
