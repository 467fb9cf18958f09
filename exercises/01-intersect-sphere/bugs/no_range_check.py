"""Typical bug of 01-intersect-sphere: hits behind the origin (t_min ignored). raylab check must name it."""

import math

import numpy as np


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    return -b - math.sqrt(disc)
