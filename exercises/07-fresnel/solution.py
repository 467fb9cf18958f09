"""Reference solution of 07-fresnel (a test: it passes every case)."""

import math

import numpy as np


def fresnel(cos_i, eta):
    cos_i = abs(cos_i)
    sin2_t = eta * eta * (1 - cos_i * cos_i)
    if sin2_t >= 1:                        # total internal reflection
        return 1.0
    cos_t = math.sqrt(1 - sin2_t)
    r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    return 0.5 * (r_s * r_s + r_p * r_p)
