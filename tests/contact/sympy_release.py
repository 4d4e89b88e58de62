#!/usr/bin/python3
"""Independent check (sympy and mpmath only, no kinergy) of where a body leaves a surface that can
only push: the normal force N of a track, N >= 0, and the state `where: ["N(x) = 0"]`.

Every case is derived here from first principles, with nothing taken from kinergy:
  - the positions are written by hand from the YAML's description, and asserted equal to the
    YAML's `position:` (and for the rod its points A and B, from `angle:` and `points:`);
  - the supports' forces are unknowns of Newton-Euler, m a_G = sum of forces and
    Ibar alpha = sum of moments about G, the accelerations from differentiating the positions
    twice in time;
  - the rate from conservation of energy, T1 + V1 = T2 + V2 (every support is smooth, or a
    rolling contact that does no work);
  - the body leaves where its normal force falls to zero: N(theta, theta_dot^2 from energy) = 0
    is solved for cos(theta) (after dropping factors that do not vanish while the body moves,
    sin(theta) for 0 < theta < pi/2, and m, g, L ...), and it is checked that N > 0 from the
    start to there, so that this zero is the first one.

Each derived closed form is proved equal to the YAML's expect form by sympy simplification (two
acos forms by their arguments, acos being one-to-one), each value matched to the figures the YAML
writes (angles in degrees), and each result printed with 15 significant digits.

  1. derivations/kinetics/ball_leaves_dome.yaml -- a particle from rest at the top of a smooth
     dome of radius R: ball at R (sin(theta), cos(theta)); the dome's push N along the outward
     normal (sin(theta), cos(theta)). m a = N n - m g j gives N = m g cos(theta) - m R theta_dot^2;
     energy R^2 theta_dot^2/2 = g R (1 - cos(theta)); N = 0 at cos(theta) = 2/3.
     theta2, v2 = R theta_dot, drop = R - y.
  2. derivations/kinetics/block_leaves_quarter_circle.yaml -- the same on a convex circle of radius
     R, reached at the top at v0 (theta_dot = v0/R): cos(theta) = (2 + v0^2/(g R))/3; theta2, v2,
     drop.
  3. derivations/kinetics/sphere_rolls_off_sphere.yaml -- a solid sphere (Ibar = 2 m r^2/5) rolling
     without slipping from rest on top of a fixed sphere of radius R: centre G = (R + r)(sin, cos),
     its angle phi, the contact C = R (sin, cos). No slip, v_C = v_G + phi_dot k x (C - G) = 0,
     gives (R + r) theta_dot + r phi_dot = 0 (asserted to be the YAML's constraint); Newton-Euler
     with the push N along n and the friction F along the tangent u = (cos, -sin) at C unknown,
     and the rolling differentiated once more; energy with T = m v_G^2/2 + Ibar phi_dot^2/2.
     cos(theta) = 10/17; theta2, v2 = (R + r) theta_dot. (The friction needed, (2/7) m g
     sin(theta), stays finite as N -> 0, so F/N grows without bound near the release: the scene
     is the idealised one, rolling held to the end.)
  4. derivations/kinetics/rod_leaves_wall.yaml -- a uniform rod (Ibar = m L^2/12), A on a smooth
     floor, B on a smooth vertical wall, theta from the vertical: A = (L sin, 0), B = (0, L cos),
     G = (L/2)(sin, cos). N_A up at A, N_B along +x at B unknown; m a_G = (N_B, N_A - m g),
     Ibar theta_ddot = (A - G) x (0, N_A) + (B - G) x (N_B, 0). Released at theta0 with A moving
     away from the wall at vA0, theta_dot0 = vA0/(L cos(theta0)) (x_A = L sin(theta)). N_B =
     m L/2 (cos theta_ddot - sin theta_dot^2) vanishes at cos(theta) = 2 cos(theta0)/3 +
     2 vA0^2/(9 g L cos(theta0)^2); theta2, omega2. N_A > 0 there (A stays on the floor) and
     N_B > 0 at the start (B is pressed on the wall when released).
  5. tests/data/contact/rod_leaves_wall_rest.yaml -- the same ladder from rest: cos(theta) =
     2 cos(theta0)/3, omega2 = sqrt(g cos(theta0)/L).
  6. tests/data/contact/dome_past_release.yaml -- the dome asked at theta = 70 deg, which has no
     expect: the release angle from first principles (case 1's derivation with this scene's
     numbers) is 48.1897 deg to 6 significant figures, the figure kinergy's refusal names; and the
     push a ball held on the dome at 70 deg would need is negative, so 70 deg is past the release.
     Also the leave angles of cases 4 and 5 to 6 significant figures, 51.0531 deg and 52.8283 deg,
     the figures kinergy prints. Each of the three angles is found twice: from the closed form,
     and by mpmath's root finder on N(theta) itself, the rate from energy, not the closed form.
  7. tests/data/contact/loop_two_bodies.yaml -- a particle inside a vertical loop of radius R (the
     loop pushes it toward the centre), theta from the bottom, entering at v1 < sqrt(5 g R):
     N = m (v1^2/R - 2 g + 3 g cos(theta)) > 0 at both states (0 and 350 deg) and zero between, at
     cos(theta) = (2 g - v1^2/R)/(3 g), 123.819 deg to 6 significant figures: the place kinergy's
     confirming simulation names. And case 2's angle to 6 figures, 45.1791 deg, the place
     `kinergy simulate` stops at.

The YAML is read with PyYAML where it is installed, else by a plain reading of the few block and
flow mappings these scenes use (where PyYAML is there, the plain reading is also checked to give
what PyYAML gives).

Run (from the repository root):  /usr/bin/python3 tests/contact/sympy_release.py
It prints every result and ends with "all checks passed"; any mismatch stops it with an
AssertionError.
"""
import os
import re
import sys

