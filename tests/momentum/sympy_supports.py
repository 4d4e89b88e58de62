#!/usr/bin/python3
"""Independent check (sympy only, no kinergy) of moments of a system whose supports cancel
(issue 27, item 5): derivations/momentum/drum_blocks_on_table.yaml and
derivations/momentum/drum_climbs_cable.yaml.

Neither uses angular momentum: each body is isolated with its cord tensions as unknowns and
Newton-Euler written for it; the accelerations are constant, so the rates after t1 from rest
are the accelerations times t1. Each closed form is proved equal to the YAML's expect form, each
value matched to the figures the YAML writes.

drum_blocks_on_table: a drum (M, r, I = M r^2/2) on a fixed axle O; block A hangs from a cord
leaving the drum's right side (x = r), block B slides on a level table (kinetic friction mu,
normal force mB g) tied by a horizontal cord leaving the top of the drum (y = r). phi is the
drum's angle (counter-clockwise), yA = r phi - a, xB = -r phi - b (B on the left).
    A:     mA yA'' = TA - mA g
    B:     mB xB'' = TB - mu mB g       (B slides to +x: friction along -x)
    drum:  I phi'' = -r TA + r TB        (TA down at (r, 0), TB along -x at (0, r))

drum_climbs_cable: a drum (m, r, I = m k^2) hangs from a vertical cable wound on it, the cable's
upper end fixed and leaving the drum at its left (x = -r); a couple Mc turns it. y = r phi.
    drum:  m y'' = T - m g,   I phi'' = Mc - r T   (T up at (-r, y): moment (-r)(T) about G)

Run (from the repository root):  /usr/bin/python3 tests/momentum/sympy_supports.py
"""
import os

import sympy as sp

from yaml_claims import expect_entries, parameter_values

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def compare(scene, derived, local):
    text = open(os.path.join(ROOT, "derivations", "momentum", scene)).read()
    expect = expect_entries(text)
    vals = parameter_values(text)
    assert set(expect) == set(derived), (scene, sorted(expect), sorted(derived))
    for name, closed in derived.items():
        form, value = expect[name]
        claimed = sp.sympify(form, locals=local)
        assert sp.simplify(closed - claimed) == 0, (scene, name, closed, claimed)
        number = float(closed.subs(vals))
        literal = value.split()[0]
        # the YAML's figures: the value rounded to its last written decimal place
        places = len(literal.split(".")[1]) if "." in literal else 0
        assert abs(number - float(literal)) <= 0.5 * 10**-places * (1 + 1e-12), (scene, name, number, literal)
        print(f"{scene}: {name:7s} = {closed}  = {number:.15g}  (YAML: {form}, {value})")


def drum_blocks_on_table():
    M, r, mA, mB, mu, g, t1 = sp.symbols("M r mA mB mu g t1", positive=True)
    TA, TB, alpha = sp.symbols("TA TB alpha")
    I = M * r**2 / 2
    eqs = [
        sp.Eq(mA * r * alpha, TA - mA * g),          # yA'' = r phi''
        sp.Eq(mB * (-r * alpha), TB - mu * mB * g),  # xB'' = -r phi''
        sp.Eq(I * alpha, -r * TA + r * TB),
    ]
    sol = sp.solve(eqs, [TA, TB, alpha], dict=True)[0]
    omega2 = sp.simplify(sol[alpha] * t1)
    # B slides to +x over the interval (the friction's sense): xB' = -r phi' > 0
    assert sp.simplify(-r * omega2).subs({mA: 5, mB: 4, mu: sp.Rational(1, 5), g: 9.81, r: 1, M: 8, t1: 2}) > 0
    derived = {"omega2": omega2, "vB2": sp.simplify(-r * omega2)}
    compare("drum_blocks_on_table.yaml", derived, {"M": M, "r": r, "mA": mA, "mB": mB, "mu": mu, "g": g, "t1": t1})


def drum_climbs_cable():
    m, r, k, Mc, g, t1 = sp.symbols("m r k Mc g t1", positive=True)
    T, alpha = sp.symbols("T alpha")
    I = m * k**2
    eqs = [sp.Eq(m * r * alpha, T - m * g), sp.Eq(I * alpha, Mc - r * T)]
    sol = sp.solve(eqs, [T, alpha], dict=True)[0]
    omega2 = sp.simplify(sol[alpha] * t1)
    derived = {"omega2": omega2, "v2": sp.simplify(r * omega2), "T": sp.simplify(sol[T])}
    compare("drum_climbs_cable.yaml", derived, {"m": m, "r": r, "k": k, "Mc": Mc, "g": g, "t1": t1})


def main():
    drum_blocks_on_table()
    drum_climbs_cable()
    print("all checks passed")


if __name__ == "__main__":
    main()
