#!/usr/bin/python3
"""Independent check (sympy only, no kinergy) of kinetics at an instant (issue 27): Newton's
second law at a state, angular accelerations and support reactions.

For each case the script derives the results from first principles -- Newton-Euler per body,
m a_G = sum of forces and Ibar alpha = sum of moments about G, the reactions unknown; the
accelerations by differentiating the positions twice in time; energy conservation where a rate is
needed -- prints each closed form (sympy-simplified) and its value to 15 significant digits, and
asserts:

  1. derivations/kinetics/bar_released_pin_reaction.yaml -- slender bar pinned at its end O, at
     release (theta = 0, at rest) and at its lowest position (theta = -pi/2, rate from energy,
     negative root): alpha, the pin's force (Rx, Ry) on the bar, omega2. Each derived closed form
     is proved equal to the YAML's expect form, each value matched to the figures the YAML writes.
  2. the same bar at theta = 30 deg, theta_dot = 2 rad/s (given; the case of
     tests/kinetics/test_kinetics.cpp): alpha, Rx, Ry against the hand formulas of that test
     (moments about O: I_O alpha = -m g L/2 cos(theta)).
  3. derivations/kinetics/disk_rolls_incline_friction.yaml -- uniform disk rolling without
     slipping down an incline from rest: a, |F|, N, mu_min against the YAML's expect.
  5. derivations/kinetics/rod_and_disk_pendulum.yaml -- a rod and a disk welded (one composite
     body in the YAML), here two bodies moving together: moments about O of both, the pin's
     force from the sum of m a, omega at the vertical from both bodies' energies.
  6. derivations/kinetics/ball_leaves_dome.yaml -- a ball sliding off a smooth dome leaves it
     where the normal force vanishes: energy and the normal equation in polar form.
  4. a regression case for the future (not yet a derivation): slender bar AB, end A sliding on a
     smooth floor y = 0, released from rest at theta0 = 60 deg (B above A). Coordinates: xA and
     the bar's angle theta from the +x axis; A = (xA, 0), G = (xA + L/2 cos(theta), L/2 sin(theta)).
     alpha, a_A, N just after release, asserted against forms by hand (alpha = -12 g/(7 L),
     a_A = -3 sqrt(3) g/7, N = 4 m g/7) and, a second way, against Lagrange's equations.

The body positions are written here by hand from the descriptions, and asserted equal to the
YAML's `position:` as a check that the same scene is solved.

Run (from the repository root):  /usr/bin/python3 tests/kinetics/sympy_kinetics.py
It prints every result and ends with "all checks passed"; any mismatch stops it with an
AssertionError.
"""
import os
import re
import sys

import sympy as sp
from sympy import Rational as Q, cos, pi, sin, sqrt

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
KINETICS = os.path.join(ROOT, "derivations", "kinetics")

t = sp.symbols("t")
m, L, g, r, beta = sp.symbols("m L g r beta", positive=True)
SYMS = {"m": m, "L": L, "g": g, "r": r, "beta": beta, "pi": pi}


# ----------------------------------------------------------------------------- helpers
def load_scene(name):
    """The scene's body positions and expect entries, from its YAML file."""
    path = os.path.join(KINETICS, name)
    text = open(path).read()
    try:
        import yaml
        doc = yaml.safe_load(text)
        expect = {k: (str(v["form"]), str(v["value"])) for k, v in doc["expect"].items()}
        positions = {b: [str(c) for c in body["position"]] for b, body in doc["bodies"].items()}
        return expect, positions
    except ImportError:  # a plain reading of the two flat blocks the script needs
        expect = {}
        for line in text.split("expect:", 1)[1].splitlines():
            mm = re.match(r"\s+(\w+): \{form: (.*), value: (.*)\}\s*$", line)
            if mm:
                expect[mm.group(1)] = (mm.group(2), mm.group(3))
        positions = {}
        for mm in re.finditer(r"\n  (\w+):\n(?:    .*\n)*?    position: \[(.*)\]", text):
            positions[mm.group(1)] = [s.strip() for s in split_top(mm.group(2))]
        return expect, positions


def split_top(s):
    """s split at the commas outside parentheses."""
    out, depth, cur = [], 0, ""
    for c in s:
        if c == "," and depth == 0:
            out.append(cur)
            cur = ""
            continue
        depth += (c == "(") - (c == ")")
        cur += c
    out.append(cur)
    return out


def to_sym(text):
    return sp.sympify(text, locals=SYMS)


