"""Typical bug of 02-intersect-plane: parallel ray not handled. raylab check must name it."""

import math

import numpy as np


def intersect_plane(origin, direction, point, normal, t_min, t_max):
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.dot(point - origin, normal) / np.dot(direction, normal)
    return float(t) if t >= t_min or not np.isfinite(t) else None
