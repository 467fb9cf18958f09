"""Reference solution of 12-spawn-offset (a test: it passes every case)."""

import math

import numpy as np


def spawn_offset(p, n, d):
    scale = max(1.0, float(np.max(np.abs(p))))   # the rounding grows with |p|
    side = 1.0 if np.dot(d, n) > 0 else -1.0
    return p + side * 1e-7 * scale * n
