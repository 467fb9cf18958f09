"""Cosine-weighted hemisphere sampling / 余弦加权的半球采样

Return (direction, pdf): a direction of z > 0 with density cos(theta)/pi, and that pdf.
返回 (direction, pdf)：z > 0 半球上概率密度为 cosθ/π 的方向，以及该概率密度。

Check it: raylab check 11-cosine-hemisphere starter.py
"""

import math

import numpy as np


def sample_cosine_hemisphere(u1, u2):
    # TODO: Return (direction, pdf): a direction of z > 0 with density cos(theta)/pi, and that pdf.
    # TODO：返回 (direction, pdf)：z > 0 半球上概率密度为 cosθ/π 的方向，以及该概率密度。
    raise NotImplementedError("sample_cosine_hemisphere")
