"""Typical bug of 01-intersect-sphere: missing normalisation (a = |d|^2 dropped, b not halved). raylab check must name it."""

import math

import numpy as np


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = 2 * np.dot(oc, direction)
    disc = b * b - 4 * (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    for t in (-b - math.sqrt(disc), -b + math.sqrt(disc)):
        if t_min <= t <= t_max:
            return t
    return None
