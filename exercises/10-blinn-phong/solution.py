"""Reference solution of 10-blinn-phong (a test: it passes every case)."""

import math

import numpy as np


def blinn_phong(n, v, l, shininess):
    if np.dot(n, l) <= 0:
        return 0.0
    h = (l + v) / np.linalg.norm(l + v)   # the half vector
    return max(0.0, float(np.dot(n, h))) ** shininess