import mpmath as mp
import sympy as sp
from sympy import Rational as Q, acos, cos, pi, sin, sqrt

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
mp.mp.dps = 30

t = sp.symbols("t")
m, g, R, r, L, v0, vA0, theta0 = sp.symbols("m g R r L v0 vA0 theta0", positive=True)
th_f, phi_f = sp.Function("theta")(t), sp.Function("phi")(t)
th, thd, thdd = sp.symbols("theta theta_dot theta_ddot")
phi, phid, phidd = sp.symbols("phi phi_dot phi_ddot")
COORDS = {th_f: (th, thd, thdd), phi_f: (phi, phid, phidd)}
c = sp.symbols("c")  # cos(theta)
SYMS = {"m": m, "g": g, "R": R, "r": r, "L": L, "v0": v0, "vA0": vA0, "theta0": theta0,
        "theta": th, "phi": phi, "pi": pi}


# ----------------------------------------------------------------------------- reading the YAML
def split_top(s, sep=","):
    """s split at the separators outside brackets and quotes."""
    out, depth, cur, quote = [], 0, "", None
    for ch in s:
        if quote:
            quote = None if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == sep and depth == 0:
            out.append(cur)
            cur = ""
            continue
        cur += ch
    out.append(cur)
    return out


def parse_flow(s):
    """A YAML flow value ({k: v, ...}, [a, b], a scalar) as dicts, lists and strings."""
    s = s.strip()
    if s.startswith("{") and s.endswith("}"):
        out = {}
        for item in split_top(s[1:-1]):
            if item.strip():
                k, _, v = item.partition(":")
                out[k.strip()] = parse_flow(v)
        return out
    if s.startswith("[") and s.endswith("]"):
        return [parse_flow(item) for item in split_top(s[1:-1]) if item.strip()]
    if len(s) >= 2 and s[0] == s[-1] and s[0] in "\"'":
        return s[1:-1]
    return s


def plain_yaml(text):
    """A plain reading of the block mappings (with flow values) these scenes are written in;
    folded scalars (description: >) and list items (analyses:) are skipped."""
    doc = {}
    stack = [(-1, doc)]
    for raw in text.splitlines():
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        indent = len(raw) - len(raw.lstrip())
        line = raw.strip()
        while stack[-1][0] >= indent:
            stack.pop()
        parent = stack[-1][1]
        if parent is None or line.startswith("- "):
            continue
        key, _, rest = line.partition(":")
        rest = rest.strip()
        if rest in ("", ">", "|", ">-", "|-"):
            child = {} if rest == "" else None
            if child is not None:
                parent[key.strip()] = child
            stack.append((indent, child))
        else:
            parent[key.strip()] = parse_flow(rest)
    return doc


def as_text(node):
    """PyYAML's reading with every key and scalar as its text, as the plain reading gives."""
    if isinstance(node, dict):
        return {str(k): as_text(v) for k, v in node.items()}
    if isinstance(node, list):
        return [as_text(v) for v in node]
    return str(node)


SECTIONS = ("parameters", "bodies", "effects", "states", "expect")