def kin(expr, coords):
    """expr(q(t)) with q, q', q'' replaced by the symbols (q, q_dot, q_ddot) of coords."""
    rep = {}
    for f, (q, qd, qdd) in coords.items():
        rep[sp.Derivative(f, (t, 2))] = qdd
        rep[sp.Derivative(f, t)] = qd
    e = expr.subs(rep)
    return e.subs({f: q for f, (q, _, _) in coords.items()})


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def n15(e):
    v = sp.N(e, 15)
    return "0" if v == 0 else f"{v}"


def show(name, closed, vals, unit=""):
    closed = sp.simplify(closed)
    value = closed.subs(vals)
    if value.free_symbols:  # a form at a general state: no number
        print(f"  {name:8s} = {sp.sstr(closed)}")
    else:
        print(f"  {name:8s} = {sp.sstr(closed):40s} = {n15(value)} {unit}".rstrip())
    return closed


def sig_figs(literal):
    digits = re.sub(r"[^0-9]", "", literal).lstrip("0")
    return len(digits)


def check_claim(name, derived, expect, vals):
    """The derived closed form equals the claimed form (proved by simplification), and its value
    rounds to the claimed value at the figures the claim is written with."""
    form_text, value_text = expect[name]
    form = to_sym(form_text)
    assert sp.simplify(derived - form) == 0, f"{name}: derived {derived} != claimed form {form}"
    literal = value_text.split()[0]
    claimed = float(literal)
    v = float(sp.N(derived.subs(vals), 30))
    if claimed == 0:
        assert abs(v) < 1e-12, f"{name}: derived {v} != claimed 0"
        how = "exactly 0"
    else:
        sf = sig_figs(literal)
        rounded = float(f"{v:.{sf - 1}e}")
        assert rounded == claimed, f"{name}: derived {v} rounds to {rounded}, claimed {claimed}"
        how = f"{sf} significant figures"
    print(f"    {name}: form {form_text} proved; value {value_text} matches to {how}")


def check_positions(positions, body, mine):
    theirs = [to_sym(s) for s in positions[body]]
    for a, b in zip(mine, theirs):
        assert sp.simplify(a - b) == 0, f"{body}: position {a} != YAML's {b}"
    print(f"  position of {body} as in the YAML: ({sp.sstr(theirs[0])}, {sp.sstr(theirs[1])})")


# ----------------------------------------------------------------------------- case 1 and 2
def pinned_bar():
    """Slender bar OB pinned at O = (0, 0); theta from the x axis. Newton-Euler for the bar with
    the pin's force (Rx, Ry) on it unknown; returns alpha, Rx, Ry as functions of theta, theta_dot
    and the bar's kinetic + potential energy."""
    th_f = sp.Function("theta")(t)
    th, thd, thdd = sp.symbols("theta theta_dot theta_ddot")
    Rx, Ry = sp.symbols("R_x R_y")
    Ibar = m * L**2 / 12
    rG = [L / 2 * cos(th_f), L / 2 * sin(th_f)]
    rO = [sp.S(0), sp.S(0)]
    coords = {th_f: (th, thd, thdd)}
    aG = [kin(sp.diff(c, t, 2), coords) for c in rG]
    vG = [kin(sp.diff(c, t), coords) for c in rG]
    rGs = [kin(c, coords) for c in rG]
    arm = [rO[0] - rGs[0], rO[1] - rGs[1]]  # from G to the pin
    eqs = [sp.Eq(m * aG[0], Rx),                       # sum F_x = m a_Gx
           sp.Eq(m * aG[1], Ry - m * g),               # sum F_y = m a_Gy
           sp.Eq(Ibar * thdd, cross(arm, [Rx, Ry]))]   # sum M_G = Ibar alpha (weight acts at G)
    sol = sp.solve(eqs, [thdd, Rx, Ry], dict=True)
    assert len(sol) == 1
    s = sol[0]
    energy = sp.Rational(1, 2) * m * (vG[0]**2 + vG[1]**2) + sp.Rational(1, 2) * Ibar * thd**2 + m * g * rGs[1]
    return (th, thd), s[thdd], s[Rx], s[Ry], energy, rGs


