"""Typical bug of 05-reflect: normal's sign flipped (d + 2(d.n)n). raylab check must name it."""

import math

import numpy as np


def reflect(d, n):
    return d + 2 * np.dot(d, n) * n
