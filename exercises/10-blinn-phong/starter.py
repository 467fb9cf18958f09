"""The Blinn-Phong highlight / Blinn-Phong 高光

Return (N . H)^shininess with H = (L + V) / |L + V|; 0 when N . L <= 0.
返回 (N·H)^shininess，H = (L + V) / |L + V|；N·L ≤ 0 时返回 0。

Check it: raylab check 10-blinn-phong starter.py
"""

import math

import numpy as np


def blinn_phong(n, v, l, shininess):
    # TODO: Return (N . H)^shininess with H = (L + V) / |L + V|; 0 when N . L <= 0.
    # TODO：返回 (N·H)^shininess，H = (L + V) / |L + V|；N·L ≤ 0 时返回 0。
    raise NotImplementedError("blinn_phong")
