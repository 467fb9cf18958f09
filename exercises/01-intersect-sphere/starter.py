"""Ray–sphere intersection / 光线与球求交

Return the nearest t in [t_min, t_max] where the ray meets the sphere, or None.
返回 [t_min, t_max] 内光线与球面交点的最小 t，没有交点时返回 None。

Check it: raylab check 01-intersect-sphere starter.py
"""

import math

import numpy as np


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    # TODO: Return the nearest t in [t_min, t_max] where the ray meets the sphere, or None.
    # TODO：返回 [t_min, t_max] 内光线与球面交点的最小 t，没有交点时返回 None。
    raise NotImplementedError("intersect_sphere")
