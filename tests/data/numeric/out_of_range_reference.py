#!/usr/bin/env python3
"""Independent references (mpmath, 60 digits) for tests/data/numeric/out_of_range.yaml.
Run: python3 tests/data/numeric/out_of_range_reference.py"""
import mpmath

mpmath.mp.dps = 200  # c = 1e80 has 81 integer digits: reduce it modulo 2*pi with room to spare
c = mpmath.mpf(10) ** 80
print("tiny  =", mpmath.nstr(-2 * mpmath.exp(-1000000), 30))
print("sin_c =", mpmath.nstr(mpmath.sin(c), 30))
print("cos_c =", mpmath.nstr(mpmath.cos(c), 30))
