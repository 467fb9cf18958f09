"""Reference solution of 01-intersect-sphere (a test: it passes every case)."""

import math

import numpy as np


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)            # half of the linear coefficient (|direction| = 1)
    c = np.dot(oc, oc) - radius * radius
    disc = b * b - c                     # the discriminant, divided by 4
    if disc < 0:
        return None
    s = math.sqrt(disc)
    for t in (-b - s, -b + s):           # the nearer root first
        if t_min <= t <= t_max:
            return t
    return None
