"""Reference solution of 05-reflect (a test: it passes every case)."""

import math

import numpy as np


def reflect(d, n):
    return d - 2 * np.dot(d, n) * n