def load_scene(rel):
    """The scene's parameters, bodies, effects, states and expect (every leaf a string)."""
    text = open(os.path.join(ROOT, rel)).read()
    plain = plain_yaml(text)
    try:
        import yaml
    except ImportError:
        doc = plain
    else:
        doc = as_text(yaml.safe_load(text))
        for k in SECTIONS:  # the fallback reads these sections as PyYAML does
            assert plain.get(k) == doc.get(k), f"{rel}: plain reading of {k}: {plain.get(k)} != {doc.get(k)}"
    return {k: doc.get(k, {}) for k in SECTIONS}


def to_sym(text):
    return sp.sympify(str(text).replace("^", "**"), locals=SYMS)


def parameter_values(scene):
    """The parameters as exact numbers (SI; an angle written in deg to radians)."""
    vals = {}
    for name, text in scene["parameters"].items():
        number, *unit = str(text).split()
        v = sp.Rational(number)
        if unit and unit[0] == "deg":
            v = v * pi / 180
        vals[SYMS[name]] = v
    return vals


# ----------------------------------------------------------------------------- mechanics helpers
def kin(expr):
    """expr(q(t)) with q, q', q'' replaced by the symbols (q, q_dot, q_ddot)."""
    rep = {}
    for f, (q, qd, qdd) in COORDS.items():
        rep[sp.Derivative(f, (t, 2))] = qdd
        rep[sp.Derivative(f, t)] = qd
    return sp.sympify(expr).subs(rep).subs({f: q for f, (q, _, _) in COORDS.items()})


def vel(vec):
    return [kin(sp.diff(x, t)) for x in vec]


def acc(vec):
    return [kin(sp.diff(x, t, 2)) for x in vec]


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def n15(e):
    v = sp.N(e, 15)
    return "0" if v == 0 else f"{v}"


def show(name, closed, vals, unit=""):
    closed = sp.simplify(closed)
    value = closed.subs(vals)
    if value.free_symbols:
        print(f"  {name:8s} = {sp.sstr(closed)}")
    else:
        print(f"  {name:8s} = {sp.sstr(closed):52s} = {n15(value)} {unit}".rstrip())
    return closed


def in_cos(expr):
    """expr, a function of theta, written in c = cos(theta) (sin(theta)^2 = 1 - c^2)."""
    e = sp.expand(sp.expand_trig(expr))
    e = e.subs(sin(th) ** 2, 1 - c**2).subs(cos(th), c)
    e = sp.simplify(e)
    assert th not in e.free_symbols, f"not a function of cos(theta) alone: {e}"
    return e


def release_cos(N, rate2, vals):
    """cos(theta) where the push N(theta, theta_dot) falls to zero, theta_dot^2 = rate2(theta)
    from energy. N depends on theta_dot through theta_dot^2 only (asserted). The factors of N
    that do not vanish while the body moves (nonzero constants, sin(theta) on 0 < theta < pi/2)
    are dropped; what is left must have one root in cos(theta)."""
    assert sp.simplify(N - N.subs(thd, -thd)) == 0, "N depends on the sign of theta_dot"
    Ne = sp.factor(sp.simplify(N.subs(thd, sp.sqrt(rate2))))
    kept = []
    for f in sp.Mul.make_args(Ne):
        base = f.base if f.is_Pow else f
        if th not in f.free_symbols:
            assert f.subs(vals).is_nonzero, f"a constant factor of N that is zero: {f}"
        elif base == sin(th):
            print(f"  (the factor {f} of N is dropped: positive for 0 < theta < pi/2)")
        else:
            kept.append(f)
    roots = sp.solve(in_cos(sp.Mul(*kept)), c)
    assert len(roots) == 1, f"not one root in cos(theta): {roots}"
    return sp.simplify(roots[0]), Ne


def sig_figs(literal):
    return len(re.sub(r"[^0-9]", "", literal).lstrip("0"))


def rounds_to(v, literal):
    sf = sig_figs(literal)
    return float(f"{float(v):.{sf - 1}e}") == float(literal), sf


