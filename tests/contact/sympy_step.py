#!/usr/bin/env python3
"""Independent oracle: round body rolling into a step edge (plastic, rough impact),
then pivoting about the edge E up to the top. sympy for derivation, mpmath for numbers.

Usage:  python3 sympy_step.py              -> prints oracle JSON
        python3 sympy_step.py --check FILE -> compares FILE (same shape) at rel. tol 1e-6
Frame: E at origin, x right, y up, angles/omega counterclockwise positive.
"""
import json, sys
import sympy as sp
import mpmath as mp

mp.mp.dps = 30
m, r, h, k, g, v1 = sp.symbols('m r h k g v1', positive=True)
w2, al, Nn, Ft, psi, w = sp.symbols('omega2 alpha N F psi omega', real=True)
zx = lambda a, b: a[0] * b[1] - a[1] * b[0]          # z-component of a x b (2D)
perp = lambda a: sp.Matrix([-a[1], a[0]])            # z_hat x a
I = k * m * r**2                                      # centroidal inertia

# ---------- geometry at impact ----------
d = sp.sqrt(r**2 - (r - h)**2)
rG = sp.Matrix([-d, r - h])                           # E->G at impact
n = rG / r                                            # unit normal (E towards G)
t = perp(n)                                           # t = (-n_y, n_x)

# ---------- impact: angular momentum about E is conserved ----------
# Only the edge impulse is impulsive (weight, floor reaction finite) and it acts AT E,
# so its moment about E vanishes:  H_E(before) = H_E(after),  H_E = I*omega + rG x m*vG.
vG1 = sp.Matrix([v1, 0]); om1 = -v1 / r               # rolling: omega = -v/r
# after a rough plastic impact the material point at E is at rest: vG2 = omega2 z x rG
vG2 = w2 * perp(rG)
H1 = I * om1 + m * zx(rG, vG1)
H2 = I * w2 + m * zx(rG, vG2)
omega2 = sp.simplify(sp.solve(sp.Eq(H1, H2), w2)[0])
vG2 = vG2.subs(w2, omega2)
# kinetic energy T = 1/2 m vG^2 + 1/2 I omega^2
T1 = m * vG1.dot(vG1) / 2 + I * om1**2 / 2
T2 = sp.simplify(m * vG2.dot(vG2) / 2 + I * omega2**2 / 2)
T_lost = sp.simplify(T1 - T2)
# linear impulse-momentum:  J = m (vG2 - vG1)
J = m * (vG2 - vG1)
Jn, Jt = sp.simplify(J.dot(n)), sp.simplify(J.dot(t))
# consistency: angular impulse about G,  I (omega2 - omega1) = (E - G) x J
assert sp.simplify(I * (omega2 - om1) - zx(-rG, J)) == 0

# ---------- pivoting about E: Newton-Euler at general angle psi ----------
# psi = angle of E->G above the horizontal (G on the left of E): G = r(-cos psi, sin psi)
rP = r * sp.Matrix([-sp.cos(psi), sp.sin(psi)])
nP = rP / r; tP = perp(nP)
# E fixed, body rigid: aG = alpha z x rG - omega^2 rG
aG = al * perp(rP) - w**2 * rP
Fe = Nn * nP + Ft * tP                                # edge force on the body
# Newton: m aG = Fe + m g_vec ;  Euler about G: I alpha = (E - G) x Fe
sol = sp.solve([*(m * aG - Fe - sp.Matrix([0, -m * g])), I * al - zx(-rP, Fe)],
               [al, Nn, Ft], dict=True)[0]
alphaP, NP, FP = (sp.simplify(sol[s]) for s in (al, Nn, Ft))
psi0 = sp.asin((r - h) / r)
assert sp.simplify((rP.subs(psi, psi0) - rG).applyfunc(lambda e: sp.simplify(e))) == sp.zeros(2, 1)
N2 = NP.subs({psi: psi0, w: omega2})
F2 = FP.subs({psi: psi0, w: omega2})
# ---------- energy while pivoting (contact point at rest: edge force does no work) ----------
# 1/2 (I + m r^2) omega^2 + m g r sin(psi) = const
Ip = I + m * r**2
E0 = Ip * omega2**2 / 2 + m * g * (r - h)
omega_sq = sp.simplify((2 * (E0 - m * g * r * sp.sin(psi)) / Ip))   # omega^2(psi)
omega_top = -sp.sqrt(omega_sq.subs(psi, sp.pi / 2))                 # still clockwise
vG_top = r * sp.sqrt(omega_sq.subs(psi, sp.pi / 2))
N_top = NP.subs({psi: sp.pi / 2, w: -sp.sqrt(omega_sq.subs(psi, sp.pi / 2))})
Npath = NP.subs(w**2, omega_sq)                      # N along the path, as function of psi
# thresholds in v1: omega_top = 0  and  N2 = 0
_pos = lambda roots: [s for s in roots if s.subs({r: 1, h: sp.S.Half, k: 1, g: 1}) > 0][0]  # h < r
v1_min = _pos(sp.solve(sp.Eq(omega_sq.subs(psi, sp.pi / 2), 0), v1))
v1_max = _pos(sp.solve(sp.Eq(N2, 0), v1))


