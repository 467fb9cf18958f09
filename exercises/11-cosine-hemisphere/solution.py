"""Reference solution of 11-cosine-hemisphere (a test: it passes every case)."""

import math

import numpy as np


def sample_cosine_hemisphere(u1, u2):
    r, phi = math.sqrt(u1), 2 * math.pi * u2   # a uniform point of the unit disk ...
    x, y = r * math.cos(phi), r * math.sin(phi)
    z = math.sqrt(max(0.0, 1 - u1))          # ... lifted onto the hemisphere (Malley)
    return np.array([x, y, z]), z / math.pi