def check_claim(name, derived, expect, vals):
    """The derived closed form equals the YAML's form (proved by simplification; two acos forms
    by their arguments, acos being one-to-one on [-1, 1]), and its value rounds to the YAML's
    value at the figures it is written with (an angle in deg compared in degrees)."""
    entry = expect[name]
    form = to_sym(entry["form"])
    if sp.simplify(derived - form) == 0:
        how = "proved"
    else:
        assert isinstance(derived, acos) and isinstance(form, acos), \
            f"{name}: derived {derived} != claimed form {form}"
        assert sp.simplify(derived.args[0] - form.args[0]) == 0, \
            f"{name}: derived {derived} != claimed form {form}"
        how = "proved (acos of equal arguments)"
    if "value" not in entry:
        print(f"    {name}: form {entry['form']} {how}")
        return
    literal, *unit = entry["value"].split()
    scale = 180 / pi if unit and unit[0] == "deg" else 1
    v = sp.N((derived * scale).subs(vals), 30)
    ok, sf = rounds_to(v, literal)
    assert ok, f"{name}: derived {v} does not round to the claimed {literal}"
    print(f"    {name}: form {entry['form']} {how}; value {entry['value']} matches to {sf} significant figures")


def check_positions(scene, body, mine, angle=None, points=None):
    """My hand-written positions equal the YAML's: the body's, and its points' from its angle."""
    b = scene["bodies"][body]
    theirs = [to_sym(s) for s in b["position"]]
    for a, y in zip(mine, theirs):
        assert sp.simplify(a - y) == 0, f"{body}: position {a} != YAML's {y}"
    print(f"  position of {body} as in the YAML: ({sp.sstr(theirs[0])}, {sp.sstr(theirs[1])})")
    if angle is not None:
        ang = to_sym(b["angle"])
        assert sp.simplify(cos(ang) - cos(angle)) == 0 and sp.simplify(sin(ang) - sin(angle)) == 0
        for p, world in (points or {}).items():
            local = [to_sym(s) for s in b["points"][p]]
            yaml_world = [theirs[0] + cos(ang) * local[0] - sin(ang) * local[1],
                          theirs[1] + sin(ang) * local[0] + cos(ang) * local[1]]
            for a, y in zip(world, yaml_world):
                assert sp.simplify(a - y) == 0, f"{body}.{p}: {a} != YAML's {y}"
            print(f"  point {body}.{p} as in the YAML (angle {b['angle']}): "
                  f"({sp.sstr(world[0])}, {sp.sstr(world[1])})")


def check_release_state(scene, effect):
    """State 2 of the scene is where the push of `effect`, a track that only pushes, vanishes."""
    assert scene["states"]["2"]["where"] == [f"N({effect}) = 0"], scene["states"]["2"]
    assert "pushes" in scene["effects"][effect] and "track" in scene["effects"][effect]


def check_state1(scene, mine):
    """State 1 as written by hand from the description equals the YAML's."""
    s1 = scene["states"]["1"]
    for key, value in mine.items():
        assert sp.simplify(to_sym(s1[key]) - value) == 0, f"state 1 {key}: {s1[key]} != {value}"


def positive_between(N_of_theta, a, b, vals, n=50):
    """N > 0 at n points of [a, b) (a, b numbers): the zero at b is the first."""
    f = sp.lambdify(th, N_of_theta.subs(vals), "mpmath")
    a, b = (mp.mpf(str(sp.N(x, 30))) for x in (a, b))
    for k in range(n):
        x = a + (b - a) * k / n
        assert f(x) > 0, f"N <= 0 at theta = {x} before the release"


# ----------------------------------------------------------------------------- cases 1, 2 and 6
def particle_on_circle():
    """A particle on a fixed circle of radius R, centre O, pushed outward by N: Newton's second law
    with N and theta_ddot unknown; returns N(theta, theta_dot) and the energy."""
    N = sp.symbols("N")
    rP = [R * sin(th_f), R * cos(th_f)]
    n = [sin(th), cos(th)]  # the outward normal at the particle
    a = acc(rP)
    v = vel(rP)
    eqs = [sp.Eq(m * a[0], N * n[0]), sp.Eq(m * a[1], N * n[1] - m * g)]
    sol = sp.solve(eqs, [thdd, N], dict=True)
    assert len(sol) == 1
    energy = Q(1, 2) * m * (v[0] ** 2 + v[1] ** 2) + m * g * kin(rP[1])
    return [kin(x) for x in rP], sp.simplify(sol[0][N]), sp.simplify(sol[0][thdd]), energy


def rate_squared(energy, state1):
    """theta_dot^2 at theta, from energy(theta, theta_dot) = energy at state 1."""
    w2 = sp.symbols("w2", positive=True)
    e2 = sp.expand(energy).subs(thd**2, w2)
    assert thd not in e2.free_symbols
    sol = sp.solve(sp.Eq(e2, energy.subs(state1)), w2)
    assert len(sol) == 1
    return sp.simplify(sol[0])


