"""Typical bug of 11-cosine-hemisphere: uniform directions, not cosine-weighted. raylab check must name it."""

import math

import numpy as np


def sample_cosine_hemisphere(u1, u2):
    z, phi = u1, 2 * math.pi * u2
    r = math.sqrt(max(0.0, 1 - z * z))
    return np.array([r * math.cos(phi), r * math.sin(phi), z]), z / math.pi
