"""Typical bug of 11-cosine-hemisphere: pdf forgotten (returned 1). raylab check must name it."""

import math

import numpy as np


def sample_cosine_hemisphere(u1, u2):
    r, phi = math.sqrt(u1), 2 * math.pi * u2
    z = math.sqrt(max(0.0, 1 - u1))
    return np.array([r * math.cos(phi), r * math.sin(phi), z]), 1.0
