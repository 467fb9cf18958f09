"""Typical bug of 12-spawn-offset: offset always along +n (refraction offset the wrong way). raylab check must name it."""

import math

import numpy as np


def spawn_offset(p, n, d):
    return p + 1e-4 * n