def particle_case(rel, body, effect, title, v_top):
    """The particle reaches the top (theta = 0) moving horizontally (+x) at v_top."""
    scene = load_scene(rel)
    vals = parameter_values(scene)
    print(title)
    check_release_state(scene, effect)
    rP, N, alpha, energy = particle_on_circle()
    check_positions(scene, body, rP)
    vx = vel([R * sin(th_f), R * cos(th_f)])[0]
    theta_dot0 = sp.solve(sp.Eq(vx.subs(th, 0), v_top), thd)[0]  # x' = R cos(theta) theta_dot
    check_state1(scene, {"theta": 0, "theta_dot": theta_dot0})
    show("alpha", alpha, {})
    show("N", N, {})
    rate2 = rate_squared(energy, {th: 0, thd: theta_dot0})
    show("thdot^2", rate2, {})
    c2, _ = release_cos(N, rate2, vals)
    theta2 = acos(c2)
    positive_between(N.subs(thd, sp.sqrt(rate2)), 0, theta2.subs(vals), vals)
    print("  N = 0 (N > 0 from the top to there):")
    show("cos th2", c2, vals)
    show("theta2", theta2 * 180 / pi, vals, "deg")
    speed = sp.sqrt(in_cos(R**2 * rate2).subs(c, c2))  # |v| = R theta_dot
    v2 = show("v2", speed, vals, "m/s")
    drop = show("drop", R - in_cos(rP[1]).subs(c, c2), vals, "m")
    return scene, vals, {"theta2": theta2, "v2": v2, "drop": drop}, N, rate2


def case1():
    scene, vals, got, _, _ = particle_case(
        "derivations/kinetics/ball_leaves_dome.yaml", "ball", "dome",
        "Case 1: ball_leaves_dome.yaml (m = 0.4 kg, R = 1.5 m, g = 9.81 m/s^2), from rest", 0)
    print("  against the YAML's expect:")
    for name in ("theta2", "v2", "drop"):
        check_claim(name, got[name], scene["expect"], vals)
    assert set(scene["expect"]) == {"theta2", "v2", "drop"}


def case2():
    scene, vals, got, _, _ = particle_case(
        "derivations/kinetics/block_leaves_quarter_circle.yaml", "block", "surface",
        "Case 2: block_leaves_quarter_circle.yaml (m = 0.5 kg, R = 2 m, v0 = 1.5 m/s, g = 9.81 m/s^2)",
        v0)
    print("  against the YAML's expect:")
    for name in ("theta2", "v2", "drop"):
        check_claim(name, got[name], scene["expect"], vals)
    assert set(scene["expect"]) == {"theta2", "v2", "drop"}


def degrees_6(name, closed_deg, N_numeric, bracket, literal):
    """The leave angle to 6 significant figures, from the closed form and, independently, from
    mpmath's root of N(theta) itself; both must round to literal."""
    a = mp.mpf(sp.N(closed_deg, 30))
    root = mp.findroot(N_numeric, (mp.mpf(bracket[0]), mp.mpf(bracket[1])), solver="anderson")
    b = root * 180 / mp.pi
    assert abs(a - b) < mp.mpf("1e-20"), f"{name}: closed form {a} deg, root of N {b} deg"
    assert f"{float(a):.6g}" == literal, f"{name}: {float(a):.6g} deg, expected {literal}"
    print(f"  {name}: {mp.nstr(a, 15)} deg (closed form), {mp.nstr(b, 15)} deg (root of N);"
          f" to 6 significant figures {literal} deg")