def case1_2():
    expect, positions = load_scene("bar_released_pin_reaction.yaml")
    (th, thd), alpha, Rx, Ry, E, rG = pinned_bar()
    vals = {m: 4, L: Q(9, 10), g: Q(981, 100)}
    print("Case 1: bar_released_pin_reaction.yaml (m = 4 kg, L = 0.9 m, g = 9.81 m/s^2)")
    check_positions(positions, "bar", rG)
    print("  Newton-Euler, general state:")
    show("alpha", alpha, {}, "")
    show("Rx", Rx, {}, "")
    show("Ry", Ry, {}, "")
    # state 1: theta = 0 at rest
    s1 = {th: 0, thd: 0}
    print("  state 1 (theta = 0, theta_dot = 0):")
    alpha1 = show("alpha1", alpha.subs(s1), vals, "rad/s^2")
    Rx1 = show("Rx1", Rx.subs(s1), vals, "N")
    Ry1 = show("Ry1", Ry.subs(s1), vals, "N")
    # state 2: theta = -pi/2, theta_dot from T1 + V1 = T2 + V2, the negative root
    w = sp.symbols("omega2", real=True)
    roots = sp.solve(sp.Eq(E.subs(s1), E.subs({th: -pi / 2, thd: w})), w)
    assert len(roots) == 2
    omega2 = [x for x in roots if float(x.subs(vals)) < 0][0]
    s2 = {th: -pi / 2, thd: omega2}
    print("  state 2 (theta = -pi/2, theta_dot from energy, negative root):")
    omega2 = show("omega2", omega2, vals, "rad/s")
    alpha2 = show("alpha2", alpha.subs(s2), vals, "rad/s^2")
    Rx2 = show("Rx2", Rx.subs(s2), vals, "N")
    Ry2 = show("Ry2", Ry.subs(s2), vals, "N")
    print("  against the YAML's expect:")
    for name, d in [("alpha1", alpha1), ("Rx1", Rx1), ("Ry1", Ry1), ("omega2", omega2),
                    ("alpha2", alpha2), ("Rx2", Rx2), ("Ry2", Ry2)]:
        check_claim(name, d, expect, vals)
    assert set(expect) == {"alpha1", "Rx1", "Ry1", "omega2", "alpha2", "Rx2", "Ry2"}

    print()
    print("Case 2: the same bar at theta = 30 deg, theta_dot = 2 rad/s (given)")
    s = {th: pi / 6, thd: 2}
    a = show("alpha", alpha.subs(s), vals, "rad/s^2")
    rx = show("Rx", Rx.subs(s), vals, "N")
    ry = show("Ry", Ry.subs(s), vals, "N")
    # the hand formulas of tests/kinetics/test_kinetics.cpp: moments about O with I_O = m L^2/3,
    # a_G = (L/2)(-alpha sin - w^2 cos, alpha cos - w^2 sin), R = m a_G - W
    tt, ww = pi / 6, 2
    a_h = -3 * g / (2 * L) * cos(tt)
    rx_h = m * L / 2 * (-a_h * sin(tt) - ww**2 * cos(tt))
    ry_h = m * L / 2 * (a_h * cos(tt) - ww**2 * sin(tt)) + m * g
    for name, d, h in [("alpha", a, a_h), ("Rx", rx, rx_h), ("Ry", ry, ry_h)]:
        assert sp.simplify(d - h) == 0, f"case 2 {name}: {d} != {h}"
    print("    alpha, Rx, Ry equal the hand formulas of tests/kinetics/test_kinetics.cpp (proved)")


