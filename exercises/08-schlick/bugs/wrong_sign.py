"""Typical bug of 08-schlick: Schlick with the wrong sign ((1 + cos)^5). raylab check must name it."""

import math

import numpy as np


def schlick(cos_i, eta):
    cos_i = abs(cos_i)
    r0 = ((eta - 1) / (eta + 1)) ** 2
    cos = cos_i
    if eta > 1:
        sin2_t = eta * eta * (1 - cos_i * cos_i)
        if sin2_t >= 1:
            return 1.0
        cos = math.sqrt(1 - sin2_t)
    return r0 + (1 - r0) * (1 + cos) ** 5
