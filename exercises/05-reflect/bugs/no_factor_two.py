"""Typical bug of 05-reflect: factor 2 missing. raylab check must name it."""

import math

import numpy as np


def reflect(d, n):
    return d - np.dot(d, n) * n
