"""Typical bug of 10-blinn-phong: light below the surface not checked. raylab check must name it."""

import math

import numpy as np


def blinn_phong(n, v, l, shininess):
    h = (l + v) / np.linalg.norm(l + v)
    return max(0.0, float(np.dot(n, h))) ** shininess
