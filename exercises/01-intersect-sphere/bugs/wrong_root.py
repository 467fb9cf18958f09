"""Typical bug of 01-intersect-sphere: wrong root chosen. raylab check must name it."""

import math

import numpy as np


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    t = -b + math.sqrt(disc)
    return t if t_min <= t <= t_max else None
