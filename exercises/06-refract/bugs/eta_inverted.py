"""Typical bug of 06-refract: eta inverted (eta_t / eta_i). raylab check must name it."""

import math

import numpy as np


def refract(d, n, eta):
    eta = 1 / eta
    cos_i = -np.dot(d, n)
    k = 1 - eta * eta * (1 - cos_i * cos_i)
    if k < 0:
        return None
    return eta * d + (eta * cos_i - math.sqrt(k)) * n
