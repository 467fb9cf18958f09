"""Typical bug of 06-refract: total internal reflection not handled. raylab check must name it."""

import math

import numpy as np


def refract(d, n, eta):
    cos_i = -np.dot(d, n)
    k = 1 - eta * eta * (1 - cos_i * cos_i)
    return eta * d + (eta * cos_i - np.sqrt(k)) * n
