"""Whole `kinergy solve` processes, timed start to finish (tests/bench/run_solve.sh):

1. against a sympy.physics.mechanics script that derives, solves and evaluates the same textbook
   problem (the sliding rod: tests/bench/sympy_sliding_rod.py), side by side, median of repeats;
2. an N-link pendulum's energy problem, N = 2 ... 16: N slender rods pinned in a chain, released
   from rest with every link horizontal; state 2 is where the chain is T_LEG s later (its angles and
   the rates of links 2 ... N, from an RK4 integration of the equations of motion written out by
   hand below, in numpy), so that kinergy's confirmation by simulation can reach it; link 1's rate
   asked. Each answer is checked against mpmath (the energy equation written out by hand below, a
   quadratic in link 1's rate) and against the integration's own link-1 rate.

Writes the markdown report (default docs/solve_scaling.md): every target's row, met or not, with
the command, date and machine.
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from mpmath import mp, mpf, cos, sin, sqrt

mp.dps = 40
M, L, G = mpf(2), mpf("0.5"), mpf("9.81")


T_LEG = 0.2  # s from the release to state 2


def nlink_motion(n, steps=8000):
    """Angles and rates of the chain T_LEG s after its release, by classical RK4 in doubles.
    G_i = sum_{j<i} L e(th_j) + (L/2) e(th_i): with c_ij = 1 (j < i), 1/2 (j = i), 0 (j > i) and
    A = m L^2 c^T c, the mass matrix is M_jk = A_jk cos(th_j - th_k) + delta_jk m L^2/12 and
    Lagrange's equations read M th'' = -sum_k A_jk sin(th_j - th_k) w_k^2 - m g L cos(th_j) sum_i c_ij."""
    c = np.tril(np.ones((n, n)), -1) + 0.5 * np.eye(n)
    A = float(M * L * L) * c.T @ c
    load = float(M * G * L) * c.sum(axis=0)

    def rhs(y):
        th, w = y[:n], y[n:]
        d = th[:, None] - th[None, :]
        mass = A * np.cos(d) + np.eye(n) * float(M * L * L) / 12
        return np.concatenate([w, np.linalg.solve(mass, -(A * np.sin(d)) @ (w * w) - load * np.cos(th))])

    y, h = np.zeros(2 * n), T_LEG / steps
    for _ in range(steps):
        k1 = rhs(y)
        k2 = rhs(y + h / 2 * k1)
        k3 = rhs(y + h / 2 * k2)
        k4 = rhs(y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return [float(v) for v in y[:n]], [float(v) for v in y[n:]]


def state2(n):
    """State 2 (angles and rates as the scene writes them), checked: halving the step moves it by < 1e-11."""
    th, w = nlink_motion(n)
    th_c, w_c = nlink_motion(n, 4000)
    err = max(abs(a - b) for a, b in zip(th + w, th_c + w_c))
    if err > 1e-11:
        sys.exit(f"N = {n}: the RK4 reference moved by {err:.1e} when its step was halved")
    return th, w


def nlink_scene(n, th, w):
    s = [f"title: {n}-link pendulum released horizontal, link 1's rate at a given position",
         "parameters: {m: 2 kg, L: 0.5 m, g: 9.81 m/s^2}", "points: {O: [0, 0]}", "coordinates:"]
    s += [f"  th{i}: rad" for i in range(1, n + 1)]
    s.append("bodies:")
    for i in range(1, n + 1):
        x = " + ".join([f"L*cos(th{j})" for j in range(1, i)] + [f"L/2*cos(th{i})"])
        y = " + ".join([f"L*sin(th{j})" for j in range(1, i)] + [f"L/2*sin(th{i})"])
        s += [f"  link{i}:", "    mass: m", "    inertia: {slender_rod: L}", f"    position: [{x}, {y}]",
              f"    angle: th{i}", "    points: {O: [-L/2, 0], B: [L/2, 0]}"]
    s += ["effects:", "  gravity: {g: g}", "  pin1: {pin: [O, link1.O]}"]
    s += [f"  pin{i}: {{pin: [link{i - 1}.B, link{i}.O]}}" for i in range(2, n + 1)]
    s.append("states:")
    s.append("  1: {" + ", ".join(f"th{i}: 0, th{i}_dot: 0" for i in range(1, n + 1)) + "}")
    parts = []
    for i in range(1, n + 1):
        parts.append(f"th{i}: {th[i - 1]!r} rad")
        if i > 1:
            parts.append(f"th{i}_dot: {w[i - 1]!r} rad/s")
    s.append("  2: {" + ", ".join(parts) + "}")
    s += ["analyses:", "  - energy: {from: 1, to: 2}", "find:", "  w1: {value: th1_dot@2, unit: rad/s, root: negative}"]
    return "\n".join(s) + "\n"


def nlink_roots(n, th_text, w_text):
    """Both roots w1 of T2 + V2 = T1 + V1 = 0 (released from rest, every link horizontal: V1 = 0).
    v_Gi = sum_{j<i} L w_j (-sin th_j, cos th_j) + (L/2) w_i (-sin th_i, cos th_i);
    T = sum (1/2) m |v_Gi|^2 + (1/2)(m L^2/12) w_i^2;  V = sum m g y_Gi."""
    th = [mpf(repr(v)) for v in th_text]
    rates = [mpf(repr(v)) for v in w_text]

    def energy(w1):
        w = [w1] + rates[1:]
        T, V = mpf(0), mpf(0)
        for i in range(n):
            vx = sum(-L * w[j] * sin(th[j]) for j in range(i)) - L / 2 * w[i] * sin(th[i])
            vy = sum(L * w[j] * cos(th[j]) for j in range(i)) + L / 2 * w[i] * cos(th[i])
            y = sum(L * sin(th[j]) for j in range(i)) + L / 2 * sin(th[i])
            T += M * (vx**2 + vy**2) / 2 + M * L**2 / 12 * w[i] ** 2 / 2
            V += M * G * y
        return T + V

    # a quadratic in w1: its coefficients from three values
    e0, e1, em = energy(mpf(0)), energy(mpf(1)), energy(mpf(-1))
    a = (e1 + em) / 2 - e0
    b = (e1 - em) / 2
    c = e0
    d = sqrt(b * b - 4 * a * c)
    return [(-b + d) / (2 * a), (-b - d) / (2 * a)]


def timed(cmd, repeats, timeout):
    """Median wall-clock seconds of `repeats` runs of cmd, its last stdout; None on timeout."""
    times, out = [], ""
    for _ in range(repeats):
        t0 = time.perf_counter()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, ""
        times.append(time.perf_counter() - t0)
        if p.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{p.stdout}{p.stderr}")
        out = p.stdout
    return statistics.median(times), out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kinergy", default="build-bench/kinergy")
    ap.add_argument("--python", default="/usr/bin/python3")
    ap.add_argument("--out", default="docs/solve_scaling.md")
    ap.add_argument("--max-n", type=int, default=16)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--command", default="bash tests/bench/run_solve.sh")
    args = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    kin = os.path.abspath(args.kinergy)
    rows = []

    # 1. the whole process against sympy's, side by side (interleaved, so that load falls on both)
    rod = os.path.join(root, "derivations/energy/sliding_rod.yaml")
    script = os.path.join(here, "sympy_sliding_rod.py")
    tk, ts = [], []
    for _ in range(args.repeats):
        t, kout = timed([kin, "solve", rod, "--json"], 1, args.timeout)
        tk.append(t)
        t, sout = timed([args.python, script], 1, args.timeout)
        ts.append(t)
    k_med, s_med = statistics.median(tk), statistics.median(ts)
    kval = json.loads(kout)["results"][0]["value"]
    sval = sout.strip()
    agree = abs(float(kval) - float(sval)) <= 1e-13 * abs(float(sval))
    ratio = s_med / k_med
    rows.append(("whole `kinergy solve` ≥ 50× faster than a sympy.physics.mechanics script (sliding rod, whole processes)",
                 f"kinergy {k_med * 1e3:.1f} ms, sympy {s_med * 1e3:.0f} ms: {ratio:.0f}× (values {kval} and {sval}{'' if agree else ', DISAGREE'})",
                 ratio >= 50 and agree))

    # 2. the N-link energy problem
    table = []
    n16 = None
    with tempfile.TemporaryDirectory() as tmp:
        for n in range(2, args.max_n + 1):
            path = os.path.join(tmp, f"nlink{n}.yaml")
            th, w = state2(n)
            with open(path, "w") as f:
                f.write(nlink_scene(n, th, w))
            t, out = timed([kin, "solve", path, "--json"], 1, args.timeout)
            if t is not None and t < 2:
                t, out = timed([kin, "solve", path, "--json"], 3, args.timeout)
            if t is None:
                table.append((n, None, "—", "—"))
                print(f"N = {n}: over {args.timeout:.0f} s", file=sys.stderr)
                break
            value = json.loads(out)["results"][0]["value"]
            roots = nlink_roots(n, th, w)
            # the root kinergy gives is mpmath's, and the one the motion reaches (RK4's link-1 rate)
            ok = any(abs(mpf(value) - r) <= mpf(10) ** -12 * abs(r) for r in roots) and abs(float(value) - w[0]) <= 1e-9 * abs(w[0])
            table.append((n, t, value, "yes" if ok else "**no** (" + ", ".join(mp.nstr(r, 15) for r in roots) + ")"))
            print(f"N = {n}: {t:.3f} s, w1 = {value}, mpmath agrees: {ok}", file=sys.stderr)
            if n == 16:
                n16 = (t, ok)
    rows.append(("the N-link energy problem at N = 16 solved in under 10 s (whole process)",
                 "not reached" if n16 is None else f"{n16[0]:.2f} s" + ("" if n16[1] else ", value DISAGREES with mpmath"),
                 n16 is not None and n16[0] < 10 and n16[1]))
    # growth: the exponent of t ~ N^k between the last two measured N at least 4 apart
    done = [(n, t) for n, t, _, _ in table if t is not None]
    growth = ""
    if len(done) >= 5:
        import math
        (n_a, t_a), (n_b, t_b) = done[len(done) // 2], done[-1]
        k = math.log(t_b / t_a) / math.log(n_b / n_a)
        growth = f"Between N = {n_a} and N = {n_b} the time grows as N^{k:.1f}."

    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    md = ["# Whole solves: against a sympy script, and as the scene grows", "",
          f"Generated by `{args.command}` (tests/bench/solve_scaling.py, tests/bench/sympy_sliding_rod.py); do not edit by hand.",
          f"Run on {datetime.date.today().isoformat()}; machine: {os.cpu_count()} cores, {platform.machine()}, {cpu}; "
          f"Python {platform.python_version()}.", "",
          "## Targets", "", "| target | measured | met |", "|---|---|---|"]
    for what, measured, met in rows:
        md.append(f"| {what} | {measured} | {'yes' if met else '**no**'} |")
    md += ["", "Every time is a whole process, start to finish, wall clock: the kinergy CLI (Release) and",
           "`python3 tests/bench/sympy_sliding_rod.py` (frames, points, a rigid body, T and V by",
           "sympy.physics.mechanics, the energy equation solved by `sympy.solve`, the value by `sympy.N`),",
           f"alternated, median of {args.repeats}.", "",
           "## The N-link pendulum's energy problem", "",
           "N slender rods (m = 2 kg, L = 0.5 m) pinned in a chain, released from rest with every link",
           f"horizontal; state 2 is where the chain is {T_LEG} s later — every angle and the rates of links",
           "2 … N, from an RK4 integration in numpy of the equations of motion written out by hand",
           "(halving its step moves them by less than 1e-11) — so that the default confirmation by",
           "simulation reaches it; link 1's rate is asked (`root: negative`: the chain falls). `kinergy solve --json`, whole process, with",
           "confirmation on; the value is checked against mpmath (one of the two roots of the energy",
           "equation, a quadratic in link 1's rate, to 12 digits) and against the integration's link-1",
           f"rate (to 1e-9). Each N at most {args.timeout:.0f} s.", "",
           "| N | time (s) | w1 (rad/s) | agrees with mpmath |", "|---:|---:|---:|---|"]
    for n, t, value, ok in table:
        md.append(f"| {n} | {'> %.0f' % args.timeout if t is None else '%.3f' % t} | {value} | {ok} |")
    if growth:
        md += ["", growth]
    with open(args.out, "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
