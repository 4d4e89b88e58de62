#!/usr/bin/python3
"""Independent check (sympy only, no kinergy) of positions over a duration (issue 27, item 6):
derivations/momentum/disk_spun_on_floor_distance.yaml.

A uniform disk (m, r, I = m r^2/2) spun at omega0 clockwise is set down without forward speed on a
floor with kinetic friction mu_k. While it slides, Newton's second law with the friction force
mu_k m g forward at the contact (it opposes the contact point's backward slip):
    m x'' = mu_k m g,     I phi'' = mu_k m g r      (moments about the centre, counter-clockwise)
The script solves these differential equations with sympy's dsolve from x(0) = 0, x'(0) = 0,
phi(0) = 0, phi'(0) = -omega0 (no impulse-momentum in it), finds the time the contact point stops
slipping (x' + r phi' = 0), and evaluates x, x' and phi there. Each closed form is proved equal
to the YAML's expect form, each value matched to the figures the YAML writes.

Run (from the repository root):  /usr/bin/python3 tests/momentum/sympy_positions.py
"""
import os

import sympy as sp

from yaml_claims import expect_entries, parameter_values

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCENE = os.path.join(ROOT, "derivations", "momentum", "disk_spun_on_floor_distance.yaml")

m, r, omega0, mu_k, g = sp.symbols("m r omega0 mu_k g", positive=True)
t = sp.symbols("t", nonnegative=True)
x, phi = sp.Function("x"), sp.Function("phi")


def main():
    text = open(SCENE).read()
    I = m * r**2 / 2
    # Newton's second law while sliding, from rest forward and spinning clockwise
    sx = sp.dsolve(sp.Eq(m * x(t).diff(t, 2), mu_k * m * g), x(t), ics={x(0): 0, x(t).diff(t).subs(t, 0): 0}).rhs
    sphi = sp.dsolve(sp.Eq(I * phi(t).diff(t, 2), mu_k * m * g * r), phi(t),
                     ics={phi(0): 0, phi(t).diff(t).subs(t, 0): -omega0}).rhs
    # rolling begins when the contact point stops slipping: x' + r phi' = 0
    slip = sp.simplify(sx.diff(t) + r * sphi.diff(t))
    (t2,) = sp.solve(sp.Eq(slip, 0), t)
    derived = {
        "t2": sp.simplify(t2),
        "v2": sp.simplify(sx.diff(t).subs(t, t2)),
        "d": sp.simplify(sx.subs(t, t2)),
        "turned": sp.simplify(sphi.subs(t, t2)),
    }
    # the slip keeps its sign before t2 (so the friction force is constant over the interval)
    assert sp.simplify(slip.subs(t, t2 / 2)) < 0
    expect = expect_entries(text)
    vals = parameter_values(text)
    local = {"m": m, "r": r, "omega0": omega0, "mu_k": mu_k, "g": g}
    assert set(expect) == set(derived), (sorted(expect), sorted(derived))
    for name, closed in derived.items():
        form, value = expect[name]
        claimed = sp.sympify(form, locals=local)
        assert sp.simplify(closed - claimed) == 0, (name, closed, claimed)
        number = float(closed.subs(vals))
        literal = value.split()[0]
        # the YAML's figures: the value rounded to its last written decimal place
        places = len(literal.split(".")[1]) if "." in literal else 0
        assert abs(number - float(literal)) <= 0.5 * 10**-places * (1 + 1e-12), (name, number, literal)
        print(f"{name:7s} = {closed}  = {number:.15g}  (YAML: {form}, {value})")
    print("all checks passed")


if __name__ == "__main__":
    main()
