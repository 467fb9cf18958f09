"""Typical bug of 12-spawn-offset: a fixed epsilon too small far from the origin. raylab check must name it."""

import math

import numpy as np


def spawn_offset(p, n, d):
    side = 1.0 if np.dot(d, n) > 0 else -1.0
    return p + side * 1e-9 * n
