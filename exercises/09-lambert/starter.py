"""Lambert's cosine law / 朗伯余弦定律

Return Lambert's factor max(0, n . l).
返回朗伯余弦项 max(0, n·l)。

Check it: raylab check 09-lambert starter.py
"""

import math

import numpy as np


def lambert(n, l):
    # TODO: Return Lambert's factor max(0, n . l).
    # TODO：返回朗伯余弦项 max(0, n·l)。
    raise NotImplementedError("lambert")