def num(expr, sub):
    return mp.mpf(str(sp.N(expr.subs(sub), 40)))


def n_min(sub):
    """min of N over psi in [psi0, pi/2]: fine grid, then golden-section refinement."""
    f = sp.lambdify(psi, Npath.subs(sub), 'mpmath')
    a, b = num(psi0, sub), mp.pi / 2
    M = 4000
    xs = [a + (b - a) * i / M for i in range(M + 1)]
    i = min(range(M + 1), key=lambda j: f(xs[j]))
    lo, hi = xs[max(i - 1, 0)], xs[min(i + 1, M)]
    gr = (mp.sqrt(5) - 1) / 2
    for _ in range(120):
        c, e = hi - gr * (hi - lo), lo + gr * (hi - lo)
        if f(c) <= f(e): hi = e
        else: lo = c
    return min(f(xs[i]), f((lo + hi) / 2), f(a), f(b))


def rk4_top(sub):
    """2nd check: integrate psi'' = -alpha(psi) (omega = -psi') from Newton-Euler, with psi as
    independent variable: du/dpsi = psi''/u, u = psi' > 0. Hand-written RK4 in mpmath."""
    acc = sp.lambdify(psi, (-alphaP).subs(sub), 'mpmath')   # alpha is free of omega
    u, p = -num(omega2, sub), num(psi0, sub)
    steps = 4000; hs = (mp.pi / 2 - p) / steps
    fu = lambda p_, u_: acc(p_) / u_
    for _ in range(steps):
        k1 = fu(p, u); k2 = fu(p + hs / 2, u + hs * k1 / 2)
        k3 = fu(p + hs / 2, u + hs * k2 / 2); k4 = fu(p + hs, u + hs * k3)
        u += hs * (k1 + 2 * k2 + 2 * k3 + k4) / 6; p += hs
    return -u


CASES = {"wheel": dict(m=8, r=sp.Rational(3, 10), h=sp.Rational(1, 10), v1=sp.Rational(8, 5), k=sp.Rational(1, 2)),
         "sphere": dict(m=2, r=sp.Rational(1, 10), h=sp.Rational(1, 50), v1=sp.Rational(9, 10), k=sp.Rational(2, 5)),
         "wheel_fast": dict(m=8, r=sp.Rational(3, 10), h=sp.Rational(1, 10), v1=2, k=sp.Rational(1, 2))}
G_ = sp.Rational(981, 100)


def oracle():
    out = {}
    for name, c in CASES.items():
        sub = {m: c["m"], r: c["r"], h: c["h"], v1: c["v1"], k: c["k"], g: G_}
        if name == "wheel_fast":
            res = {"omega2": num(omega2, sub), "N2": num(N2, sub)}
            assert res["N2"] < 0
        else:
            res = {key: num(e, sub) for key, e in dict(
                omega2=omega2, vG2=r * sp.Abs(omega2), T_lost=T_lost, Jn=Jn, Jt=Jt, N2=N2, F2=F2,
                omega_top=omega_top, vG_top=vG_top, N_top=N_top).items()}
            sub_v = {s: val for s, val in sub.items() if s is not v1}
            res["v1_min"] = num(v1_min, sub_v)
            res["v1_max"] = num(v1_max, sub_v)
            res["N_min"] = n_min(sub)
            assert res["N_min"] > 0 and res["omega2"] < 0 and res["omega_top"] < 0
            assert res["v1_min"] < c["v1"] < res["v1_max"]
            # past the top it rolls down the far side about E, the same N(psi) with psi beyond pi/2
            # (G = r(-cos psi, sin psi) now right of E), until the edge's push falls to zero:
            # the root of N(psi) = 0 in (pi/2, pi) — where the body lets go of the corner
            Nf = sp.lambdify(psi, Npath.subs(sub), "mpmath")
            mp.mp.dps = 40
            pl = mp.findroot(Nf, (mp.pi / 2 + mp.mpf('1e-6'), mp.pi - mp.mpf('1e-6')), solver='bisect')
            res["x_leave"] = num(-r * sp.cos(psi), {**sub, psi: sp.Float(str(pl), 40)})
            res["y_leave"] = num(r * sp.sin(psi), {**sub, psi: sp.Float(str(pl), 40)})
            wt = rk4_top(sub)
            assert abs(wt / res["omega_top"] - 1) < mp.mpf('1e-9'), (name, wt, res["omega_top"])
        out[name] = {kk: float(mp.nstr(vv, 15)) for kk, vv in res.items()}
    return out


def main():
    ref = oracle()
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        got = json.load(open(sys.argv[2]))
        bad = []
        for case, vals in got.items():
            for key, x in vals.items():
                y = ref.get(case, {}).get(key)
                if y is None or abs(x - y) > 1e-6 * abs(y) + 1e-12:
                    bad.append(f"{case}.{key}: got {x!r}, oracle {y!r}")
        for b in bad: print("MISMATCH", b)
        print("OK" if not bad else f"{len(bad)} mismatch(es)")
        sys.exit(1 if bad else 0)
    print(json.dumps(ref, sort_keys=True, indent=1))


if __name__ == "__main__":
    main()
