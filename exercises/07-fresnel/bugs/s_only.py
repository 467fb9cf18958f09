"""Typical bug of 07-fresnel: only R_s (one polarisation). raylab check must name it."""

import math

import numpy as np


def fresnel(cos_i, eta):
    cos_i = abs(cos_i)
    sin2_t = eta * eta * (1 - cos_i * cos_i)
    if sin2_t >= 1:
        return 1.0
    cos_t = math.sqrt(1 - sin2_t)
    r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    return r_s * r_s
