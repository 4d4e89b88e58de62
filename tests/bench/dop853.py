#!/usr/bin/python3
"""scipy's side of the simulation benchmark (tests/bench/simulation.cpp runs this script).

    /usr/bin/python3 tests/bench/dop853.py REFERENCE OUT [--quick]

REFERENCE (written by simulation_bench) gives, for each scene, its parameters, the start state,
the end time, the tolerances to time and the reference end state (50-digit integration or
closed form). For each scene and tolerance this script times
scipy.integrate.solve_ivp(method='DOP853', rtol=tol, atol=tol) on a right-hand side written by
hand in numpy (the same physics as the hand-written C++ one), and reports the wall time, the
number of right-hand side evaluations and the largest absolute error of the end state against
the reference. It also cross-checks the reference: DOP853 at rtol = atol = 1e-14, and mpmath
(odefun, a Taylor-series integrator at 20 digits; mpmath.quad for the sliding rod's time to
state 2) unless --quick.

OUT gets one line per result:
    wp SCENE TOL SECONDS NFEV ERROR
    check SCENE WHAT DIFFERENCE SECONDS
"""
import math
import statistics
import sys
import time

import mpmath
import numpy as np
from scipy.integrate import solve_ivp


# ---------------------------------------------------------------- the physics, by hand

def double_pendulum(p):
    """Two uniform bars, bar 1 (m1, L1) pinned at its end O, bar 2 (m2, L2) pinned to bar 1's
    free end; th1, th2 from the downward vertical, d = th1 - th2. Lagrange's equations:
        [(m1/3 + m2) L1^2        m2 L1 L2/2 cos d] [th1''] = [f1]
        [m2 L1 L2/2 cos d        m2 L2^2/3       ] [th2'']   [f2]
        f1 = -m2 L1 L2/2 sin d w2^2 - (m1/2 + m2) g L1 sin th1
        f2 =  m2 L1 L2/2 sin d w1^2 - m2 g L2/2 sin th2
    solved by Cramer's rule."""
    m1, L1, m2, L2, g = p["m1"], p["L1"], p["m2"], p["L2"], p["g"]
    M11 = (m1 / 3 + m2) * L1 * L1
    M22 = m2 * L2 * L2 / 3
    k = m2 * L1 * L2 / 2
    G1 = (m1 / 2 + m2) * g * L1
    G2 = m2 * g * L2 / 2

    def rhs(t, y):
        th1, th2, w1, w2 = y
        d = th1 - th2
        M12 = k * np.cos(d)
        s = k * np.sin(d)
        f1 = -s * w2 * w2 - G1 * np.sin(th1)
        f2 = s * w1 * w1 - G2 * np.sin(th2)
        det = M11 * M22 - M12 * M12
        return np.array([w1, w2, (M22 * f1 - M12 * f2) / det, (M11 * f2 - M12 * f1) / det])

    return rhs


def sliding_rod(p):
    """A uniform rod (m, l), its ends on a horizontal and a vertical track, theta from the
    horizontal: T = (1/2)(m l^2/3) theta'^2, V = -m g (l/2) sin theta, so
        theta'' = (m g l/2 cos theta)/(m l^2/3) = 3 g cos theta/(2 l)."""
    g, l = p["g"], p["l"]
    c = 3 * g / (2 * l)

    def rhs(t, y):
        return np.array([y[1], c * np.cos(y[0])])

    return rhs


# the same right-hand sides in mpmath, for odefun
def double_pendulum_mp(p):
    m1, L1, m2, L2, g = (mpmath.mpf(p[k]) for k in ("m1", "L1", "m2", "L2", "g"))

    def rhs(t, y):
        th1, th2, w1, w2 = y
        d = th1 - th2
        M11, M22, M12 = (m1 / 3 + m2) * L1**2, m2 * L2**2 / 3, m2 * L1 * L2 / 2 * mpmath.cos(d)
        s = m2 * L1 * L2 / 2 * mpmath.sin(d)
        f1 = -s * w2**2 - (m1 / 2 + m2) * g * L1 * mpmath.sin(th1)
        f2 = s * w1**2 - m2 * g * L2 / 2 * mpmath.sin(th2)
        det = M11 * M22 - M12**2
        return [w1, w2, (M22 * f1 - M12 * f2) / det, (M11 * f2 - M12 * f1) / det]

    return rhs


def sliding_rod_mp(p):
    c = 3 * mpmath.mpf(p["g"]) / (2 * mpmath.mpf(p["l"]))
    return lambda t, y: [y[1], c * mpmath.cos(y[0])]