# ----------------------------------------------------------------------------- case 3
def case3():
    expect, positions = load_scene("disk_rolls_incline_friction.yaml")
    x_f, phi_f = sp.Function("x")(t), sp.Function("phi")(t)
    x, xd, xdd, phi, phid, phidd = sp.symbols("x x_dot x_ddot phi phi_dot phi_ddot")
    N, F = sp.symbols("N F")  # F: friction on the disk along u (down the incline), N along n
    Ibar = m * r**2 / 2
    u = [cos(beta), -sin(beta)]           # down the incline
    n = [sin(beta), cos(beta)]            # the incline's outward normal
    rG = [x_f * cos(beta) + r * sin(beta), -x_f * sin(beta) + r * cos(beta)]
    coords = {x_f: (x, xd, xdd), phi_f: (phi, phid, phidd)}
    aG = [kin(sp.diff(c, t, 2), coords) for c in rG]
    rGs = [kin(c, coords) for c in rG]
    rC = [x * cos(beta), -x * sin(beta)]  # the contact point
    arm = [rC[0] - rGs[0], rC[1] - rGs[1]]
    force = [N * n[0] + F * u[0], N * n[1] + F * u[1]]
    rolling = x_f + r * phi_f             # the constraint x + r phi = 0 at every instant
    eqs = [sp.Eq(m * aG[0], force[0]),
           sp.Eq(m * aG[1], force[1] - m * g),
           sp.Eq(Ibar * phidd, cross(arm, force)),
           sp.Eq(kin(sp.diff(rolling, t, 2), coords), 0)]
    sol = sp.solve(eqs, [xdd, phidd, N, F], dict=True)
    assert len(sol) == 1
    s = {k: sp.simplify(v) for k, v in sol[0].items()}
    vals = {m: 8, r: Q(15, 100), g: Q(981, 100), beta: pi / 9}
    print("Case 3: disk_rolls_incline_friction.yaml (m = 8 kg, r = 0.15 m, beta = 20 deg, g = 9.81)")
    check_positions(positions, "disk", rGs)
    print("  Newton-Euler (from rest; no rate enters):")
    a1 = show("a1", s[xdd], vals, "m/s^2")
    show("phi_ddot", s[phidd], vals, "rad/s^2")
    Fsigned = show("F", s[F], vals, "N  (along +x, down the incline: negative = up)")
    assert float(Fsigned.subs(vals)) < 0
    F1 = show("F1", -Fsigned, vals, "N  (|F|, up the incline)")
    N1 = show("N1", s[N], vals, "N")
    mu = show("mu_min", F1 / N1, vals, "")
    print("  against the YAML's expect:")
    for name, d in [("a1", a1), ("F1", F1), ("N1", N1), ("mu_min", mu)]:
        check_claim(name, d, expect, vals)
    assert set(expect) == {"a1", "F1", "N1", "mu_min"}


# ----------------------------------------------------------------------------- case 4
def case4():
    xA_f, th_f = sp.Function("x_A")(t), sp.Function("theta")(t)
    xA, xAd, xAdd, th, thd, thdd = sp.symbols("x_A x_A_dot x_A_ddot theta theta_dot theta_ddot")
    N = sp.symbols("N")
    Ibar = m * L**2 / 12
    rA = [xA_f, sp.S(0)]
    rG = [xA_f + L / 2 * cos(th_f), L / 2 * sin(th_f)]
    coords = {xA_f: (xA, xAd, xAdd), th_f: (th, thd, thdd)}
    aG = [kin(sp.diff(c, t, 2), coords) for c in rG]
    vG = [kin(sp.diff(c, t), coords) for c in rG]
    aA = kin(sp.diff(rA[0], t, 2), coords)
    arm = [kin(rA[0] - rG[0], coords), kin(rA[1] - rG[1], coords)]
    eqs = [sp.Eq(m * aG[0], 0),                      # smooth floor: no horizontal force
           sp.Eq(m * aG[1], N - m * g),
           sp.Eq(Ibar * thdd, cross(arm, [0, N]))]   # the floor's push at A about G
    sol = sp.solve(eqs, [xAdd, thdd, N], dict=True)
    assert len(sol) == 1
    s = {k: sp.simplify(v) for k, v in sol[0].items()}
    vals = {m: 5, L: Q(6, 5), g: Q(981, 100)}
    print("Case 4: bar AB, end A on a smooth floor, released from rest at theta0 = 60 deg")
    print("  (m = 5 kg, L = 1.2 m, g = 9.81 m/s^2; theta from the +x axis, A = (xA, 0),")
    print("   G = (xA + L/2 cos(theta), L/2 sin(theta)); B above and to the right of A)")
    print("  Newton-Euler, general state:")
    show("alpha", s[thdd], {}, "")
    show("a_A", s[xAdd], {}, "")
    show("N", s[N], {}, "")
    rel = {th: pi / 3, thd: 0}
    print("  just after release (theta = pi/3, theta_dot = 0):")
    alpha = show("alpha", s[thdd].subs(rel), vals, "rad/s^2")
    a_A = show("a_A", s[xAdd].subs(rel), vals, "m/s^2  (along +x)")
    Nr = show("N", s[N].subs(rel), vals, "N  (up, on A)")
    aGx = show("a_Gx", aG[0].subs(s).subs(rel), vals, "m/s^2")
    aGy = show("a_Gy", aG[1].subs(s).subs(rel), vals, "m/s^2")
    # forms by hand: Ibar alpha = -N L/2 cos(theta), m (L/2) cos(theta) alpha = N - m g at rest
    hand = {"alpha": (alpha, -12 * g / (7 * L)), "a_A": (a_A, -3 * sqrt(3) * g / 7),
            "N": (Nr, 4 * m * g / 7), "a_Gx": (aGx, 0), "a_Gy": (aGy, -3 * g / 7)}
    for name, (d, h) in hand.items():
        assert sp.simplify(d - h) == 0, f"case 4 {name}: {d} != {h}"
    general = {thdd: -6 * g * cos(th) / (L * (1 + 3 * cos(th)**2)), N: m * g / (1 + 3 * cos(th)**2)}
    for k, h in general.items():
        assert sp.simplify(s[k].subs(thd, 0) - h) == 0, f"case 4 at rest {k}: {s[k]} != {h}"
    assert float(Nr.subs(vals)) > 0  # A stays on the floor
    # a second way: Lagrange's equations in (xA, theta), the floor's force doing no virtual work
    T = sp.Rational(1, 2) * m * (vG[0]**2 + vG[1]**2) + sp.Rational(1, 2) * Ibar * thd**2
    V = m * g * kin(rG[1], coords)
    Lag = T - V
    back = {xA: xA_f, xAd: sp.diff(xA_f, t), th: th_f, thd: sp.diff(th_f, t)}
    Lt = Lag.subs(back)
    leqs = [kin(sp.diff(sp.diff(Lt, sp.diff(q, t)), t) - sp.diff(Lt, q), coords) for q in (xA_f, th_f)]
    lsol = sp.solve(leqs, [xAdd, thdd], dict=True)[0]
    for k in (xAdd, thdd):
        assert sp.simplify(lsol[k] - s[k]) == 0, f"case 4 Lagrange {k}: {lsol[k]} != {s[k]}"
    print("    alpha, a_A, N equal the forms by hand (-12 g/(7 L), -3 sqrt(3) g/7, 4 m g/7);")
    print("    a_Gx = 0 (G falls vertically); Lagrange's equations give the same alpha and a_A")
    print("    at every state (theta, theta_dot)")


