#!/usr/bin/python3
"""Independent check (sympy and mpmath only, no kinergy) of static friction in rolling (issue 27,
"whether mu suffices"): the friction F a rolling body needs against mu_s N.

Each case is derived from Newton-Euler for the body, written here by hand:
  a uniform disk (I = m r^2/2) rolling on a line, a = r alpha: m a = P + m g sin(beta) - F and
  I alpha = F r, so F = (I/(I + m r^2)) (P + m g sin(beta)) = (P + m g sin(beta))/3, N = m g cos(beta);
  a uniform sphere (I = 2 m r^2/5) rolling inside a circular bowl of radius R, its centre on the
  circle R - r at angle theta from the bottom: (7/5) m (R - r) theta'' = -m g sin(theta),
  F = (2/7) m g sin(theta), N = m g cos(theta) + m (R - r) theta'^2.

  1. derivations/energy/disk_pushed_static_friction.yaml: v2 from work and energy (the push's work
     integral of P0 sin(pi x/d) dx over 0..d), F and F/N at x = d/2, and the greatest F/N over
     the push, P0/(3 m g), below mu_s: proved equal to the YAML's expect forms and values.
  2. derivations/kinetics/disk_rolls_incline_friction.yaml: the least mu, tan(beta)/3, below its
     mu_s.
  3. The cases of tests/kinetics/test_static_friction.cpp where the rolling fails, with the numbers
     that test asserts:
     a. the disk of case 2 with mu_s = 0.1 slips at release: F - mu_s N = m g (sin(beta)/3 - 0.1 cos(beta));
     b. the disk of case 1 with P0 = 60 N slips where P/(3 m g) = 0.2: x, and the time from
        t = integral of dx / v(x);
     c. the sphere of the bowl launched at the bottom at w0 = 6 rad/s, mu_s = 0.5, slips where
        F/N = 0.5: theta, the time (integral of dtheta/theta'), F and N there.

Run (from the repository root):  /usr/bin/python3 tests/kinetics/sympy_static_friction.py
It ends with "all checks passed"; any mismatch stops it with an AssertionError.
"""
import os
import re

import mpmath as mp
import sympy as sp
import yaml
from sympy import cos, pi, sin, sqrt, tan

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
mp.mp.dps = 30


def scene(rel):
    return yaml.safe_load(open(os.path.join(ROOT, "derivations", rel)))


def matches(value, claimed):
    """Does value round to the number claimed ('3.080 m/s'), to the figures it is written with?"""
    text = str(claimed).split()[0]
    x = float(text)
    n = len(text.lstrip("-+").replace(".", "").lstrip("0"))
    e = int(mp.floor(mp.log10(abs(x))))
    return abs(float(value) - x) <= 0.5 * 10 ** (e - n + 1)


m, r, g, d, P0, v0, x, beta = sp.symbols("m r g d P0 v0 x beta", positive=True)

# ---------------------------------------------------------------- 1. the pushed disk
doc = scene("energy/disk_pushed_static_friction.yaml")
assert doc["bodies"]["disk"]["position"] == ["x", "r"], "the disk's centre at (x, r)"
P = P0 * sin(pi * x / d)
I = m * r**2 / 2
F = I / (I + m * r**2) * P           # from m a = P - F, I alpha = F r, a = r alpha
N = m * g                            # m a_y = N - m g = 0
# work and energy: (1/2)(m + I/r^2) (v2^2 - v0^2) = integral of P dx
v2 = sqrt(v0**2 + 2 * sp.integrate(P, (x, 0, d)) / (m + I / r**2))
vals = {m: 8, r: sp.Rational(15, 100), g: sp.Rational(981, 100), d: 2, P0: 40, v0: 1}
mus = sp.Rational(2, 10)
SYM = {"m": m, "r": r, "g": g, "d": d, "P0": P0, "v0": v0, "pi": pi}
exp = doc["expect"]
for name, derived in [("v2", v2), ("F3", F.subs(x, d / 2)), ("share3", (F / N).subs(x, d / 2))]:
    claimed = sp.sympify(exp[name]["form"].replace("^", "**"), locals=SYM)
    assert sp.simplify(derived - claimed) == 0, (name, derived, claimed)
    value = derived.subs(vals)
    assert matches(value, exp[name]["value"]), (name, sp.N(value), exp[name]["value"])
    print(f"1. {name} = {sp.simplify(derived)} = {sp.N(value, 15)}")