# ----------------------------------------------------------------------------- case 7
def case7():
    """tests/data/contact/loop_two_bodies.yaml: a particle inside a vertical loop (the loop pushes
    it toward the centre O), theta from the bottom, at (R sin(theta), -R cos(theta)), entering at
    the bottom at v1 < sqrt(5 g R); asked at 350 deg. The block beside it moves on its own (it
    changes nothing here). N > 0 at both states, N = 0 between them: the release, to 6 figures
    (what kinergy's confirming simulation reports), and the block's quarter circle to 6 figures."""
    scene = load_scene("tests/data/contact/loop_two_bodies.yaml")
    v1, M = sp.symbols("v1 M", positive=True)
    SYMS.update({"v1": v1, "M": M})
    vals = parameter_values(scene)
    print("Case 7: loop_two_bodies.yaml (R = 1 m, v1 = 6 m/s, g = 9.81 m/s^2), asked at 350 deg")
    N = sp.symbols("N")
    rP = [R * sin(th_f), -R * cos(th_f)]
    inward = [-sin(th), cos(th)]  # from the particle toward O
    a = acc(rP)
    sol = sp.solve([sp.Eq(m * a[0], N * inward[0]), sp.Eq(m * a[1], N * inward[1] - m * g)], [thdd, N], dict=True)
    assert len(sol) == 1
    Nf = sp.simplify(sol[0][N])
    check_positions(scene, "ball", [kin(x) for x in rP])
    v = vel(rP)
    energy = Q(1, 2) * m * (v[0] ** 2 + v[1] ** 2) + m * g * kin(rP[1])
    rate2 = rate_squared(energy, {th: 0, thd: v1 / R})
    N_e = sp.simplify(Nf.subs(thd, sp.sqrt(rate2)))
    show("N", N_e, {})
    c7, _ = release_cos(Nf, rate2, vals)
    theta7 = sp.pi - acos(-c7)  # the root past the side (cos < 0): between 90 and 180 deg
    assert sp.simplify(cos(theta7) - c7) == 0
    show("cos th", c7, vals)
    show("theta", theta7 * 180 / pi, vals, "deg  (where the ball leaves the loop)")
    asked = 35 * pi / 18
    for where, at in (("state 1", 0), ("state 2", asked)):
        Nat = show("N at " + where, N_e.subs(th, at), vals, "N")
        assert Nat.subs(vals) > 0, f"N <= 0 at {where}"
    positive_between(N_e, 0, theta7.subs(vals), vals)
    f7 = sp.lambdify(th, N_e.subs(vals), "mpmath")
    degrees_6("loop release", (theta7 * 180 / pi).subs(vals), f7, (1.8, 2.5), "123.819")
    # the block over the quarter circle (case 2), to 6 figures as kinergy's simulate reports it
    v0 = sp.Rational(3, 2)
    cb = (2 + v0**2 / (sp.Rational(981, 100) * 2)) / 3
    degrees_6("block_leaves_quarter_circle", acos(cb) * 180 / pi,
              lambda x: mp.cos(x) - mp.mpf(sp.N(cb, 30)), (0.5, 1.0), "45.1791")


# ----------------------------------------------------------------------------- case 3
def case3():
    scene = load_scene("derivations/kinetics/sphere_rolls_off_sphere.yaml")
    vals = parameter_values(scene)
    print("Case 3: sphere_rolls_off_sphere.yaml (m = 1.5 kg, r = 0.05 m, R = 0.8 m, g = 9.81 m/s^2)")
    check_release_state(scene, "dome")
    N, F = sp.symbols("N F")
    Ibar = Q(2, 5) * m * r**2                      # a solid sphere
    rG = [(R + r) * sin(th_f), (R + r) * cos(th_f)]
    rC = [R * sin(th_f), R * cos(th_f)]            # the contact point, on the fixed sphere
    check_positions(scene, "ball", [kin(x) for x in rG])
    assert to_sym(scene["bodies"]["ball"]["angle"]) == phi
    at = [to_sym(s) for s in scene["effects"]["rolling"]["at"]]
    assert all(sp.simplify(a - kin(b)) == 0 for a, b in zip(at, rC)), "the contact point"
    check_state1(scene, {"theta": 0, "theta_dot": 0, "phi": 0})
    n = [sin(th), cos(th)]                         # outward normal at C
    u = [cos(th), -sin(th)]                        # tangent at C, theta increasing
    # no slip: the ball's material point at C is at rest
    vG = vel(rG)
    arm = [kin(rC[0] - rG[0]), kin(rC[1] - rG[1])]  # from G to C
    vC = [vG[0] - phid * arm[1], vG[1] + phid * arm[0]]  # v_G + phi_dot k x (C - G)
    assert sp.simplify(dot(vC, n)) == 0
    slip = sp.simplify(dot(vC, u))
    lhs, rhs = scene["effects"]["rolling"]["constraint"].split("=")
    yaml_rolling = to_sym(lhs) - to_sym(rhs)
    yaml_rate = kin(sp.diff(yaml_rolling.subs({th: th_f, phi: phi_f}), t))
    assert sp.simplify(slip - yaml_rate) == 0, f"no slip {slip} = 0 is not the YAML's {yaml_rate} = 0"
    print(f"  no slip at C: v_C . u = {sp.sstr(slip)} = 0, the YAML's constraint differentiated")
    slip_acc = kin(sp.diff(slip.subs({thd: sp.diff(th_f, t), phid: sp.diff(phi_f, t)}), t))
    aG = acc(rG)
    force = [N * n[0] + F * u[0], N * n[1] + F * u[1]]
    eqs = [sp.Eq(m * aG[0], force[0]),
           sp.Eq(m * aG[1], force[1] - m * g),
           sp.Eq(Ibar * phidd, cross(arm, force)),
           sp.Eq(slip_acc, 0)]
    sol = sp.solve(eqs, [thdd, phidd, N, F], dict=True)
    assert len(sol) == 1
    s = {k: sp.simplify(v) for k, v in sol[0].items()}
    show("alpha", s[thdd], {})
    show("N", s[N], {})
    show("F", s[F], {})
    phid_roll = sp.solve(slip, phid)[0]
    energy = (Q(1, 2) * m * (vG[0] ** 2 + vG[1] ** 2) + Q(1, 2) * Ibar * phid_roll**2
              + m * g * kin(rG[1]))
    rate2 = rate_squared(energy, {th: 0, thd: 0})
    show("thdot^2", rate2, {})
    c2, _ = release_cos(s[N], rate2, vals)
    theta2 = acos(c2)
    positive_between(s[N].subs(thd, sp.sqrt(rate2)), 0, theta2.subs(vals), vals)
    print("  N = 0 (N > 0 from the top to there):")
    show("cos th2", c2, vals)
    show("theta2", theta2 * 180 / pi, vals, "deg")
    v2 = show("v2", sp.sqrt(in_cos((R + r) ** 2 * rate2).subs(c, c2)), vals, "m/s")
    show("F2", s[F].subs(th, theta2), vals,
         "N  (the friction there, along the tangent)")
    print("  against the YAML's expect:")
    check_claim("theta2", theta2, scene["expect"], vals)
    check_claim("v2", v2, scene["expect"], vals)
    assert set(scene["expect"]) == {"theta2", "v2"}


