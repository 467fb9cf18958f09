"""Ray–plane intersection / 光线与平面求交

Return t where the ray crosses the plane through `point` with unit `normal`, or None.
返回光线与过 point、单位法线为 normal 的平面的交点 t，没有交点时返回 None。

Check it: raylab check 02-intersect-plane starter.py
"""

import math

import numpy as np


def intersect_plane(origin, direction, point, normal, t_min, t_max):
    # TODO: Return t where the ray crosses the plane through `point` with unit `normal`, or None.
    # TODO：返回光线与过 point、单位法线为 normal 的平面的交点 t，没有交点时返回 None。
    raise NotImplementedError("intersect_plane")
