#!/usr/bin/env python3
"""100-significant-digit references for the numerically hard scenes in tests/stability/.

Every value below is computed from a hand-derived formula (written out next to it and in the
scene's description), with the scene's exact decimal inputs (mpf('9.81'), exact fractions,
mp.pi) at 130 significant digits, and rounded to 100 significant digits. The formulas are
arranged so that no catastrophic cancellation happens even in the working precision
(1 - cos x is written 2 sin^2(x/2), a difference of cosines as a product of sines, a
difference of squares as a product, an energy loss through the effective mass), so the 100
printed digits are far inside the 130 carried.

    python3 tests/stability/references.py            print every reference
    python3 tests/stability/references.py --yaml     print them as `expect:` value lines
    python3 tests/stability/references.py --check    check that the scenes claim exactly these
                                                     values (100 significant digits) for every
                                                     find, and nothing else; exit 1 otherwise
"""

import os
import re
import sys
from fractions import Fraction

from mpmath import mp, mpf, sqrt, sin, cos, asin, pi

mp.dps = 130

DIGITS = 100
HERE = os.path.dirname(os.path.abspath(__file__))


def D(s):
    """An exact decimal input, as written in the scene."""
    return mpf(s)


def diff(a, b):
    """a - b of two decimal inputs, formed exactly (as a fraction) before rounding to mpf."""
    q = Fraction(a) - Fraction(b)
    return mpf(q.numerator) / q.denominator


DEG = pi / 180

CASES = {}


def case(filename):
    def register(fn):
        CASES[filename] = fn
        return fn
    return register


# 1. Pinned bar released 2e-6 rad from its lowest position.
#    (m L^2/3) w^2 / 2 = m g (L/2)(1 - cos t0)  ->  w = sqrt(6 g / L) sin(t0/2), vB = L w.
@case("bar_release_near_bottom.yaml")
def _():
    L, g, t0 = D("0.9"), D("9.81"), D("2e-6")
    w = sqrt(6 * g / L) * sin(t0 / 2)
    return {"omega2": (w, "rad/s"), "vB2": (L * w, "m/s")}


# 2a. Rectangular plate a x b hung from the middle of its top edge, released 1e-6 rad from
#     the vertical. I_P = m (a^2 + 4 b^2)/12, drop of G = (b/2)(1 - cos t1):
#     w = 2 sin(t1/2) sqrt(6 g b / (a^2 + 4 b^2)), vG = (b/2) w.
@case("plate_swing_near_vertical.yaml")
def _():
    a, b, g, t1 = D("0.4"), D("0.3"), D("9.81"), D("1e-6")
    w = 2 * sin(t1 / 2) * sqrt(6 * g * b / (a**2 + 4 * b**2))
    return {"omega2": (w, "rad/s"), "vG2": (b / 2 * w, "m/s")}


# 2b. Pinned bar released at 30 deg, w asked at 30 deg - 1e-6 rad.
#     w^2 = 3 g (cos(t1 - d) - cos t1)/L with cos(t1 - d) - cos t1 = 2 sin(t1 - d/2) sin(d/2).
@case("pendulum_near_30deg.yaml")
def _():
    L, g, t1, d = D("0.9"), D("9.81"), 30 * DEG, D("1e-6")
    w = sqrt(6 * g * sin(t1 - d / 2) * sin(d / 2) / L)
    return {"omega2": (w, "rad/s"), "vB2": (L * w, "m/s")}


# 3. Rod on a floor and a wall, released from rest at the vertical, w asked at
#    theta = pi/2 - eps. (m l^2/6) w^2 = m g (l/2)(1 - sin(pi/2 - eps)) = m g l sin^2(eps/2):
#    |w| = sqrt(6 g / l) sin(eps/2); theta decreases. vA = l cos(eps) |w| (A slides out),
#    vB = -l sin(eps) |w| (B slides down).
@case("sliding_rod_near_vertical.yaml")
def _():
    l, g, eps = D("1.2"), D("9.81"), D("1e-6")
    w = sqrt(6 * g / l) * sin(eps / 2)
    return {"omega2": (-w, "rad/s"), "vA2": (l * cos(eps) * w, "m/s"),
            "vB2": (-l * sin(eps) * w, "m/s")}


