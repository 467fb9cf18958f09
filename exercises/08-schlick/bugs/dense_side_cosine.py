"""Typical bug of 08-schlick: cosine taken on the denser side. raylab check must name it."""

import math

import numpy as np


def schlick(cos_i, eta):
    cos_i = abs(cos_i)
    r0 = ((eta - 1) / (eta + 1)) ** 2
    return r0 + (1 - r0) * (1 - cos_i) ** 5
