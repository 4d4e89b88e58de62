#!/usr/bin/env python3
"""Independent reference for derivations/energy/collar_cord_pull.yaml and tests/effects/test_cord_pull.cpp.

A collar (particle, mass m) on a smooth vertical rod; a cord from the collar over a small pulley D
at (b, h) is pulled with constant force P. Work-energy from rest at y = 0 to y = d:
    (1/2) m v2^2 = P (L1 - L2) - m g d,   L(y) = sqrt(b^2 + (h - y)^2).
The pull on the collar is P times the unit vector toward D, so its generalized force along y is
    Q_y = P (h - y) / L(y) = -d(P L)/dy.
Run: python3 tests/effects/cord_pull_reference.py   (needs sympy: Debian python3-sympy)
"""
import sympy as sp

m, P, b, h, d, g, y = sp.symbols("m P b h d g y", positive=True)
L = sp.sqrt(b**2 + (h - y) ** 2)
U = P * (L.subs(y, 0) - L.subs(y, d))
v2 = sp.sqrt(2 * (U - m * g * d) / m)
Qy = sp.simplify(P * (h - y) / L)
assert sp.simplify(Qy + sp.diff(P * L, y)) == 0

vals = {m: 3, P: 60, b: sp.Rational(2, 5), h: sp.Rational(9, 10), d: sp.Rational(3, 5), g: sp.Rational(981, 100)}
print("U_pull =", sp.N(U.subs(vals), 20), "J")
print("v2     =", sp.N(v2.subs(vals), 20), "m/s")
print("Q_y(y=0.3) =", sp.N(Qy.subs(vals).subs(y, sp.Rational(3, 10)), 20), "N")