# 4. Bullet of 1e-9 of the bar's mass embeds in a hanging bar (e = 0).
#    Effective mass of the bar at the hit point: I_O/d^2 = M L^2/(3 d^2);
#    m_eff = m (I_O/d^2)/(m + I_O/d^2); J = m_eff v0 (plastic); w = J d/I_O; v' = v0 - J/m;
#    pin impulse on the bar: R = M (L/2) w - J; loss = m_eff v0^2/2;
#    bullet's loss of kinetic energy = J (v0 + v')/2; bar's kinetic energy = I_O w^2/2.
@case("bullet_tiny_mass_ratio.yaml")
def _():
    M, m, L, v0, d = D("6"), D("6e-9"), D("1.5"), D("450"), D("1.2")
    IO = M * L**2 / 3
    Mq = IO / d**2
    meff = m * Mq / (m + Mq)
    J = meff * v0
    w = J * d / IO
    vb = v0 - J / m
    return {"omega": (w, "rad/s"), "v_bullet": (vb, "m/s"),
            "R_pin": (M * L / 2 * w - J, "N*s"),
            "lost": (meff * v0**2 / 2, "J"),
            "bullet_lost": (J * (v0 + vb) / 2, "J"),
            "T_bar": (IO * w**2 / 2, "J")}


# 5. Pendulum bob strikes a block 1e9 times heavier (e = 0.7).
#    v1 = sqrt(2 g l (1 - cos 60deg)) = sqrt(g l); J = (1 + e) m_eff v1, m_eff = m1 m2/(m1 + m2);
#    v_block = J/m2, v_ball = v1 - J/m1, rebound_defect = v_ball + e v1 = J/m1 - (1+e) v1 + ...
#    = m1 (1 + e) v1/(m1 + m2) (computed as (1 + e) v1 m1/(m1 + m2)); loss = (1 - e^2) m_eff v1^2/2;
#    rebound angle: 2 g l sin^2(phi3/2)*2 = v_ball^2 -> phi3 = -2 asin(|v_ball| / (2 sqrt(g l))).
@case("pendulum_hits_massive_block.yaml")
def _():
    m1, m2, l, e, g = D("1.2"), D("1.2e9"), D("1.5"), D("0.7"), D("9.81")
    v1 = sqrt(g * l)
    meff = m1 * m2 / (m1 + m2)
    J = (1 + e) * meff * v1
    vball = v1 - J / m1
    lost = (1 - e) * (1 + e) * meff * v1**2 / 2
    phi3 = -2 * asin(abs(vball) / (2 * sqrt(g * l)))
    return {"v1": (v1, "m/s"), "v_block": (J / m2, "m/s"), "v_ball": (vball, "m/s"),
            "rebound_defect": ((1 + e) * v1 * m1 / (m1 + m2), "m/s"),
            "lost": (lost, "J"), "dT": (lost, "J"), "phi3": (phi3 / DEG, "deg")}


# 6. Plastic impact (e = 0) of a puck on the end of a free rod.
#    Effective mass of the rod at its end along the normal: M/4 (1/M + (L/2)^2/(M L^2/12) = 4/M);
#    m_eff = m (M/4)/(m + M/4); J = m_eff v0; vG = J/M; w = (L/2) J/(M L^2/12) = 6 J/(M L);
#    v_puck = v0 - J/m; vA = vG - (L/2) w; separation speed 0; loss = m_eff v0^2/2.
@case("plastic_puck_on_rod.yaml")
def _():
    M, L, m, v0 = D("2"), D("1"), D("0.4"), D("8")
    meff = m * (M / 4) / (m + M / 4)
    J = meff * v0
    vG = J / M
    w = 6 * J / (M * L)
    return {"J": (J, "N*s"), "vG": (vG, "m/s"), "omega": (w, "rad/s"),
            "v_puck": (v0 - J / m, "m/s"), "vA": (vG - L / 2 * w, "m/s"),
            "sep": (mpf(0), "m/s"),
            "lost": (meff * v0**2 / 2, "J"), "dT": (meff * v0**2 / 2, "J")}