# ----------------------------------------------------------------------------- cases 4 and 5
def rod_on_floor_and_wall(rel, body):
    """The rod AB, A on the floor y = 0, B on the wall x = 0; returns the scene, its values, N_A,
    N_B (functions of theta, theta_dot) and the energy."""
    scene = load_scene(rel)
    vals = parameter_values(scene)
    check_release_state(scene, "wall")
    NA, NB = sp.symbols("N_A N_B")
    Ibar = m * L**2 / 12                            # a slender rod
    rA = [L * sin(th_f), sp.S(0)]
    rB = [sp.S(0), L * cos(th_f)]
    rG = [L / 2 * sin(th_f), L / 2 * cos(th_f)]
    check_positions(scene, body, [kin(x) for x in rG], angle=pi / 2 + th,  # A -> B: (-sin, cos)
                    points={"A": [kin(x) for x in rA], "B": [kin(x) for x in rB]})
    # the rod's angle is pi/2 + theta, so its angular velocity is theta_dot (counter-clockwise)
    aG = acc(rG)
    armA = [kin(rA[0] - rG[0]), kin(rA[1] - rG[1])]
    armB = [kin(rB[0] - rG[0]), kin(rB[1] - rG[1])]
    eqs = [sp.Eq(m * aG[0], NB),                                       # sum F_x
           sp.Eq(m * aG[1], NA - m * g),                               # sum F_y
           sp.Eq(Ibar * thdd, cross(armA, [0, NA]) + cross(armB, [NB, 0]))]  # sum M_G
    sol = sp.solve(eqs, [thdd, NA, NB], dict=True)
    assert len(sol) == 1
    s = {k: sp.simplify(v) for k, v in sol[0].items()}
    vG = vel(rG)
    energy = Q(1, 2) * m * (vG[0] ** 2 + vG[1] ** 2) + Q(1, 2) * Ibar * thd**2 + m * g * kin(rG[1])
    return scene, vals, s[thdd], s[NA], s[NB], energy, vel(rA)[0]


