"""Mirror reflection / 镜面反射

Return the mirror direction of the incident direction d about the unit normal n.
返回入射方向 d 关于单位法线 n 的镜面反射方向。

Check it: raylab check 05-reflect starter.py
"""

import math

import numpy as np


def reflect(d, n):
    # TODO: Return the mirror direction of the incident direction d about the unit normal n.
    # TODO：返回入射方向 d 关于单位法线 n 的镜面反射方向。
    raise NotImplementedError("reflect")
