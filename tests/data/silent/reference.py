"""Reference values for the scenes of tests/data/silent/, derived by hand (energy, impulse-momentum)
with mpmath/sympy, independent of kinergy. Prints one line per result:
    SCENE_FILE RESULT_NAME VALUE
VALUE to 15 significant digits, in the unit the scene asks for (SI unless the scene says so);
lines whose name starts with '#' are diagnostics (not a result of the scene).
"""
import sympy as sp
from mpmath import mp, mpf, sqrt, sin, cos, asin, acos, pi, erf, exp, quad, findroot, degree

mp.dps = 50
OUT = []


def out(scene, name, value):
    OUT.append(f"{scene} {name} {mp.nstr(mpf(value), 15) if not isinstance(value, str) else value}")




# 1. spring_incline_couple(.yaml, _in.yaml) -------------------------------------------------
# Energy 1 -> 2 (both at rest), d = x2, delta = m g sin(beta)/k the stretch at x = 0:
#   M d/r + m g d sin(beta) - (1/2) k ((delta + d)^2 - delta^2) = 0  =>  M d/r - (1/2) k d^2 = 0.
d_, M_, r_, k_, m_, g_, b_ = sp.symbols("d M r k m g beta", positive=True)
delta = m_ * g_ * sp.sin(b_) / k_
eq = M_ * d_ / r_ + m_ * g_ * d_ * sp.sin(b_) - k_ / 2 * ((delta + d_) ** 2 - delta**2)
roots = sp.solve(sp.expand(eq), d_)
assert any(sp.simplify(rt - 2 * M_ / (k_ * r_)) == 0 for rt in roots)
m, r, beta, k, L0, M, g = mpf(20), mpf("0.25"), 20 * degree, mpf(150), mpf("0.6"), mpf(15), mpf("9.81")
d1 = 2 * M / (k * r)
for f in ("spring_incline_couple.yaml", "spring_incline_couple_in.yaml"):
    out(f, "d", d1)  # m
# friction needed for rolling, greatest at the stop: f = 4 M/(3 r); normal m g cos(beta)
out("spring_incline_couple.yaml", "#mu_needed", 4 * M / (3 * r) / (m * g * cos(beta)))


# 2./3. double pulley (US customary: ft, lb, slug; g = 32.2 ft/s^2) -------------------------
Wp, kp, ri, ro, Wc, Wb, mu, h, gu, s_after = (mpf(30), mpf("0.75"), mpf("0.5"), mpf(1), mpf(40), mpf(20),
                                              mpf("0.4"), mpf(3), mpf("32.2"), mpf(4))
Ip = Wp / gu * kp**2                      # pulley, slug*ft^2
Mall = Wc / gu * ri**2 + Ip + Wb / gu * ro**2   # T = (1/2) Mall omega^2 while the hub cord is taut
Mpb = Ip + Wb / gu * ro**2                 # after the landing: pulley + block
xb12 = ro / ri * h                         # block's travel while the cylinder falls h
U12 = Wc * h - mu * Wb * xb12              # ft*lb
w2 = sqrt(2 * U12 / Mall)
v2 = ro * w2
T_pb = Mpb * w2**2 / 2                     # kept through the landing (slack cord: no impulse)
s_coast = T_pb / (mu * Wb)
out("double_pulley_cord_off.yaml", "v2", v2)                  # ft/s
out("double_pulley_cord_off.yaml", "travel", xb12 + s_coast)  # ft
out("double_pulley_cord_off.yaml", "#coast_after_landing", s_coast)
# the same energy with the friction's sign reversed (friction helping the motion): the wrong answer
v2_wrong = ro * sqrt(2 * (Wc * h + mu * Wb * xb12) / Mall)
out("double_pulley_direction.yaml", "v2", v2)
out("double_pulley_direction.yaml", "v_after", v2)
out("double_pulley_direction.yaml", "#v2_if_friction_reversed", v2_wrong)
w3 = sqrt(w2**2 - 2 * mu * Wb * s_after / Mpb)
out("double_pulley_direction_after.yaml", "v3", ro * w3)      # ft/s