# 7. Perfectly elastic impact (e = 1) of a puck on a turnstile bar.
#    I = M L^2/12 about the pin, m_eff = m (I/b^2)/(m + I/b^2), J = 2 m_eff v0, w = J b/I,
#    v_puck = v0 - J/m; energy lost exactly 0; T after = m v0^2/2.
@case("elastic_turnstile.yaml")
def _():
    M, L, m, v0, b = D("4"), D("1.2"), D("0.3"), D("10"), D("0.45")
    I = M * L**2 / 12
    meff = m * (I / b**2) / (m + I / b**2)
    J = 2 * meff * v0
    return {"omega": (J * b / I, "rad/s"), "v_puck": (v0 - J / m, "m/s"),
            "lost": (mpf(0), "J"), "dT": (mpf(0), "J"),
            "T_after": (m * v0**2 / 2, "J")}


# 8. Nearly elastic impact, 1 - e = 1e-12, of a sphere on a hanging bar.
#    I_O = M L^2/3, m_eff = m (I_O/d^2)/(m + I_O/d^2), J = (1 + e) m_eff v1, w = J d/I_O,
#    v_sphere = v1 - J/m, R_pin = M (L/2) w - J, loss = (1 - e)(1 + e) m_eff v1^2/2.
@case("nearly_elastic_sphere_bar.yaml")
def _():
    M, L, m, v1, d, e = D("3"), D("1"), D("0.8"), D("5"), D("0.75"), D("0.999999999999")
    IO = M * L**2 / 3
    Mq = IO / d**2
    meff = m * Mq / (m + Mq)
    J = (1 + e) * meff * v1
    w = J * d / IO
    lost = (1 - e) * (1 + e) * meff * v1**2 / 2
    return {"omega": (w, "rad/s"), "v_sphere": (v1 - J / m, "m/s"),
            "R_pin": (M * L / 2 * w - J, "N*s"), "lost": (lost, "J"), "dT": (lost, "J")}


# 9. Blow at the centre of percussion, d = 1 m = 2L/3 with L = 1.5 m.
#    (m L^2/3) w = J d; vG = (L/2) w; R = m vG - J = J (3 d/(2 L) - 1) = 0 exactly; vP = d w.
@case("centre_of_percussion_numbers.yaml")
def _():
    m, L, d, J = D("5"), D("1.5"), D("1"), D("12")
    w = J * d / (m * L**2 / 3)
    vG = L / 2 * w
    R = J * (3 * d / (2 * L) - 1)        # = m vG - J, with 3 d/(2 L) = 1 exactly
    assert R == 0 and abs(m * vG - J) < mpf(10) ** -120
    return {"omega": (w, "rad/s"), "vG": (vG, "m/s"), "R_pin": (mpf(0), "N*s"),
            "vP": (d * w, "m/s")}


# 10. Block landing at v0 on a very stiff buffer spring, k = 5e10 N/m.
#     (1/2) m v^2 = (1/2) m v0^2 + m g x - (1/2) k x^2 = (k/2)(x_max - x)(x - x_min),
#     x_max,min = (m g +- sqrt(m^2 g^2 + k m v0^2))/k.
@case("stiff_buffer_spring.yaml")
def _():
    m, g, k, v0, x2 = D("2"), D("9.81"), D("5e10"), D("3"), D("1.8974058e-5")
    root = sqrt((m * g)**2 + k * m * v0**2)
    xmax = (m * g + root) / k
    xmin = -m * v0**2 / (k * xmax)        # product of the roots = -m v0^2/k
    v2 = sqrt(k / m * (xmax - x2) * (x2 - xmin))
    return {"x_max": (xmax, "m"), "v2": (v2, "m/s"), "F_max": (k * xmax, "N")}


