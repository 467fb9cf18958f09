"""The secondary ray's offset / 次级光线的起点偏移

Return the new ray's origin: p moved off the surface to the side d goes to.
返回新光线的起点：把 p 沿法线移到 d 所在的一侧。

Check it: raylab check 12-spawn-offset starter.py
"""

import math

import numpy as np


def spawn_offset(p, n, d):
    # TODO: Return the new ray's origin: p moved off the surface to the side d goes to.
    # TODO：返回新光线的起点：把 p 沿法线移到 d 所在的一侧。
    raise NotImplementedError("spawn_offset")
