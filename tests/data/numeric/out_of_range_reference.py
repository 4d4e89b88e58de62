#!/usr/bin/env python3
"""Independent references (mpmath, 60 digits) for tests/data/numeric/out_of_range.yaml.
Run: python3 tests/data/numeric/out_of_range_reference.py"""
import mpmath

mpmath.mp.dps = 200  # c = 1e80 has 81 integer digits: reduce it modulo 2*pi with room to spare
c = mpmath.mpf(10) ** 80
print("tiny  =", mpmath.nstr(-2 * mpmath.exp(-1000000), 30))
print("sin_c =", mpmath.nstr(mpmath.sin(c), 30))
print("cos_c =", mpmath.nstr(mpmath.cos(c), 30))
print("small =", mpmath.nstr(mpmath.mpf("1e-400") * mpmath.cos(3), 30))
# tests/data/numeric/big_angle.yaml: omega2 = sqrt(3 (g - g cos(theta0)) / L), theta0 = 1e300 deg
with mpmath.workdps(600):  # the angle's 300 integer digits, and 300 more
    th = mpmath.mpf(10) ** 300 * mpmath.pi / 180
    g, L = mpmath.mpf("9.81"), mpmath.mpf("0.9")
    print("omega2 =", mpmath.nstr(mpmath.sqrt(3 * (g - g * mpmath.cos(th)) / L), 30))
