"""Reference for tests/data/wound_spring.yaml (a numeric root, no closed form), independent of kinergy.

Energy from state 1 (theta = 0, theta_dot = w1) to state 2 (theta_dot = 0) of a slender bar
pinned at its end O, with gravity and a torsion spring k about O:
    (1/2) (m L^2/3) w1^2 = (1/2) k theta2^2 + m g (L/2) sin(theta2)
theta2 is the root near 11.93 rad (the bar wound almost two turns). mpmath at 130 digits.
"""
from mpmath import mp, mpf, sin, cos, pi, findroot

mp.dps = 130
m, L, k, g, w1 = mpf(2), mpf(1), mpf(10), mpf("9.81"), mpf(46)
f = lambda t: m * L**2 / 3 * w1**2 / 2 - k * t**2 / 2 - m * g * L / 2 * sin(t)
df = lambda t: -k * t - m * g * L / 2 * cos(t)
theta2 = findroot(f, mpf("11.9"), df=df, tol=mpf(10) ** -125)
if __name__ == "__main__":
    print(mp.nstr(theta2, 110))  # rad
    print(mp.nstr(theta2 * 180 / pi, 60))  # deg
