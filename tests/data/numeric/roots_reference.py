"""References for values that hold numbers found numerically, independent of kinergy (mpmath at
80 digits): tests/numeric/test_proven.cpp.

tests/data/numeric/rod_power_spring.yaml: a slender rod (m = 3 kg, L = 1.2 m) pinned at its end O,
released from rest horizontal, with gravity and a torsion spring k = 5 N*m/rad about O. At the
angle th below the horizontal, energy gives
    (1/2)(m L^2/3) w^2 = m g (L/2) sin th - (1/2) k th^2,
and gravity's power is P(th) = m g (L/2) cos th * w. th* solves dP/dth = 0; Pmax = P(th*).

tests/data/wound_spring.yaml with h2 = (L/2) sin(theta2): the height of G where the bar stops
(theta2 from wound_spring_reference.py).

tests/data/numeric/wound_spring_chained.yaml: from state 2 (theta2, at rest) to state 3 where the
bar turns back at w3 = -20 rad/s: (1/2)(m L^2/3) w3^2 + (1/2) k theta3^2 + m g (L/2) sin theta3 =
(1/2) k theta2^2 + m g (L/2) sin theta2, theta3 the root near 10.79 rad.
"""
import os
import sys

from mpmath import mp, mpf, sin, cos, sqrt, findroot, diff, pi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wound_spring_reference import theta2  # noqa: E402

mp.dps = 80
m, L, g, k = mpf(3), mpf("1.2"), mpf("9.81"), mpf(5)
w = lambda th: sqrt((m * g * L / 2 * sin(th) - k * th**2 / 2) / (m * L**2 / 6))
P = lambda th: m * g * L / 2 * cos(th) * w(th)
th_star = findroot(lambda t: diff(P, t), mpf("0.585"))
mw, Lw, kw, gw, w3 = mpf(2), mpf(1), mpf(10), mpf("9.81"), mpf(-20)
E2 = kw * theta2**2 / 2 + mw * gw * Lw / 2 * sin(theta2)
theta3 = findroot(lambda t: mw * Lw**2 / 3 * w3**2 / 2 + kw * t**2 / 2 + mw * gw * Lw / 2 * sin(t) - E2, mpf("10.78"))
if __name__ == "__main__":
    print(mp.nstr(th_star * 180 / pi, 60))  # deg
    print(mp.nstr(P(th_star), 60))  # W
    print(mp.nstr(sin(theta2) / 2, 60))  # h2, m (L = 1 m)
    print(mp.nstr(theta3, 60))  # rad
