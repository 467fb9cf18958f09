"""Typical bug of 10-blinn-phong: half vector not normalised. raylab check must name it."""

import math

import numpy as np


def blinn_phong(n, v, l, shininess):
    if np.dot(n, l) <= 0:
        return 0.0
    h = l + v
    return max(0.0, float(np.dot(n, h))) ** shininess