# 11. Flywheel, parameters from 1e-12 to 1e12: I = 1e12 kg*m^2, M = 1e-12 N*m, t2 = 1e12 s.
#     alpha = M/I, w2 = w1 + alpha t2, theta2 = w1 t2 + alpha t2^2/2 (kinematics of constant
#     alpha), work = M theta2 (work of the constant couple) = T2 - T1.
@case("flywheel_extreme_scales.yaml")
def _():
    m, k, M, w1, t2 = D("1e12"), D("1"), D("1e-12"), D("1"), D("1e12")
    I = m * k**2
    alpha = M / I
    th2 = w1 * t2 + alpha * t2**2 / 2
    return {"omega2": (w1 + alpha * t2, "rad/s"), "theta2": (th2, "rad"),
            "work": (M * th2, "J")}


# 12. Clutch: two disks on one shaft, speeds 1000 and 999.999999 rad/s, engaged.
#     w = wB + I_A (wA - wB)/(I_A + I_B); lost = I_A I_B (wA - wB)^2 / (2 (I_A + I_B)).
@case("clutch_nearly_equal_speeds.yaml")
def _():
    mA, rA, mB, rB = D("5"), D("0.2"), D("3"), D("0.25")
    wA, wB = D("1000"), D("999.999999")
    IA, IB = mA * rA**2 / 2, mB * rB**2 / 2
    dw = diff("1000", "999.999999")              # = 1e-6 exactly
    return {"omega2": (wB + IA * dw / (IA + IB), "rad/s"),
            "lost": (IA * IB * dw**2 / (2 * (IA + IB)), "J")}


# 13. Linkage: bar AB pinned at A, bar BC pinned at B, C on the floor through A; released from
#     rest with AB vertical, asked at theta = pi/2 - eps. With r = beta_dot/theta_dot =
#     -a cos(theta)/(b cos(beta)), sin(beta) = -a sin(theta)/b:
#     T = (1/2) theta_dot^2 K, K = m1 a^2/3 + m2 (a^2 sin^2(theta) (1 - r/2)^2 + a^2 cos^2(theta)/4)
#     + m2 b^2 r^2/12, and T = (m1 + m2) g (a/2) (1 - cos eps) = (m1 + m2) g a sin^2(eps/2).
#     vC = -a sin(theta) theta_dot (1 - r).
@case("linkage_near_vertical.yaml")
def _():
    m1, a, m2, b, g, eps = D("3"), D("0.6"), D("5"), D("1"), D("9.81"), D("2e-6")
    sth, cth = cos(eps), sin(eps)                 # theta = pi/2 - eps
    sbe = -a * sth / b
    cbe = sqrt(1 - sbe**2)
    r = -a * cth / (b * cbe)
    K = m1 * a**2 / 3 + m2 * (a**2 * sth**2 * (1 - r / 2)**2 + a**2 * cth**2 / 4) \
        + m2 * b**2 * r**2 / 12
    w = -sqrt(2 * (m1 + m2) * g * a * sin(eps / 2)**2 / K)
    return {"omega_AB": (w, "rad/s"), "omega_BC": (r * w, "rad/s"),
            "vC": (-a * sth * w * (1 - r), "m/s")}


# 13b. Folded A-frame (two equal bars, both vertical) released from its dead point; opening
#      branch beta = -theta. T = (1/2) m a^2 theta_dot^2 (2/3 + 2 sin^2(theta)),
#      V = m g a sin(theta): theta_dot = -sqrt(6 g sin^2(eps/2)/(a (1 + 3 cos^2(eps)))),
#      beta_dot = -theta_dot, vC = 2 a cos(eps) |theta_dot|.
@case("aframe_from_dead_point.yaml")
def _():
    a, g, eps = D("0.6"), D("9.81"), D("2e-6")
    w = sqrt(6 * g * sin(eps / 2)**2 / (a * (1 + 3 * cos(eps)**2)))
    return {"omega_AB": (-w, "rad/s"), "omega_BC": (w, "rad/s"), "vC": (2 * a * cos(eps) * w, "m/s")}