# ----------------------------------------------------------------------------- case 5
def case5():
    """The rod and the disk as two bodies moving together (no composition formula): moments about
    O of both, sum_i (Ibar_i alpha + r_i x m_i a_i) = sum_i r_i x W_i (the weld's forces are
    internal, the pin's have no moment about O); the pin's force from sum_i m_i a_i = R + sum_i W_i;
    omega at the vertical from the two bodies' kinetic and potential energies."""
    expect, _ = load_scene("rod_and_disk_pendulum.yaml")
    m_r, m_d = sp.symbols("m_r m_d", positive=True)
    th_f = sp.Function("theta")(t)
    th, thd, thdd = sp.symbols("theta theta_dot theta_ddot")
    coords = {th_f: (th, thd, thdd)}
    parts = [(m_r, m_r * L**2 / 12, L / 2), (m_d, m_d * r**2 / 2, L + r)]  # mass, Ibar, distance from O
    Rx, Ry = sp.symbols("Rx Ry")
    vals = {m_r: 3, m_d: 5, L: Q(8, 10), r: Q(2, 10), g: Q(981, 100)}
    print("Case 5: rod_and_disk_pendulum.yaml (m_r = 3 kg, m_d = 5 kg, L = 0.8 m, r = 0.2 m, g = 9.81)")

    def newton_euler(state):
        moment_lhs, moment_rhs, sum_ma = 0, 0, [0, 0]
        for mass, Ib, dist in parts:
            rG = [dist * cos(th_f), dist * sin(th_f)]
            aG = [kin(sp.diff(c, t, 2), coords) for c in rG]
            rGs = [kin(c, coords) for c in rG]
            moment_lhs += Ib * thdd + cross(rGs, [mass * aG[0], mass * aG[1]])
            moment_rhs += cross(rGs, [0, -mass * g])
            sum_ma = [sum_ma[0] + mass * aG[0], sum_ma[1] + mass * aG[1]]
        eqs = [sp.Eq(moment_lhs, moment_rhs), sp.Eq(sum_ma[0], Rx), sp.Eq(sum_ma[1], Ry - (m_r + m_d) * g)]
        eqs = [e.subs(state) for e in eqs]
        sol = sp.solve(eqs, [thdd, Rx, Ry], dict=True)
        assert len(sol) == 1
        return {k: sp.simplify(v) for k, v in sol[0].items()}

    s1 = newton_euler({th: 0, thd: 0})
    # energy from theta = 0 at rest to theta = -pi/2: sum (m v^2 + Ibar w^2)/2 = -sum m g dy
    w = sp.symbols("w")
    T = sum((mass * dist**2 + Ib) * w**2 / 2 for mass, Ib, dist in parts)
    drop = sum(mass * g * dist for mass, Ib, dist in parts)  # each centre falls by its distance from O
    w2 = [x for x in sp.solve(sp.Eq(T, drop), w) if float(x.subs(vals)) < 0][0]  # turning clockwise
    s2 = newton_euler({th: -pi / 2, thd: w2})
    print("  at the release (moments about O of both parts):")
    a1 = show("alpha1", s1[thdd], vals, "rad/s^2")
    rx1 = show("Rx1", s1[Rx], vals, "N")
    ry1 = show("Ry1", s1[Ry], vals, "N")
    print("  at the vertical (energy, then moments about O):")
    o2 = show("omega2", w2, vals, "rad/s")
    ry2 = show("Ry2", s2[Ry], vals, "N")
    assert sp.simplify(s2[thdd]) == 0 and sp.simplify(s2[Rx]) == 0
    print("  against the YAML's expect:")
    local = dict(SYMS, m_r=m_r, m_d=m_d)
    for name, d in [("alpha1", a1), ("Rx1", rx1), ("Ry1", ry1), ("omega2", o2), ("Ry2", ry2)]:
        form_text, value_text = expect[name]
        form = sp.sympify(form_text.replace("^", "**"), locals=local)
        assert sp.simplify(d - form) == 0, f"{name}: derived {d} != claimed form {form}"
        literal = value_text.split()[0]
        v = float(sp.N(d.subs(vals), 30))
        if float(literal) == 0:
            assert abs(v) < 1e-12
        else:
            sf = sig_figs(literal)
            assert float(f"{v:.{sf - 1}e}") == float(literal), f"{name}: derived {v}, claimed {literal}"
        print(f"    {name}: form {form_text} proved; value {value_text} matches")
    assert set(expect) == {"alpha1", "Rx1", "Ry1", "omega2", "Ry2"}


