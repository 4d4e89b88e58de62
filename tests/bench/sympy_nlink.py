#!/usr/bin/python3
"""Derivation time of an N-link pendulum with sympy.physics.mechanics (issue 6, benchmark d).

The same system as tests/bench/derivation_time.cpp: N uniform slender rods (mass m, length L),
hanging in a chain from a fixed pin O, gravity g along -y, coordinates th1..thN the absolute
angles of the links from the x axis. Link i's frame A_i is N turned by th_i about z; its mass
centre G_i is L/2 along A_i.x from the joint P_{i-1} (P_0 = O), and the next joint P_i is L
along A_i.x; its central inertia about z is m L^2/12.

Timed cases, each in a fresh process (fork) with sympy's cache cleared before every repeat:
  tv        build the frames, points and bodies; T = sum of the bodies' kinetic energies,
            V = sum m g y_Gi
  lagrange  the same, L = T - V, LagrangesMethod(L, q).form_lagranges_equations(),
            mass_matrix and forcing
  kane      the frames, points and bodies with generalized speeds u_i = th_i', the gravity loads,
            KanesMethod(...).kanes_equations(bodies, loads), mass_matrix and forcing
The time of a case is the median over at least --min-repeats repeats (3) and --min-seconds
(0.2 s) in total, as long as the repeats fit in --max-seconds (120 s) per case: a case whose
first repeat does not finish within --max-seconds is a "timeout" (and the same method is not
tried at larger N: "skipped"); a slow case may end with fewer repeats than asked (the CSV says
how many). The child's CPU time (time.process_time) is measured beside the wall-clock time
(cpu_ms): on a shared machine other work stretches the wall-clock time, not that.

  /usr/bin/python3 tests/bench/sympy_nlink.py [--n 1,2,4,8,16] [--max-seconds 120]
      [--min-seconds 0.2] [--min-repeats 3] [--out FILE.csv] [--check-mass DERIVATION_TIME]

--check-mass EXE: before timing, compare kinergy's M(q) for N = 2 (printed by
`EXE --print-mass 2`) with sympy's mass matrices from both methods at a random configuration;
exit 1 when they differ.
"""

import argparse
import csv
import multiprocessing
import random
import statistics
import subprocess
import sys
import time

import sympy
import sympy.physics.mechanics as me
from sympy.core.cache import clear_cache

METHODS = ("tv", "lagrange", "kane")


def nlink(n, kane):
    """Frames, points and rigid bodies of the N-link pendulum.

    Lagrange: velocities in the rates th_i'. Kane: angular velocities set to the generalized
    speeds u_i (u_i = th_i'), so that every velocity is linear in the u_i."""
    m, L, g = sympy.symbols("m L g", positive=True)
    q = me.dynamicsymbols(" ".join(f"th{i}" for i in range(1, n + 1)), seq=True)
    u = me.dynamicsymbols(" ".join(f"u{i}" for i in range(1, n + 1)), seq=True)
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    joint = O  # P_{i-1}
    bodies, loads = [], []
    V = 0
    for i in range(n):
        A = me.ReferenceFrame(f"A{i + 1}")
        A.orient_axis(N, N.z, q[i])  # absolute angle th_i from N.x
        if kane:
            A.set_ang_vel(N, u[i] * N.z)
        G = joint.locatenew(f"G{i + 1}", L / 2 * A.x)
        G.v2pt_theory(joint, N, A)
        nxt = joint.locatenew(f"P{i + 1}", L * A.x)
        nxt.v2pt_theory(joint, N, A)
        # uniform slender rod: central inertia m L^2/12 about the axes across it
        I = me.inertia(A, 0, m * L**2 / 12, m * L**2 / 12)
        bodies.append(me.RigidBody(f"link{i + 1}", G, A, m, (I, G)))
        loads.append((G, -m * g * N.y))
        V += m * g * G.pos_from(O).dot(N.y)  # height of G_i above O
        joint = nxt
    return dict(N=N, q=q, u=u, bodies=bodies, loads=loads, V=V)


def case_tv(n):
    s = nlink(n, kane=False)
    T = me.kinetic_energy(s["N"], *s["bodies"])
    return T, s["V"]


def case_lagrange(n):
    s = nlink(n, kane=False)
    Lag = me.kinetic_energy(s["N"], *s["bodies"]) - s["V"]  # L = T - V
    LM = me.LagrangesMethod(Lag, s["q"])
    LM.form_lagranges_equations()
    return LM.mass_matrix, LM.forcing


def case_kane(n):
    s = nlink(n, kane=True)
    kd = [qi.diff(me.dynamicsymbols._t) - ui for qi, ui in zip(s["q"], s["u"])]  # th_i' = u_i
    KM = me.KanesMethod(s["N"], q_ind=s["q"], u_ind=s["u"], kd_eqs=kd)
    KM.kanes_equations(s["bodies"], s["loads"])
    return KM.mass_matrix, KM.forcing


CASES = {"tv": case_tv, "lagrange": case_lagrange, "kane": case_kane}


def one_repeat(method, n, conn):
    """Child process: one timed derivation from a clean cache; sends (wall, CPU) time in ms."""
    clear_cache()
    c0 = time.process_time()
    t0 = time.perf_counter()
    CASES[method](n)
    conn.send(((time.perf_counter() - t0) * 1000, (time.process_time() - c0) * 1000))
    conn.close()


