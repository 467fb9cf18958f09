"""Reference solution of 06-refract (a test: it passes every case)."""

import math

import numpy as np


def refract(d, n, eta):
    cos_i = -np.dot(d, n)                   # n faces against d
    k = 1 - eta * eta * (1 - cos_i * cos_i)  # cos^2 of the transmitted angle
    if k < 0:                               # total internal reflection
        return None
    return eta * d + (eta * cos_i - math.sqrt(k)) * n
