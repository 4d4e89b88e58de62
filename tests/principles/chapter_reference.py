#!/usr/bin/env python3
"""Independent reference for six worked problems in derivations/.

Each problem is re-derived here from first principles with sympy (energy, momentum,
Newton/Lagrange equations written below), NOT by running kinergy.  Only the data
(the `parameters:` block) and the `expect:` block are read from the yaml files.

For every result the script prints the closed form and its value to 30 significant
digits, then checks
  * forms:  simplify(mine - yaml_form) == 0, all symbols positive;
  * values: mine agrees with the yaml number to the figures written there
            (|mine - written| <= half a unit in the last written place).
Exits with status 1 on any disagreement.

Run from the repository root:  python3 tests/principles/chapter_reference.py
"""
import os
import sys
from decimal import Decimal

import mpmath as mp
import sympy as sp
import yaml

mp.mp.dps = 40
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FAILURES = []


# ----------------------------------------------------------------------------- helpers
def load(rel):
    with open(os.path.join(ROOT, rel)) as f:
        doc = yaml.safe_load(f)
    syms, vals = {}, {}
    for name, text in doc["parameters"].items():
        syms[name] = sp.Symbol(name, positive=True)
        first = str(text).split()[0]
        try:  # "2 kg" -> 2 (SI units throughout these files); "m/s" alone -> unknown
            vals[syms[name]] = sp.Rational(first)
        except (TypeError, ValueError):
            pass
    return doc, syms, vals


def check(ok, what):
    print(f"    [{'ok' if ok else 'FAIL'}] {what}")
    if not ok:
        FAILURES.append(what)


def mpval(expr, vals):
    """Numeric value of a sympy expression, 40 digits, as an mpmath number."""
    v = sp.N(sp.sympify(expr).subs(vals), 40)
    if not v.is_real:
        check(False, f"value of {expr} is real (got {v})")
    return mp.mpf(str(v))


def agrees_to_written(x, written):
    """True when x rounds to the written number (half a unit in its last figure)."""
    d = Decimal(written)
    half = mp.mpf(5) * mp.mpf(10) ** (d.as_tuple().exponent - 1)
    return abs(x - mp.mpf(written)) <= half * (1 + mp.mpf(10) ** -20)


def report(doc, syms, vals, name, mine_form=None, mine_value=None):
    """Print and check one result against doc['expect'][name]."""
    exp = doc["expect"][name]
    if mine_value is None:
        mine_value = mpval(mine_form, vals)
    print(f"  {name}:")
    if mine_form is not None:
        print(f"    closed form : {sp.simplify(mine_form)}")
    print(f"    value       : {mp.nstr(mine_value, 30, strip_zeros=False)}")
    if "form" in exp:
        theirs = sp.sympify(str(exp["form"]).replace("^", "**"), locals=syms)
        print(f"    yaml form   : {exp['form']}")
        check(mine_form is not None and sp.simplify(mine_form - theirs) == 0,
              f"{name}: form agrees with yaml")
    written = str(exp["value"]).split()[0]
    print(f"    yaml value  : {exp['value']}")
    check(agrees_to_written(mine_value, written), f"{name}: value agrees with yaml {written} to the figures written")
    return mine_value


def note(text):
    print(f"    note: {text}")