# the greatest F/N over the push: P/(3 m g) is greatest where sin = 1
ratio = sp.simplify(F / N)
greatest = sp.maximum(ratio.subs(vals), x, sp.Interval(0, 2))
assert greatest == (P0 / (3 * m * g)).subs(vals) and greatest < mus
print(f"1. greatest F/N = {ratio.subs(x, d/2)} = {sp.N(greatest, 15)} < mu_s = {mus}")

# ---------------------------------------------------------------- 2. the disk on the incline
doc = scene("kinetics/disk_rolls_incline_friction.yaml")
least = sp.simplify((m * g * sin(beta) / 3) / (m * g * cos(beta)))
assert sp.simplify(least - tan(beta) / 3) == 0
mus_incline = sp.sympify(str(doc["parameters"]["mus"]))
assert least.subs(beta, pi / 9) < mus_incline
print(f"2. least mu = {least} = {sp.N(least.subs(beta, pi / 9), 15)} < mu_s = {mus_incline}")

# ---------------------------------------------------------------- 3. where it slips
# a. mu_s = 0.1 at release: short by F - mu_s N
short = (8 * sp.Rational(981, 100) * (sin(pi / 9) / 3 - sp.Rational(1, 10) * cos(pi / 9)))
print(f"3a. short by {sp.N(short, 15)} N, needs {sp.N(tan(pi / 9) / 3, 15)}")
assert abs(sp.N(short) - 1.57254) < 5e-6

# b. the push with P0 = 60 N, mu_s = 0.2: P0 sin(pi x/d)/(3 m g) = 0.2
mg = 8 * mp.mpf("9.81")
xs = 2 / mp.pi * mp.asin(mp.mpf("0.2") * 3 * mg / 60)
v = lambda s: mp.sqrt(1 + 2 * (60 * 2 / mp.pi) * (1 - mp.cos(mp.pi * s / 2)) / (mp.mpf(3) / 2 * 8))
ts = mp.quad(lambda s: 1 / v(s), [0, xs])
print(f"3b. slips at x = {mp.nstr(xs, 12)} m, t = {mp.nstr(ts, 12)} s, F = {mp.nstr(0.2 * mg, 12)} N")
assert abs(ts - mp.mpf("0.449859")) < 5e-6

# c. the sphere in the bowl: m = 2, r = 0.1, R = 0.5, w0 = 6, mu_s = 0.5
mb, L, w0 = 2, mp.mpf("0.4"), 6
g_ = mp.mpf("9.81")
rate = lambda th: mp.sqrt(w0**2 - 10 * g_ * (1 - mp.cos(th)) / (7 * L))  # (7/10) m L^2 w^2 + m g L (1 - cos) conserved
Fb = lambda th: 2 * mb * g_ * mp.sin(th) / 7
Nb = lambda th: mb * g_ * mp.cos(th) + mb * L * rate(th) ** 2
th = mp.findroot(lambda th: Fb(th) / Nb(th) - mp.mpf("0.5"), (1.2, 1.45), solver="anderson")
tb = mp.quad(lambda s: 1 / rate(s), [0, th])
print(f"3c. slips at theta = {mp.nstr(th, 12)}, t = {mp.nstr(tb, 12)} s, F = {mp.nstr(Fb(th), 12)} N, N = {mp.nstr(Nb(th), 12)} N")
assert abs(tb - mp.mpf("0.279195")) < 5e-6 and abs(Fb(th) - mp.mpf("5.47626")) < 5e-5 and abs(Nb(th) - mp.mpf("10.9525")) < 5e-4

print("all checks passed")