def time_case(method, n, args):
    """(status, median wall ms or None, median CPU ms or None, repeats): repeats in fresh
    processes within the budget."""
    ctx = multiprocessing.get_context("fork")
    times, cpus = [], []
    start = time.monotonic()
    while len(times) < args.min_repeats or sum(times) < 1000 * args.min_seconds:
        remaining = args.max_seconds - (time.monotonic() - start)
        # a further repeat that would not fit in the budget is not started
        if times and max(times) / 1000 > remaining:
            break
        recv, send = ctx.Pipe(duplex=False)
        p = ctx.Process(target=one_repeat, args=(method, n, send))
        p.start()
        send.close()
        got = recv.poll(max(remaining, 0))
        if got:
            wall, cpu = recv.recv()
            times.append(wall)
            cpus.append(cpu)
        p.join(0 if not got else None)
        if p.is_alive():
            p.kill()
            p.join()
        if not got:
            break
    if not times:
        return "timeout", None, None, 0
    return "ok", statistics.median(times), statistics.median(cpus), len(times)


def check_mass(exe):
    """kinergy's M(q) and f(q, q') = Q - c for N = 2 against sympy's mass_matrix and forcing
    (Lagrange and Kane) at a random configuration and rates: like with like."""
    out = subprocess.run([exe, "--print-eom", "2"], check=True, capture_output=True, text=True).stdout
    rng = random.Random(20240606)
    vals = {"th1": rng.uniform(-3, 3), "th2": rng.uniform(-3, 3), "th1_dot": rng.uniform(-3, 3),
            "th2_dot": rng.uniform(-3, 3), "m": rng.uniform(0.5, 3), "L": rng.uniform(0.2, 2),
            "g": 9.81}
    names = {k: sympy.Symbol(k) for k in vals}
    K = sympy.zeros(2, 2)
    F = sympy.zeros(2, 1)
    for line in out.splitlines():
        parts = line.split(" ")
        if parts[0] == "M":
            K[int(parts[1]), int(parts[2])] = sympy.sympify(" ".join(parts[3:]), locals=names).subs({names[k]: v for k, v in vals.items()})
        else:
            F[int(parts[1]), 0] = sympy.sympify(" ".join(parts[2:]), locals=names).subs({names[k]: v for k, v in vals.items()})
    # the same symbols as nlink() makes: sympy symbols are equal by name and assumptions
    m, L, g = sympy.symbols("m L g", positive=True)
    th1, th2 = me.dynamicsymbols("th1 th2")
    u1, u2 = me.dynamicsymbols("u1 u2")
    t = me.dynamicsymbols._t
    sub = {th1.diff(t): vals["th1_dot"], th2.diff(t): vals["th2_dot"], u1: vals["th1_dot"], u2: vals["th2_dot"]}
    sub2 = {th1: vals["th1"], th2: vals["th2"], m: vals["m"], L: vals["L"], g: vals["g"]}
    worst = 0.0
    for method in ("lagrange", "kane"):
        M, f = CASES[method](2)
        Ms = M.subs(sub).subs(sub2).evalf()
        fs = f.subs(sub).subs(sub2).evalf()
        pairs = [(f"M[{i},{j}]", float(K[i, j]), float(Ms[i, j])) for i in range(2) for j in range(2)]
        pairs += [(f"f[{i}]", float(F[i, 0]), float(fs[i])) for i in range(2)]
        for what, a, b in pairs:
            rel = abs(a - b) / max(abs(b), 1e-300)
            worst = max(worst, rel)
            print(f"check {method}: {what} kinergy {a:.15g} sympy {b:.15g}", file=sys.stderr)
    at = ", ".join(f"{k} = {v:.6g}" for k, v in vals.items())
    ok = worst < 1e-12
    print(f"M and forcing check N=2 at {at}: worst relative difference {worst:.3g} "
          f"({'agree' if ok else 'DIFFER'})", file=sys.stderr)
    return ok, at, worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", default="1,2,4,8,16", help="comma-separated N list")
    ap.add_argument("--max-seconds", type=float, default=120.0, help="budget per case (N, method)")
    ap.add_argument("--min-seconds", type=float, default=0.2)
    ap.add_argument("--min-repeats", type=int, default=3)
    ap.add_argument("--out", help="CSV file (default: standard output)")
    ap.add_argument("--check-mass", metavar="DERIVATION_TIME", help="kinergy's derivation_time program")
    args = ap.parse_args()
    ns = [int(x) for x in args.n.split(",") if x]

    rows = []
    if args.check_mass:
        ok, at, worst = check_mass(args.check_mass)
        rows.append(dict(N=2, method="mass_check", status="agree" if ok else "differ", median_ms="",
                         cpu_ms="", repeats=0, note=f"worst relative difference {worst:.3g} at {at}"))
        if not ok:
            sys.exit(1)

    timed_out = set()
    for n in ns:
        for method in METHODS:
            if method in timed_out:
                status, ms, cpu, reps = "skipped", None, None, 0
            else:
                status, ms, cpu, reps = time_case(method, n, args)
                if status == "timeout":
                    timed_out.add(method)
            shown = f"{ms:.4g} ms (CPU {cpu:.4g} ms)" if ms is not None else status
            print(f"sympy N={n:<3} {method:<9} {shown} ({reps} repeats)", file=sys.stderr, flush=True)
            rows.append(dict(N=n, method=method, status=status,
                             median_ms="" if ms is None else f"{ms:.6g}",
                             cpu_ms="" if cpu is None else f"{cpu:.6g}", repeats=reps,
                             note=f"max_seconds={args.max_seconds:g}"))

    f = open(args.out, "w", newline="") if args.out else sys.stdout
    w = csv.DictWriter(f, fieldnames=["N", "method", "status", "median_ms", "cpu_ms", "repeats", "note"])
    w.writeheader()
    w.writerows(rows)
    if args.out:
        f.close()


if __name__ == "__main__":
    main()