SCENES = {"double_pendulum": (double_pendulum, double_pendulum_mp),
          "sliding_rod": (sliding_rod, sliding_rod_mp)}


# ---------------------------------------------------------------- reading the reference

def read_reference(path):
    """Blocks 'scene NAME' ... 'end': param NAME VALUE, y0 ..., t_end T, tols ..., ref ..."""
    scenes, cur = [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "scene":
                cur = {"name": w[1], "params": {}, "exact": {}}
            elif w[0] == "param":
                cur["params"][w[1]] = float(w[2])
                cur["exact"][w[1]] = w[3] if len(w) > 3 else w[2]
            elif w[0] == "y0":
                cur["y0"] = [float(v) for v in w[1:]]
            elif w[0] == "t_end":
                cur["t_end"] = float(w[1])
                cur["t_end_text"] = w[1]
            elif w[0] == "tols":
                cur["tols"] = [float(v) for v in w[1:]]
            elif w[0] == "ref":
                cur["ref_text"] = w[1:]
                cur["ref"] = [float(v) for v in w[1:]]
            elif w[0] == "end":
                scenes.append(cur)
    return scenes


def max_abs_error(y, ref):
    return max(abs(a - b) for a, b in zip(y, ref))


def solve(rhs, sc, tol):
    sol = solve_ivp(rhs, (0.0, sc["t_end"]), sc["y0"], method="DOP853", rtol=tol, atol=tol)
    if not sol.success:
        raise RuntimeError(f"{sc['name']}: DOP853 at tol {tol}: {sol.message}")
    return sol


def time_dop853(rhs, sc, tol, budget):
    """Median wall time of whole solve_ivp calls (at least 3, more while within budget)."""
    times = []
    sol = None
    while len(times) < 3 or (sum(times) < budget and len(times) < 50):
        t0 = time.perf_counter()
        sol = solve(rhs, sc, tol)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), sol


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quick = "--quick" in sys.argv
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    scenes = read_reference(args[0])
    out = open(args[1], "w")
    budget = 0.05 if quick else 0.3
    for sc in scenes:
        make, make_mp = SCENES[sc["name"]]
        rhs = make(sc["params"])
        for tol in sc["tols"]:
            sec, sol = time_dop853(rhs, sc, tol, budget)
            err = max_abs_error(sol.y[:, -1], sc["ref"])
            out.write(f"wp {sc['name']} {tol:g} {sec:.6e} {sol.nfev} {err:.6e}\n")
            print(f"{sc['name']}: DOP853 tol {tol:g}: {sec * 1e3:.2f} ms, {sol.nfev} evaluations, error {err:.3g}",
                  file=sys.stderr)
        # the reference cross-checked by DOP853 at its tightest
        t0 = time.perf_counter()
        sol = solve(rhs, sc, 1e-14)
        out.write(f"check {sc['name']} dop853_1e-14 {max_abs_error(sol.y[:, -1], sc['ref']):.6e} "
                  f"{time.perf_counter() - t0:.6e}\n")
        if quick:
            continue
        # ... and by mpmath: a Taylor-series integrator at 20 digits, from the same doubles
        mpmath.mp.dps = 20
        t0 = time.perf_counter()
        f = mpmath.odefun(make_mp(sc["params"]), 0, [mpmath.mpf(v) for v in sc["y0"]])
        y = f(mpmath.mpf(sc["t_end_text"]))
        mpmath.mp.dps = 40  # the difference itself, not rounded to 20 digits
        diff = max(abs(a - mpmath.mpf(b)) for a, b in zip(y, sc["ref_text"]))
        out.write(f"check {sc['name']} mpmath_odefun_20_digits {float(diff):.6e} {time.perf_counter() - t0:.6e}\n")
        if sc["name"] == "sliding_rod":
            # t2 = sqrt(l/(3 g)) * integral from 0 to theta2 of dtheta/sqrt(sin theta), at 30 digits
            # from the exact parameters (energy: theta'^2 = 3 g sin theta / l)
            mpmath.mp.dps = 30
            e = sc["exact"]
            g, l, th2 = mpmath.mpf(e["g"]), mpmath.mpf(e["l"]), mpmath.mpf(e["theta2"])
            t2 = mpmath.sqrt(l / (3 * g)) * mpmath.quad(lambda th: 1 / mpmath.sqrt(mpmath.sin(th)), [0, th2])
            out.write(f"check {sc['name']} mpmath_quad_t2 {float(abs(t2 - mpmath.mpf(sc['t_end_text']))):.6e} 0\n")
    out.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
