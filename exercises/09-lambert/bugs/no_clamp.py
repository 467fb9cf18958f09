"""Typical bug of 09-lambert: negative cosine not clamped. raylab check must name it."""

import math

import numpy as np


def lambert(n, l):
    return float(np.dot(n, l))
