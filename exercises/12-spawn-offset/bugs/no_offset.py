"""Typical bug of 12-spawn-offset: no offset (shadow acne). raylab check must name it."""

import math

import numpy as np


def spawn_offset(p, n, d):
    return p