# 14. Atwood machine whose masses differ by 1e-9 of their size (mA = 6.000000006 kg, mB = 6 kg).
#     v^2 = 2 (mA - mB) g d / (mA + mB + M/2), dm = mA - mB = 6e-9 kg exactly; omega = -v/r.
@case("atwood_tiny_imbalance.yaml")
def _():
    mB, dm, M, r, d, g = D("6"), D("6e-9"), D("4"), D("0.2"), D("0.5"), D("9.81")
    v = sqrt(2 * dm * g * d / (2 * mB + dm + M / 2))
    return {"vA2": (v, "m/s"), "omega2": (-v / r, "rad/s")}


# 15. Block on a vertical spring; stretch 0.05 m at state 1, 0.04999999995 m at state 2.
#     (1/2) m v^2 = (1/2) k (s1^2 - s2^2) - m g (s1 - s2) = (s1 - s2)((k/2)(s1 + s2) - m g).
@case("spring_nearly_equal_stretch.yaml")
def _():
    m, k, g, s1, s2 = D("2"), D("800"), D("9.81"), D("0.05"), D("0.04999999995")
    ds = diff("0.05", "0.04999999995")          # = 5e-11 exactly
    v = sqrt(2 * ds * (k / 2 * (s1 + s2) - m * g) / m)
    return {"v2": (-v, "m/s"), "vy2": (v, "m/s")}


# 16. Disk rolling down an incline of 1e-6 rad: v^2 = 4 g d sin(beta)/3, omega = -v/r.
@case("disk_rolling_tiny_incline.yaml")
def _():
    r, g, beta, d = D("0.15"), D("9.81"), D("1e-6"), D("3")
    v = sqrt(4 * g * d * sin(beta) / 3)
    return {"v2": (v, "m/s"), "omega2": (-v / r, "rad/s")}


# 17a. Disk thrown almost rolling: slip speed s0 = v0 + r omega0 = 5e-9 m/s.
#      Slip decreases at 3 mu g (dv/dt = -mu g, r domega/dt = -2 mu g): t2 = s0/(3 mu g),
#      v2 = v0 - mu g t2 = v0 - s0/3, omega2 = -v2/r; energy lost = mu m g * (slide) =
#      m s0^2/6 (= m_eff s0^2/2, m_eff = m/3).
@case("disk_almost_rolling.yaml")
def _():
    m, r, v0, w0, mu, g = D("3"), D("0.15"), D("5"), D("-33.3333333"), D("0.15"), D("9.81")
    s0 = diff("5", Fraction("0.15") * Fraction("33.3333333"))   # v0 + r omega0 = 5e-9 exactly
    t2 = s0 / (3 * mu * g)
    v2 = v0 - s0 / 3
    return {"t2": (t2, "s"), "v2": (v2, "m/s"), "omega2": (-v2 / r, "rad/s"),
            "lost": (m * s0**2 / 6, "J")}


# 17b. US customary: square plate hinged at a corner, released 1e-4 deg from its lowest position.
#      I_P = 2 m a^2/3, drop of G = (a/sqrt 2)(1 - cos phi0):
#      w = sqrt(3 sqrt(2) g / a) sin(phi0/2), vG = (a/sqrt 2) w.
@case("us_plate_tiny_angle.yaml")
def _():
    a, g, phi0 = D("18") / 12, D("32.2"), D("1e-4") * DEG   # a in ft
    w = sqrt(3 * sqrt(2) * g / a) * sin(phi0 / 2)
    return {"omega2": (w, "rad/s"), "vG2": (a / sqrt(2) * w, "ft/s")}


# 17c. Spinning frame whose balls move in by 1e-9 of their radius (angular momentum conserved).
#      I(s) = m_hub k^2 + 2 m_b s^2; w2 = w1 I(s1)/I(s2);
#      T2 - T1 = (1/2) H (w2 - w1) = H w1 m_b (s1 - s2)(s1 + s2)/I(s2), H = I(s1) w1.
@case("spinning_frame_tiny_move.yaml")
def _():
    mh, kh, mb = D("10"), D("0.2"), D("2")
    s1, s2 = D("0.6"), D("0.5999999994")
    rpm = 2 * pi / 60
    n1 = 60 * rpm
    I1, I2 = mh * kh**2 + 2 * mb * s1**2, mh * kh**2 + 2 * mb * s2**2
    w2 = n1 * I1 / I2
    H = I1 * n1
    return {"omega2": (w2 / rpm, "rpm"),
            "work": (H * n1 * mb * diff("0.6", "0.5999999994") * (s1 + s2) / I2, "J")}


