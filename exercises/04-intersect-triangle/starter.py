"""Ray–triangle intersection / 光线与三角形求交

Return t where the ray meets the triangle (both sides, edges included), or None.
返回光线与三角形（双面，含边）交点的 t，没有交点时返回 None。

Check it: raylab check 04-intersect-triangle starter.py
"""

import math

import numpy as np


def intersect_triangle(origin, direction, v0, v1, v2, t_min, t_max):
    # TODO: Return t where the ray meets the triangle (both sides, edges included), or None.
    # TODO：返回光线与三角形（双面，含边）交点的 t，没有交点时返回 None。
    raise NotImplementedError("intersect_triangle")