# ----------------------------------------------------------------------------- case 6
def case6():
    """The ball on the dome, in polar form (no Lagrange, no kinergy): energy from the top,
    m v^2/2 = m g R (1 - cos(theta)); along the normal towards the centre, m g cos(theta) - N =
    m v^2/R; the ball leaves where N = 0."""
    expect, positions = load_scene("ball_leaves_dome.yaml")
    R = sp.symbols("R", positive=True)
    th = sp.symbols("theta", positive=True)
    v2 = 2 * g * R * (1 - cos(th))          # v^2 from energy
    N = m * g * cos(th) - m * v2 / R         # the dome's push
    roots = [x for x in sp.solve(sp.Eq(N, 0), th) if x.is_positive and x < pi / 2]
    assert len(roots) == 1
    theta2 = sp.simplify(roots[0])
    vals = {m: Q(4, 10), R: Q(15, 10), g: Q(981, 100)}
    print("Case 6: ball_leaves_dome.yaml (m = 0.4 kg, R = 1.5 m, g = 9.81)")
    Rp, thp = sp.Symbol("R"), sp.Symbol("theta")  # as the YAML's text reads (no assumptions)
    check_positions(positions, "ball", [Rp * sin(thp), Rp * cos(thp)])
    t2 = show("theta2", theta2, vals, "rad")
    v = show("v2", sp.sqrt(v2.subs(th, theta2)), vals, "m/s")
    d = show("drop", R - R * cos(theta2), vals, "m")
    # the YAML gives theta2 in degrees: its value is checked in degrees
    local = dict(SYMS, R=R)
    for name, derived, scale in [("theta2", t2, 180 / pi), ("v2", v, 1), ("drop", d, 1)]:
        form_text, value_text = expect[name]
        form = sp.sympify(form_text.replace("^", "**"), locals=local)
        assert sp.simplify(derived - form) == 0, f"{name}: derived {derived} != claimed form {form}"
        literal = value_text.split()[0]
        val = float(sp.N((derived * scale).subs(vals), 30))
        sf = sig_figs(literal)
        assert float(f"{val:.{sf - 1}e}") == float(literal), f"{name}: derived {val}, claimed {literal}"
        print(f"    {name}: form {form_text} proved; value {value_text} matches")
    assert set(expect) == {"theta2", "v2", "drop"}


def main():
    case1_2()
    print()
    case3()
    print()
    case4()
    print()
    case5()
    print()
    case6()
    print()
    print("all checks passed")


if __name__ == "__main__":
    sys.exit(main())