def rod_case(rel, body, title, vA_start):
    """Released at theta0 with A moving away from the wall (+x) at vA_start."""
    print(title)
    scene, vals, alpha, NA, NB, energy, vA = rod_on_floor_and_wall(rel, body)
    theta_dot0 = sp.solve(sp.Eq(vA.subs(th, theta0), vA_start), thd)[0]  # x_A' = L cos(theta) theta_dot
    show("thdot0", theta_dot0, vals, "rad/s  (from vA at the release)")
    check_state1(scene, {"theta": theta0, "theta_dot": theta_dot0})
    show("alpha", alpha, {})
    show("N_A", NA, {})
    show("N_B", NB, {})
    rate2 = rate_squared(energy, {th: theta0, thd: theta_dot0})
    show("thdot^2", rate2, {})
    assert (NB.subs({th: theta0, thd: theta_dot0})).subs(vals) > 0, "B not pressed on the wall at the start"
    c2, _ = release_cos(NB, rate2, vals)
    theta2 = acos(c2)
    NB_e = NB.subs(thd, sp.sqrt(rate2))
    positive_between(NB_e, vals[theta0], theta2.subs(vals), vals)
    print("  N_B = 0 (N_B > 0 from the release to there):")
    show("cos th2", c2, vals)
    show("theta2", theta2 * 180 / pi, vals, "deg")
    omega2 = show("omega2", sp.sqrt(in_cos(rate2).subs(c, c2)), vals, "rad/s  (theta increasing)")
    NA2 = show("N_A2", in_cos(NA.subs(thd, sp.sqrt(rate2))).subs(c, c2), vals, "N  (> 0: A stays on the floor)")
    assert NA2.subs(vals) > 0
    show("vA2", in_cos(L * cos(th)).subs(c, c2) * omega2, vals, "m/s")
    print("  against the YAML's expect:")
    for name, d in [("theta2", theta2), ("omega2", omega2)]:
        check_claim(name, d, scene["expect"], vals)
    assert set(scene["expect"]) == {"theta2", "omega2"}
    return vals, theta2, NB_e


# ----------------------------------------------------------------------------- main
def main():
    case1()
    print()
    case2()
    print()
    case3()
    print()
    vals4, theta4, NB4 = rod_case(
        "derivations/kinetics/rod_leaves_wall.yaml", "rod",
        "Case 4: rod_leaves_wall.yaml (m = 12 kg, L = 3 m, theta0 = 20 deg, vA0 = 0.5 m/s, g = 9.81 m/s^2)",
        vA0)
    print()
    vals5, theta5, NB5 = rod_case(
        "tests/data/contact/rod_leaves_wall_rest.yaml", "ladder",
        "Case 5: rod_leaves_wall_rest.yaml (m = 20 kg, L = 4 m, theta0 = 25 deg, g = 9.81 m/s^2), from rest",
        0)
    print()
    # case 6: the dome asked at 70 deg
    scene = load_scene("tests/data/contact/dome_past_release.yaml")
    vals6 = parameter_values(scene)
    print("Case 6: dome_past_release.yaml (m = 0.4 kg, R = 1.5 m, g = 9.81 m/s^2), asked at theta = 70 deg")
    assert not scene["expect"], "dome_past_release.yaml has no expect"
    rP, N, _, energy = particle_on_circle()
    check_positions(scene, "ball", rP)
    check_state1(scene, {"theta": 0, "theta_dot": 0})
    asked = to_sym(scene["states"]["2"]["theta"].replace("deg", "*pi/180"))
    assert asked == 7 * pi / 18
    rate2 = rate_squared(energy, {th: 0, thd: 0})
    N_e = N.subs(thd, sp.sqrt(rate2))
    c6, _ = release_cos(N, rate2, vals6)
    theta6 = acos(c6)
    show("cos th2", c6, vals6)
    show("theta2", theta6 * 180 / pi, vals6, "deg  (where the ball leaves)")
    N70 = show("N(70)", N_e.subs(th, asked), vals6, "N  (the push a ball held there would need)")
    assert N70.subs(vals6) < 0 and theta6.subs(vals6) < asked, "70 deg is not past the release"
    f6 = sp.lambdify(th, N_e.subs(vals6), "mpmath")
    degrees_6("dome release", (theta6 * 180 / pi).subs(vals6), f6, (0.5, 1.2), "48.1897")
    f4 = sp.lambdify(th, NB4.subs(vals4), "mpmath")
    degrees_6("rod_leaves_wall", (theta4 * 180 / pi).subs(vals4), f4, (0.6, 1.2), "51.0531")
    f5 = sp.lambdify(th, NB5.subs(vals5), "mpmath")
    degrees_6("rod_leaves_wall_rest", (theta5 * 180 / pi).subs(vals5), f5, (0.6, 1.2), "52.8283")
    print()
    case7()
    print()
    print("all checks passed")


if __name__ == "__main__":
    sys.exit(main())