# 4. pendulum_strikes_block_forward.yaml ------------------------------------------------------
m1, m2, l, e, phi0, g = mpf("2.4"), mpf("1.5"), mpf("1.05"), mpf("0.49"), 78 * degree, mpf("9.81")
v1 = sqrt(2 * g * l * (1 - cos(phi0)))
# impact along x: m1 v1 = m1 u1 + m2 u2, u2 - u1 = e v1
u2 = m1 * (1 + e) * v1 / (m1 + m2)
u1 = (m1 - e * m2) * v1 / (m1 + m2)
assert abs(m1 * v1 - m1 * u1 - m2 * u2) < mpf(10) ** -40 and abs(u2 - u1 - e * v1) < mpf(10) ** -40
phi3 = acos(1 - u1**2 / (2 * g * l))  # u1 > 0: the ball swings forward, to the right
f = "pendulum_strikes_block_forward.yaml"
out(f, "v1", v1)
out(f, "v_block", u2)
out(f, "v_ball", u1)
out(f, "phi3", phi3 / degree)  # deg, positive
out(f, "#phi3_in_[-90deg,0]", "none")


# 5. rod_spring_max / rod_spring_abs / bar_plate_max ------------------------------------------
m, L, a, k, d0, th1, th2, g = mpf(2), mpf(1), mpf("0.8"), mpf(600), mpf("0.2"), -10 * degree, 60 * degree, mpf("9.81")
I_O = m * L**2 / 3
F = lambda th: k * max(d0 - a * sin(th), 0)           # upward push at A
th_s = asin(d0 / a)                                    # where A leaves the spring
# work by quadrature, split where the push switches, and checked against (1/2) k (d0 - a sin th1)^2
U_spring = quad(lambda th: F(th) * a * cos(th), [th1, th_s, th2])
assert abs(U_spring - k * (d0 - a * sin(th1)) ** 2 / 2) < mpf(10) ** -30
U_grav = -m * g * L / 2 * (sin(th2) - sin(th1))
w = sqrt(2 * (U_spring + U_grav) / I_O)
for f in ("rod_spring_max.yaml", "rod_spring_abs.yaml"):
    out(f, "omega2", w)
out("rod_spring_max.yaml", "#theta_leaves_spring_deg", th_s / degree)

m, L, k, c, g = mpf(3), mpf("1.2"), mpf(60), mpf("0.6"), mpf("9.81")
I_O = m * L**2 / 3
# theta below the horizontal; B = (L cos th, -L sin th); plate pushes B along +x with k max(c - L cos th, 0)
Tb = lambda th: m * g * L / 2 * sin(th) - k * max(c - L * cos(th), 0) ** 2 / 2
# check the plate's work by quadrature: F_x dx_B = k max(..) * (-L sin th) dth
th_c = acos(c / L)
Uq = quad(lambda th: k * max(c - L * cos(th), 0) * (-L * sin(th)), [0, th_c, pi / 2])
assert abs(Uq + k * c**2 / 2) < mpf(10) ** -30
w2b = sqrt(2 * Tb(pi / 2) / I_O)
th3 = findroot(Tb, (pi / 2 + mpf("0.01"), pi - mpf("0.01")), solver="anderson")
out("bar_plate_max.yaml", "omega2", w2b)
out("bar_plate_max.yaml", "theta3", th3 / degree)  # deg
# T > 0 on (0, th3): sample
assert all(Tb(th3 * i / 1000) > 0 for i in range(1, 1000))


# 6. linkage_unreachable.yaml ----------------------------------------------------------------
m1, m2, mC, r, l, g = mpf(3), mpf(5), mpf(2), mpf("0.3"), mpf("0.6"), mpf("9.81")
S = lambda th: sqrt(l**2 - r**2 * cos(th) ** 2)
V = lambda th: g * (m1 * r * sin(th) / 2 + m2 * (r * sin(th) + S(th) / 2) + mC * (r * sin(th) + S(th)))
T = lambda th: V(45 * degree) - V(th)  # kinetic energy at theta, from rest at 45 deg
f = "linkage_unreachable.yaml"
out(f, "#T_at_45deg_J", T(45 * degree))
out(f, "#T_at_90deg_J", T(90 * degree))
ths = [45 * degree + (108 * degree) * i / 10800 for i in range(10801)]
Tmin, thmin = min((T(t), t) for t in ths)
out(f, "#T_min_on_45..153deg_J", Tmin)
out(f, "#at_theta_deg", thmin / degree)
out(f, "#T_at_153deg_J_(energy_alone)", T(153 * degree))
dV = mp.diff(V, 45 * degree)
out(f, "#dV/dtheta_at_45deg_J", dV)  # > 0: it falls toward smaller theta (clockwise)
out(f, "#falls", "clockwise(theta_decreasing)")
out(f, "omega2", "not_reached")


