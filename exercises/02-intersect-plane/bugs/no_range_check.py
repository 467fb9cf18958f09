"""Typical bug of 02-intersect-plane: hits behind the origin (t_min ignored). raylab check must name it."""

import math

import numpy as np


def intersect_plane(origin, direction, point, normal, t_min, t_max):
    denom = np.dot(direction, normal)
    if denom == 0:
        return None
    return np.dot(point - origin, normal) / denom
