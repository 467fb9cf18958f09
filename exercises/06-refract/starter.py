"""Refraction and total internal reflection / 折射与全反射

Return the refracted direction (Snell's law, eta = eta_i / eta_t), or None on total internal reflection.
按斯涅尔定律返回折射方向（eta = η_i / η_t），发生全反射时返回 None。

Check it: raylab check 06-refract starter.py
"""

import math

import numpy as np


def refract(d, n, eta):
    # TODO: Return the refracted direction (Snell's law, eta = eta_i / eta_t), or None on total internal reflection.
    # TODO：按斯涅尔定律返回折射方向（eta = η_i / η_t），发生全反射时返回 None。
    raise NotImplementedError("refract")