# 7a. door_torsion_unstable.yaml ------------------------------------------------------------
m, L, kt, g = mpf(20), mpf(2), mpf(50), mpf("9.81")
Td = lambda th: m * g * L / 2 * (1 - cos(th)) - kt * th**2 / 2
assert m * g * L / 2 > kt and all(Td(pi / 2 * i / 1000) > 0 for i in range(1, 1001))
out("door_torsion_unstable.yaml", "omega2", sqrt(2 * Td(pi / 2) / (m * L**2 / 3)))

# 7b. wheel_step_least.yaml ---------------------------------------------------------------
m, r, h, g = mpf(8), mpf("0.3"), mpf("0.1"), mpf("9.81")
# (3/4) m v^2 = (3/4) m v0^2 - m g r (sin psi - sin psi0): least T at psi = 90 deg
out("wheel_step_least.yaml", "v0_min", sqrt(4 * g * h / 3))

# 7c. tiny_swing.yaml --------------------------------------------------------------------
l, g, th0 = mpf(1), mpf("9.81"), mpf("1e-6")
vb = 2 * sqrt(g * l) * sin(th0 / 2)
out("tiny_swing.yaml", "v2", vb)
out("tiny_swing.yaml", "omega2", vb / l)

# 7d. braking_friction_long.yaml -----------------------------------------------------------
m, kG, r, Fn, mu, n0 = mpf(255), mpf("0.385"), mpf("0.125"), mpf(200), mpf("0.36"), mpf(330) * 2 * pi / 60
out("braking_friction_long.yaml", "theta2", m * kG**2 * n0**2 / (2 * mu * Fn * r))  # rad

# 7e. wheel_cam_couple_variant.yaml ---------------------------------------------------------
m, k, M0, phi0, phi2 = mpf(20), mpf("0.325"), mpf(40), mpf("1.6"), mpf("1.95")
U = quad(lambda p: M0 * exp(-((p / phi0) ** 2)), [0, phi2])
assert abs(U - M0 * phi0 * sqrt(pi) / 2 * erf(phi2 / phi0)) < mpf(10) ** -40
out("wheel_cam_couple_variant.yaml", "omega2", sqrt(2 * U / (m * k**2)))

# 7b'. wheel_step_limit.yaml: the same least speed, as the speed that just reaches the top at rest --
m, r, h, g = mpf(8), mpf("0.3"), mpf("0.1"), mpf("9.81")
out("wheel_step_limit.yaml", "v0_min", sqrt(4 * g * h / 3))

# ball_bounce_energy.yaml: what energy alone says (sqrt(g h) up at h/2), and what the motion does
# (it meets h/2 falling at -sqrt(g h); after the bounce it rises to e^2 h = h/4 only)
g, h, e = mpf("9.81"), mpf(2), mpf("0.5")
out("ball_bounce_energy.yaml", "v2", sqrt(g * h))
out("ball_bounce_energy.yaml", "#v_at_h/2_falling", -sqrt(g * h))
out("ball_bounce_energy.yaml", "#rise_after_bounce", e**2 * h)

# pendulum_pin_friction.yaml: m g (L/2)(cos(beta) - cos(theta0)) = Mf (theta0 + beta), beta in (0, pi/2)

m, L, g, Mf, th0 = mpf(2), mpf(1), mpf("9.81"), mpf("0.5"), 60 * degree
beta = findroot(lambda b: m * g * L / 2 * (cos(b) - cos(th0)) - Mf * (th0 + b), mpf("0.9"))
out("pendulum_pin_friction.yaml", "beta", beta / degree)  # deg

if __name__ == "__main__":
    print("\n".join(OUT))