# ----------------------------------------------------------------------------- 1
def collar_spring():
    # Energy: (1/2) m x'^2 + (1/2) k (sqrt(x^2 + h^2) - L0)^2 = const.
    # T(s) = (1/2) m v0^2 - [V(s) - V(-a)]; v0_min makes min_{s in [-a,a]} T(s) = 0.
    # Candidates for the minimum: stationary points of V (dV/ds = 0) inside, and both ends.
    doc, S, vals = load("derivations/energy/collar_spring_least_speed.yaml")
    m, k, h, L0, a, v0 = (S[n] for n in ("m", "k", "h", "L0", "a", "v0"))
    s = sp.Symbol("s", real=True)
    V = lambda x: k / 2 * (sp.sqrt(x**2 + h**2) - L0) ** 2
    T = m * v0**2 / 2 - (V(s) - V(-a))
    cands = set(sp.solve(sp.diff(V(s), s), s)) | {-a, a}
    inside = [c for c in cands if -vals[a] <= c.subs(vals) <= vals[a]]  # exact comparison
    s_star = min(inside, key=lambda c: sp.N((V(-a) - V(c)).subs(vals)))  # least T
    print(f"  binding point s* = {s_star}  (candidates in range: {inside})")
    check(s_star == 0, "binding point is inside the path, at s = 0")
    sol = [r for r in sp.solve(sp.Eq(T.subs(s, s_star), 0), v0) if sp.N(r.subs(vals)) > 0]
    check(len(sol) == 1, "one positive root for v0")
    v0min = sol[0]
    # brute-force the claim that T >= 0 everywhere on [-a, a] with v0 = v0_min
    Tn = sp.lambdify(s, T.subs(v0, v0min).subs(vals), "mpmath")
    A = mpval(a, vals)
    worst = min(Tn(-A + 2 * A * i / 4000) for i in range(4001))
    check(worst > -mp.mpf(10) ** -30, f"T(s) >= 0 on [-a, a] at v0_min (least on grid {mp.nstr(worst, 5)} J)")
    check(mpval(V(0) - V(-a), vals) == 4, "description: spring energy at 0 minus at -a is 4 J")
    Vpp0 = sp.simplify(sp.diff(V(s), s, 2).subs(s, 0))
    note(f"V''(0) = {Vpp0} = {sp.N(Vpp0.subs(vals))} N/m < 0: x = 0 is an unstable equilibrium, so at "
         "exactly v0_min the collar only creeps toward x = 0 (infinite time); v0_min is an infimum, "
         "any v0 > v0_min gets through.")
    note("the closed form assumes h < L0 <= sqrt(a^2 + h^2) (max of V at s = 0, V(-a) <= V(a)).")
    report(doc, S, vals, "v0_min", v0min)


# ----------------------------------------------------------------------------- 2
def rod_revolution():
    # Rod pinned at its end: centre (L/2 sin th, -L/2 cos th), I_c = m L^2/12.
    # T = (1/2) m |v_c|^2 + (1/2) I_c th'^2,  V = m g y_c;  T(th) = T(0) - [V(th) - V(0)].
    # Pin is two-sided, so the only condition is T(th) >= 0 on [0, pi].
    doc, S, vals = load("derivations/energy/rod_full_revolution_least_speed.yaml")
    m, L, g, w0 = (S[n] for n in ("m", "L", "g", "w0"))
    th, thd = sp.symbols("theta thetadot", real=True)
    rc = sp.Matrix([L / 2 * sp.sin(th), -L / 2 * sp.cos(th)])
    ang = th - sp.pi / 2
    R = sp.Matrix([[sp.cos(ang), -sp.sin(ang)], [sp.sin(ang), sp.cos(ang)]])
    check(sp.simplify(rc + R * sp.Matrix([-L / 2, 0])) == sp.zeros(2, 1), "body point O stays at the pin (0, 0)")
    vc = rc.diff(th) * thd
    Tq = sp.simplify(m / 2 * vc.dot(vc) + m * L**2 / 24 * thd**2)
    print(f"  T = {Tq}")
    V = m * g * rc[1]
    KE = Tq.subs(thd, w0) - (V - V.subs(th, 0))
    cands = [c for c in sp.solve(sp.diff(V, th), th) if 0 <= c <= sp.pi] + [sp.S(0), sp.pi]
    th_star = min(set(cands), key=lambda c: sp.N(KE.subs(th, c).subs(vals).subs(w0, 1)))
    check(th_star == sp.pi, "least kinetic energy at theta = 180 deg (upright)")
    w0min = [r for r in sp.solve(KE.subs(th, th_star), w0) if sp.N(r.subs(vals)) > 0][0]
    note("upright is an unstable equilibrium: at exactly w0_min the rod approaches it asymptotically; "
         "w0_min is an infimum.")
    report(doc, S, vals, "w0_min", w0min)