# ---------------------------------------------------------------------------------------------

def sig(x, n=DIGITS):
    """x rounded to n significant digits, as a decimal string (fixed or with an exponent)."""
    if x == 0:
        return "0"
    sign = "-" if x < 0 else ""
    x = abs(x)
    e = int(mp.floor(mp.log10(x)))
    scaled = x * mpf(10) ** (n - 1 - e)
    while scaled >= mpf(10) ** n:
        e += 1
        scaled /= 10
    while scaled < mpf(10) ** (n - 1):
        e -= 1
        scaled *= 10
    frac = scaled - mp.floor(scaled)
    if abs(frac - mpf("0.5")) < mpf(10) ** -20:
        raise SystemExit("rounding at digit %d is too close to a tie" % n)
    q = int(mp.nint(scaled))
    if q == 10 ** n:
        q //= 10
        e += 1
    digits = str(q)
    assert len(digits) == n
    if 0 <= e < n - 1:
        body = digits[:e + 1] + "." + digits[e + 1:]
    elif -5 <= e < 0:
        body = "0." + "0" * (-e - 1) + digits
    else:
        body = digits[0] + "." + digits[1:] + "e" + str(e)
    return sign + body


def significant_digits(text):
    """Number of significant digits of a decimal string (leading zeros do not count)."""
    mant = re.split("[eE]", text.lstrip("+-"))[0].replace(".", "")
    return len(mant.lstrip("0")) if mant.strip("0") else 0


def references():
    return {f: fn() for f, fn in CASES.items()}


def check():
    import yaml
    bad = 0
    refs = references()
    files = sorted(f for f in os.listdir(HERE) if f.endswith(".yaml"))
    for f in files:
        if f not in refs:
            print("%s: no reference computed for this scene" % f)
            bad += 1
    for f, vals in refs.items():
        path = os.path.join(HERE, f)
        if not os.path.exists(path):
            print("%s: scene file missing" % f)
            bad += 1
            continue
        with open(path) as fh:
            scene = yaml.safe_load(fh)
        finds = scene.get("find", {}) or {}
        expect = scene.get("expect", {}) or {}
        for name in sorted(set(finds) | set(expect) | set(vals)):
            where = "%s: %s" % (f, name)
            if name not in vals:
                print("%s: no reference" % where)
                bad += 1
                continue
            if name not in finds or name not in expect or "value" not in expect[name]:
                print("%s: not found and claimed in the scene" % where)
                bad += 1
                continue
            x, unit = vals[name]
            claimed = str(expect[name]["value"]).strip()
            num, _, cunit = claimed.partition(" ")
            find_unit = finds[name].get("unit") if isinstance(finds[name], dict) else None
            want = sig(x)
            if cunit.strip() != unit or find_unit != unit:
                print("%s: unit %r (find: %r), reference unit %r" % (where, cunit, find_unit, unit))
                bad += 1
            elif x == 0:
                if num != "0":
                    print("%s: claims %s, reference is exactly 0" % (where, num))
                    bad += 1
            elif significant_digits(num) != DIGITS:
                print("%s: claim has %d significant digits, not %d"
                      % (where, significant_digits(num), DIGITS))
                bad += 1
            elif mpf(num) != mpf(want):
                print("%s: claims %s\n    reference %s" % (where, num, want))
                bad += 1
    n = sum(len(v) for v in refs.values())
    print("%d references in %d scenes: %s" % (n, len(refs), "all match" if not bad else
                                               "%d problem(s)" % bad))
    return 0 if bad == 0 else 1


def main(argv):
    if "--check" in argv:
        return check()
    as_yaml = "--yaml" in argv
    for f, vals in references().items():
        print(f)
        for name, (x, unit) in vals.items():
            if as_yaml:
                print('  %s: {value: "%s %s"}' % (name, sig(x), unit))
            else:
                print("  %s = %s %s" % (name, sig(x), unit))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
