"""Schlick's approximation / Schlick 近似

Return Schlick's R0 + (1 - R0)(1 - cos)^5, the cosine on the less dense side; 1 on total internal reflection.
返回 Schlick 近似 R0 + (1 − R0)(1 − cosθ)^5，余弦取光疏介质一侧；全反射时返回 1。

Check it: raylab check 08-schlick starter.py
"""

import math

import numpy as np


def schlick(cos_i, eta):
    # TODO: Return Schlick's R0 + (1 - R0)(1 - cos)^5, the cosine on the less dense side; 1 on total internal reflection.
    # TODO：返回 Schlick 近似 R0 + (1 − R0)(1 − cosθ)^5，余弦取光疏介质一侧；全反射时返回 1。
    raise NotImplementedError("schlick")