# ----------------------------------------------------------------------------- 3
def bumper_stop(S, vals, v0value):
    """Stop of the package: (1/2) m v0^2 + W(x) = 0, W piecewise-polynomial between the
    switching points 0 < d1 < d2.  Returns (region, symbolic root, numeric root)."""
    m, k1, k2, d1, d2, v0 = (S[n] for n in ("m", "k1", "k2", "d1", "d2", "v0"))
    x = sp.Symbol("x", real=True)
    vv = dict(vals)
    vv[v0] = sp.Rational(v0value)
    regions = [(sp.S(0), d1, 0), (d1, d2, -k1 * (x - d1)), (d2, sp.oo, -k1 * (x - d1) - k2 * (x - d2))]
    W_lo = sp.S(0)  # work from 0 to the start of the region
    for i, (lo, hi, F) in enumerate(regions):
        T = m * v0**2 / 2 + W_lo + sp.integrate(F, (x, lo, x))
        for r in sp.solve(sp.Eq(T, 0), x):
            rn = sp.N(r.subs(vv), 40)
            if rn.is_real and sp.N(lo.subs(vv)) <= rn <= sp.N(hi.subs(vv)):
                return i, r, mp.mpf(str(rn)), T
        W_lo += sp.integrate(F, (x, lo, hi))
    raise RuntimeError("no stop found")


def two_stage_bumper():
    # Energy: (1/2) m v0^2 + int_0^x F dx = 0 with F = -k1 max(x-d1,0) - k2 max(x-d2,0),
    # integrated region by region; the stop is the first root lying in its own region.
    # The force magnitude grows with x, so its greatest value is at the stop.
    doc, S, vals = load("derivations/energy/two_stage_bumper_max.yaml")
    m, k1, k2, d1, d2, v0 = (S[n] for n in ("m", "k1", "k2", "d1", "d2", "v0"))
    check(mpval(k1 * (d2 - d1) ** 2 / 2, vals) == 1 and mpval(m * v0**2 / 2, vals) == 9,
          "description: soft stage takes 1 J of 9 J")
    region, xs, xn, T = bumper_stop(S, vals, str(vals[v0]))
    check(region == 2, "stop lies past d2 (stiff stage reached)")
    x = sp.Symbol("x", real=True)
    roots = sorted(sp.nsimplify(r.subs(vals)) - vals[d2] for r in sp.solve(T, x))  # u = x - d2, exact
    check(roots == [sp.Rational(-1, 10), sp.Rational(8, 100)], f"description: u roots {roots} are -0.1 and 0.08")
    report(doc, S, vals, "xmax", xs)
    report(doc, S, vals, "Fmax", sp.expand(k1 * (xs - d1) + k2 * (xs - d2)))
    # v0 = 0.5 m/s: 0.25 J < 1 J, the stiff stage is never reached
    region, xs2, xn2, _ = bumper_stop(S, vals, "0.5")
    print(f"  v0 = 0.5 m/s: stop x = {sp.simplify(xs2)} = {mp.nstr(xn2, 30)} m (region {region})")
    check(region == 1 and xn2 == mp.mpf("0.55"), "v0 = 0.5 m/s stops at 0.55 m, soft stage only")
    # the yaml closed form assumes the stiff stage is reached: (1/2) m v0^2 >= (1/2) k1 (d2-d1)^2
    yaml_form = sp.sympify(str(doc["expect"]["xmax"]["form"]).replace("^", "**"), locals=S)
    at = lambda speed: sp.N(yaml_form.subs(v0, sp.Rational(speed)).subs(vals), 12)
    _, _, true95, _ = bumper_stop(S, vals, "0.95")
    note(f"the yaml form needs v0 >= (d2-d1) sqrt(k1/m) = {sp.N(((d2 - d1) * sp.sqrt(k1 / m)).subs(vals), 6)} m/s: "
         f"at v0 = 0.5 it gives {at('0.5')} (not real); at v0 = 0.95 it gives {at('0.95')} < d2 "
         f"(spurious; the true stop is {mp.nstr(true95, 12)} m).")


