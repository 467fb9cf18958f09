"""Reference solution of 09-lambert (a test: it passes every case)."""

import math

import numpy as np


def lambert(n, l):
    return max(0.0, float(np.dot(n, l)))
