"""Typical bug of 09-lambert: missing cos theta. raylab check must name it."""

import math

import numpy as np


def lambert(n, l):
    return 1.0