# ----------------------------------------------------------------------------- 4
def block_on_cart():
    # Newton, while the block slides back relative to the cart (vb < vc):
    #   m vb' = +mu_k m g,  M vc' = -mu_k m g  (normal force m g, no external horizontal force).
    # t2: vb = vc.  J = int mu_k m g dt.  d = xc - xb.  Afterwards they move together.
    doc, S, vals = load("derivations/momentum/block_slides_on_cart.yaml")
    m, M, v0, mu, g = (S[n] for n in ("m", "M", "v0", "mu_k", "g"))
    t, tau = sp.symbols("t tau", positive=True)
    f = mu * m * g
    vb = sp.integrate(f / m, (tau, 0, t))
    vc = v0 - sp.integrate(f / M, (tau, 0, t))
    xb = sp.integrate(vb.subs(t, tau), (tau, 0, t))
    xc = sp.integrate(vc.subs(t, tau), (tau, 0, t))
    t2 = sp.solve(sp.Eq(vb, vc), t)[0]
    check(sp.simplify((vc - vb).subs(t, t2 / 2)).is_positive, "block slower than cart before t2 (friction forward on block)")
    v = sp.simplify(vb.subs(t, t2))
    J = sp.integrate(f, (t, 0, t2))
    d = sp.simplify((xc - xb).subs(t, t2))
    xb2 = sp.simplify(xb.subs(t, t2))
    # cross-checks: momentum of both, energy of both (friction dissipates f*d), energy of block
    check(sp.simplify(M * v0 - (M + m) * v) == 0, "momentum of both conserved")
    check(sp.simplify(M * v0**2 / 2 - (M + m) * v**2 / 2 - f * d) == 0, "energy of both: loss = mu_k m g d")
    check(sp.simplify(m * v**2 / 2 - f * xb2) == 0, "energy of block: (1/2) m v^2 = mu_k m g x_b")
    report(doc, S, vals, "v", v)
    report(doc, S, vals, "t2", t2)
    report(doc, S, vals, "J", J)
    report(doc, S, vals, "d", d)
    report(doc, S, vals, "xb2", xb2)
    note("parameter h (block height) plays no part; after t2 no friction is needed (no external force).")


# ----------------------------------------------------------------------------- 5
def collar_rod():
    # Lagrangian in (x, th): collar at (x, 0); rod centre (x + L/2 sin th, -L/2 cos th), I_c = m L^2/12.
    # x is cyclic -> p_x = dL/dx' conserved (= 0 from rest); energy conserved.
    # p_x = d/dt[(M+m) x + m L/2 sin th] -> (M+m) x + m L/2 sin th = m L/2 (start x = 0, th = 90 deg).
    # Collar alone: only the pin pushes it horizontally, so J = M v and  F_avg * x2 = (1/2) M v^2.
    doc, S, vals = load("derivations/momentum/collar_rod_pin_reaction.yaml")
    M, m, L, g = (S[n] for n in ("M", "m", "L", "g"))
    x, th, xd, thd = sp.symbols("x theta xdot thetadot", real=True)
    rc = sp.Matrix([x + L / 2 * sp.sin(th), -L / 2 * sp.cos(th)])
    ang = th - sp.pi / 2
    R = sp.Matrix([[sp.cos(ang), -sp.sin(ang)], [sp.sin(ang), sp.cos(ang)]])
    check(sp.simplify(rc + R * sp.Matrix([-L / 2, 0]) - sp.Matrix([x, 0])) == sp.zeros(2, 1),
          "rod end A stays at the collar")
    vc = rc.jacobian([x, th]) * sp.Matrix([xd, thd])
    T = M * xd**2 / 2 + m / 2 * vc.dot(vc) + m * L**2 / 24 * thd**2
    V = m * g * rc[1]
    Lag = T - V
    check(sp.diff(Lag, x) == 0, "x is cyclic")
    px = sp.expand(sp.diff(Lag, xd))
    check(sp.simplify(px - ((M + m) * xd + m * L / 2 * sp.cos(th) * thd)) == 0, "p_x = d/dt[(M+m)x + m L/2 sin th]")
    E1 = (T + V).subs({xd: 0, thd: 0, th: sp.pi / 2})
    E2 = (T + V).subs(th, 0)
    sols = sp.solve([px.subs(th, 0), E2 - E1], [xd, thd], dict=True)
    sol = [s_ for s_ in sols if sp.N(s_[thd].subs(vals)) < 0][0]  # rod falls: th decreasing
    v = sp.simplify(sol[xd])
    x2 = sp.solve(sp.Eq((M + m) * x + m * L / 2 * sp.sin(0), m * L / 2), x)[0]
    print(f"  collar displacement x2 = {x2} = {mp.nstr(mpval(x2, vals), 30)} m")
    check(mpval(x2, vals) == mp.mpf("0.2"), "description: x2 = 0.2 m")
    J = M * v
    F = sp.simplify((M * v**2 / 2) / x2)
    # the collar moves one way only, so 'distance' = displacement: xdot(th) >= 0 on [0, 90 deg]
    xd_px0 = sp.solve(px, xd)[0]  # collar velocity from p_x = 0, in terms of th, th'
    thd_sols = sp.solve((T + V).subs(xd, xd_px0) - E1, thd)  # energy at any th
    thd_of = [r for r in thd_sols if sp.N(r.subs(vals).subs(th, sp.Rational(1, 2))) < 0][0]
    xd_of = sp.lambdify(th, xd_px0.subs(thd, thd_of).subs(vals), "mpmath")
    grid = [xd_of(mp.pi / 2 * i / 400) for i in range(401)]
    check(all(q >= -mp.mpf(10) ** -30 for q in grid), "collar velocity never negative: it moves one way")
    check(all(grid[i] >= grid[i + 1] - mp.mpf(10) ** -30 for i in range(400)),
          "collar speed grows all the way as th falls to 0: pin's horizontal push on collar never reverses")
    report(doc, S, vals, "v", v)
    report(doc, S, vals, "J", J)
    report(doc, S, vals, "F", F)
    note("F is the space average (work / displacement); the time average J/t would differ.")


