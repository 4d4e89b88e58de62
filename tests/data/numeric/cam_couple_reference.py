"""References for derivations/energy/wheel_cam_couple_numeric.yaml and wheel_cam_couple_angle.yaml
(a work integral with no elementary antiderivative), independent of kinergy.

A wheel (m = 20 kg, radius of gyration k = 0.25 m) on a fixed axle, turned from rest at phi = 0 by
the couple M = M0 exp(-(phi/phi0)^2), M0 = 40 N*m, phi0 = 0.8 rad. Its work to phi is
    U(phi) = M0 phi0 (sqrt(pi)/2) erf(phi/phi0),
and (1/2) m k^2 omega^2 = U gives
    omega2 = sqrt(2 U(phi2)/(m k^2))               at phi2 = 1.5 rad (numeric),
    phi2   = phi0 erfinv(w2^2 m k^2/(2 M0 phi0 sqrt(pi)/2))  at w2 = 6 rad/s (angle).
Also the integrals of tests/numeric/test_proven.cpp ("ball arithmetic: integrals"), by mpmath's
quad and closed forms. mpmath at 130 digits.
"""
from mpmath import mp, mpf, sqrt, pi, erf, erfinv, quad, exp, log, atan, asin

mp.dps = 130
m, k, M0, phi0 = mpf(20), mpf("0.25"), mpf(40), mpf("0.8")
U = lambda phi: M0 * phi0 * sqrt(pi) / 2 * erf(phi / phi0)
omega2 = sqrt(2 * U(mpf("1.5")) / (m * k**2))
w2 = mpf(6)
phi2 = phi0 * erfinv(w2**2 * m * k**2 / 2 / (M0 * phi0 * sqrt(pi) / 2))
if __name__ == "__main__":
    print(mp.nstr(omega2, 110))  # rad/s
    print(mp.nstr(phi2, 110))  # rad
    # ∫_0^1 exp(-x^2) dx = sqrt(pi)/2 erf(1)
    print(mp.nstr(sqrt(pi) / 2 * erf(1), 60))
    # ∫_0^2 sqrt(x) atan(x) dx, ∫_{1/2}^{3/2} asin(x/2) / (1 + x) dx, ∫_1^3 log(x) x^(1/3) dx (quad)
    print(mp.nstr(quad(lambda x: sqrt(x) * atan(x), [0, 2]), 60))
    print(mp.nstr(quad(lambda x: asin(x / 2) / (1 + x), [mpf(1) / 2, mpf(3) / 2]), 60))
    print(mp.nstr(quad(lambda x: log(x) * x ** (mpf(1) / 3), [1, 3]), 60))
