"""Exact Fresnel reflectance / 精确的菲涅耳反射率

Return the unpolarised Fresnel reflectance (R_s + R_p) / 2; 1 on total internal reflection.
返回非偏振菲涅耳反射率 (R_s + R_p) / 2；发生全反射时返回 1。

Check it: raylab check 07-fresnel starter.py
"""

import math

import numpy as np


def fresnel(cos_i, eta):
    # TODO: Return the unpolarised Fresnel reflectance (R_s + R_p) / 2; 1 on total internal reflection.
    # TODO：返回非偏振菲涅耳反射率 (R_s + R_p) / 2；发生全反射时返回 1。
    raise NotImplementedError("fresnel")