# ----------------------------------------------------------------------------- 6
def wheel_cam():
    # Energy: (1/2) m k^2 w2^2 = int_0^phi2 M0 exp(-(p/phi0)^2) dp = M0 phi0 (sqrt(pi)/2) erf(phi2/phi0).
    # Solved two ways at 40 digits: erfinv, and findroot on a quadrature of the couple.
    doc, S, vals = load("derivations/energy/wheel_cam_couple_angle.yaml")
    m, k, M0, phi0, w2 = (S[n] for n in ("m", "k", "M0", "phi0", "w2"))
    p, q = sp.symbols("phi q", positive=True)
    U = sp.integrate(M0 * sp.exp(-(q / phi0) ** 2), (q, 0, p))
    Tk = m * k**2 * w2**2 / 2
    print(f"  U(phi) = {U};  (1/2) m k^2 w2^2 = {Tk.subs(vals)} J;  U(oo) = {sp.N(U.subs(p, sp.oo).subs(vals), 10)} J")
    check(mpval(Tk, vals) < mpval(U.subs(p, sp.oo), vals), "the couple can supply the energy (U(oo) > T2)")
    form = phi0 * sp.erfinv(Tk / (M0 * phi0 * sp.sqrt(sp.pi) / 2))
    check(sp.simplify(U.subs(p, form) - Tk) == 0, "phi0 erfinv(...) solves the energy equation")
    a = mp.mpf(str(vals[phi0]))
    by_erfinv = a * mp.erfinv(mpval(Tk, vals) / (mpval(M0, vals) * a * mp.sqrt(mp.pi) / 2))  # 40 digits
    M0n, Tkn = mpval(M0, vals), mpval(Tk, vals)
    work = lambda e: mp.quad(lambda s: M0n * mp.exp(-(s / a) ** 2), [0, e]) - Tkn
    by_root = mp.findroot(work, mp.mpf("0.7"))
    print(f"  erfinv: {mp.nstr(by_erfinv, 38)}\n  quad+findroot: {mp.nstr(by_root, 38)}")
    check(abs(by_erfinv - by_root) < mp.mpf(10) ** -36, "erfinv and quadrature/findroot agree to 36 digits")
    check(agrees_to_written(by_erfinv, "0.7144304417732017885921246356422574"), "description's 34-digit value")
    report(doc, S, vals, "phi2", form, by_erfinv)
    note("'no closed form' means no elementary one: phi2 = phi0 erfinv(m k^2 w2^2/(M0 phi0 sqrt(pi))).")


def main():
    for title, fn in [("1. collar_spring_least_speed", collar_spring),
                      ("2. rod_full_revolution_least_speed", rod_revolution),
                      ("3. two_stage_bumper_max", two_stage_bumper),
                      ("4. block_slides_on_cart", block_on_cart),
                      ("5. collar_rod_pin_reaction", collar_rod),
                      ("6. wheel_cam_couple_angle", wheel_cam)]:
        print(f"\n== {title}")
        fn()
    print()
    if FAILURES:
        print(f"{len(FAILURES)} disagreement(s):")
        for f_ in FAILURES:
            print("  -", f_)
        sys.exit(1)
    print("all results agree with the yaml expect values")


if __name__ == "__main__":
    main()
