"""Ray–box intersection by slabs / 用平板法求光线与盒子的交点

Return the nearest t in [t_min, t_max] on the box's boundary (slab method), or None.
用平板法返回盒子边界上 [t_min, t_max] 内的最小 t，没有交点时返回 None。

Check it: raylab check 03-intersect-box starter.py
"""

import math

import numpy as np


def intersect_box(origin, direction, box_min, box_max, t_min, t_max):
    # TODO: Return the nearest t in [t_min, t_max] on the box's boundary (slab method), or None.
    # TODO：用平板法返回盒子边界上 [t_min, t_max] 内的最小 t，没有交点时返回 None。
    raise NotImplementedError("intersect_box")
