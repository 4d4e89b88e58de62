#!/usr/bin/python3
"""Independent check (sympy and mpmath only, no kinergy) of a body that leaves a surface that can
only push and goes on free of it: what `kinergy simulate` follows after the release.

Each motion is derived here from first principles, nothing taken from kinergy: energy up to the
release (where the surface's push N falls to zero, N from Newton-Euler), the instant of the
release as the integral t* = int dtheta / theta_dot over the motion on the surface (mpmath
quadrature), and the free motion after it in closed form (a projectile) or from Lagrange's
equations written here by hand and integrated by mpmath's Taylor-series ODE solver. The numbers
asserted by tests/simulate/test_flight.cpp are printed and asserted here (15 significant digits, asserted to 1e-9).

  1. tests/data/contact/dome_flight.yaml -- a particle released at rest at theta0 = 0.2 rad on a
     smooth dome of radius R = 1.5 m (g = 9.81). On the dome theta_dot^2 = 2 g (cos theta0 -
     cos theta)/R, N = m g cos(theta) - m R theta_dot^2 = 0 at cos(theta*) = (2/3) cos(theta0).
     After it, a projectile from R (sin, cos)(theta*) with velocity R theta_dot* (cos, -sin)(theta*).
     At t* + 0.25 s: the polar angle atan2(x, y) and the gap hypot(x, y) - R (kinergy's theta and
     dome_gap, the ball carried off the dome along its radius).
  2. derivations/kinetics/rod_leaves_wall.yaml -- the ladder (m = 12 kg, L = 3 m, theta0 = 20 deg,
     vA0 = 0.5 m/s), theta from the vertical. On wall and floor, T = (1/2)(m L^2/3) theta_dot^2 about
     the instant centre, so theta_dot^2 = theta_dot0^2 + 3 g (cos theta0 - cos theta)/L; B leaves the
     wall at cos(theta*) = 2 cos(theta0)/3 + 2 vA0^2/(9 g L cos(theta0)^2). After it, A on the floor
     only (y_G = (L/2) cos theta), x_G free: no horizontal force, x_G_dot = (L/2) cos(theta*)
     theta_dot* for ever; Lagrange for theta with T = m x_G_dot^2/2 + m (L/2)^2 sin^2 theta
     theta_dot^2/2 + (m L^2/12) theta_dot^2/2, V = m g (L/2) cos theta. At t* + 0.2 s: theta and
     B's distance from the wall x_B = x_G - (L/2) sin(theta) (kinergy's wall_gap), the floor still
     pushing (N_A = m (y_G_ddot + g) > 0 checked along the way).
  3. derivations/kinetics/bob_cord_slack.yaml -- a bob (m = 0.5 kg) on a cord of length l = 1.2 m
     from the bottom at v0 = 6 m/s, theta from the downward vertical. Taut: theta_dot^2 = (v0^2 -
     2 g l (1 - cos theta))/l^2, the tension m v^2/l + m g cos(theta) = 0 at cos(theta*) =
     -(v0^2 - 2 g l)/(3 g l). Then a projectile from l (sin, -cos)(theta*) with velocity
     l theta_dot* (cos, sin)(theta*), until its distance from O is l again (mpmath findroot): the cord
     snaps taut with e = 0, taking the velocity along the cord (v_n, the approach along the inward
     normal, is asserted) and keeping the part across it (T after = m v_t^2/2).
  4. tests/data/contact/disk_pushed_slips.yaml -- a uniform disk (m = 8 kg, r = 0.15 m) rolling at
     v0 = 1 m/s on a level floor, pushed at its centre by P = P0 sin(pi x/d) (P0 = 80 N, d = 2 m).
     Rolling: (3/2) m x_ddot = P, the friction needed P/3 (Newton-Euler), so energy gives
     (3/4) m v^2 = (3/4) m v0^2 + (P0 d/pi)(1 - cos(pi x/d)), and mu_s m g (mu_s = 0.2) holds it up to
     sin(pi x*/d) = 3 mu_s m g/P0; t* = int dx/v. Sliding after it: m x_ddot = P - mu_k m g,
     (m r^2/2) phi_ddot = -mu_k m g r (mu_k = 0.15; the slip x_dot + r phi_dot stays > 0, checked),
     integrated by mpmath to t* + 0.3 s: x, x_dot, phi_dot there.
  5. tests/data/contact/ball_thrown_off_floor.yaml -- a ball on a floor that only pushes, lifted by
     F = 3 m g (1 - t/t1) (t1 = 0.1 s): it leaves at t = 0 (the floor would pull, m g - 3 m g);
     y'' = 3 g (1 - t/t1) - g integrated by hand to t1 (v = g t1/2, y = g t1^2/2), a projectile after
     it; it strikes at t1 + (v + sqrt(v^2 + 2 g y))/g with v_n = -sqrt(v^2 + 2 g y), rebounds at half
     that (e = 0.5) and strikes again after 2 v_n+/g.
  6. tests/data/contact/disk_thrown_sliding.yaml -- a disk (r = 0.2 m) set on a floor at v0 = 3 m/s
     without spin: x_ddot = -mu_k g, (r^2/2) phi_ddot = -mu_k g r (mu_k = 0.2), the slip
     x_dot + r phi_dot = v0 - 3 mu_k g t stops at t = v0/(3 mu_k g) with x_dot = 2 v0/3; rolling on a
     level floor takes no friction, so it rolls on: x at 1 s.
"""
import mpmath as mp
import sympy as sp

mp.mp.dps = 30
g = mp.mpf("9.81")


def check(name, value, want):
    print(f"{name} = {mp.nstr(value, 15)}")
    assert mp.almosteq(value, mp.mpf(want), rel_eps=mp.mpf("1e-9")), (name, value, want)


# 1. the dome
R, th0 = mp.mpf("1.5"), mp.mpf("0.2")
ths = mp.acos(mp.mpf(2) / 3 * mp.cos(th0))
rate = lambda th: mp.sqrt(2 * g * (mp.cos(th0) - mp.cos(th)) / R)
t_leave = mp.quad(lambda th: 1 / rate(th), [th0, ths])
v = R * rate(ths)
tau = mp.mpf("0.25")
x = R * mp.sin(ths) + v * mp.cos(ths) * tau
y = R * mp.cos(ths) - v * mp.sin(ths) * tau - g * tau**2 / 2
check("dome t_leave", t_leave, "0.843453923349726")
check("dome theta_leave_deg", ths * 180 / mp.pi, "49.2032458521461")
check("dome theta(t_leave + 0.25)", mp.atan2(x, y), "1.51806416518665")
check("dome gap(t_leave + 0.25)", mp.hypot(x, y) - R, "0.144318779909857")

# 2. the ladder, derived symbolically for theta after the release
t, m_, L_, g_ = sp.symbols("t m L g", positive=True)
th = sp.Function("theta")(t)
xd = sp.symbols("xd")  # x_G_dot, constant
T = m_ * xd**2 / 2 + m_ * (L_ / 2) ** 2 * sp.sin(th) ** 2 * th.diff(t) ** 2 / 2 + (m_ * L_**2 / 12) * th.diff(t) ** 2 / 2
V = m_ * g_ * (L_ / 2) * sp.cos(th)
lag = T - V
eom = sp.diff(lag.diff(th.diff(t)), t) - lag.diff(th)
a = sp.symbols("a")
thdd = sp.solve(eom.subs(th.diff(t, 2), a), a)[0]
q, qd = sp.symbols("q qd")
thdd_f = sp.lambdify((q, qd), thdd.subs(th.diff(t), qd).subs(th, q).subs({m_: 12, L_: 3, g_: sp.Rational(981, 100)}), "mpmath")
# N_A = m (y_G_ddot + g), y_G = (L/2) cos theta
yG = L_ / 2 * sp.cos(th)
NA = (m_ * (yG.diff(t, 2) + g_)).subs(th.diff(t, 2), thdd).subs(th.diff(t), qd).subs(th, q).subs({m_: 12, L_: 3, g_: sp.Rational(981, 100)})
NA_f = sp.lambdify((q, qd), NA, "mpmath")

L, t0, vA0 = mp.mpf(3), mp.radians(20), mp.mpf("0.5")
w0 = vA0 / (L * mp.cos(t0))
cs = 2 * mp.cos(t0) / 3 + 2 * vA0**2 / (9 * g * L * mp.cos(t0) ** 2)
ths = mp.acos(cs)
w = lambda th: mp.sqrt(w0**2 + 3 * g * (mp.cos(t0) - mp.cos(th)) / L)
t_leave = mp.quad(lambda th: 1 / w(th), [t0, ths])
ws = w(ths)
xGd = L / 2 * mp.cos(ths) * ws
sol = mp.odefun(lambda s, y: [y[1], thdd_f(y[0], y[1])], 0, [ths, ws])
tau = mp.mpf("0.2")
for k in range(1, 21):
    thk, wk = sol(tau * k / 20)
    assert NA_f(thk, wk) > 0, "the floor stops pushing"
th1, w1 = sol(tau)
assert th1 < mp.pi / 2
xG = L / 2 * mp.sin(ths) + xGd * tau
check("ladder t_leave", t_leave, "0.635987033526879")
check("ladder theta_leave_deg", ths * 180 / mp.pi, "51.0531254544615")
check("ladder theta(t_leave + 0.2)", th1, "1.31472706779781")
check("ladder theta_dot(t_leave + 0.2)", w1, "2.47935197384411")
check("ladder wall_gap(t_leave + 0.2)", xG - L / 2 * mp.sin(th1), "0.0466367038593675")

# 3. the bob whirled too slowly
m, l, v0 = mp.mpf("0.5"), mp.mpf("1.2"), mp.mpf(6)
ths = mp.acos(-(v0**2 - 2 * g * l) / (3 * g * l))
rate = lambda th: mp.sqrt(v0**2 - 2 * g * l * (1 - mp.cos(th))) / l
t_slack = mp.quad(lambda th: 1 / rate(th), [0, ths])
P = mp.matrix([l * mp.sin(ths), -l * mp.cos(ths)])
V = l * rate(ths) * mp.matrix([mp.cos(ths), mp.sin(ths)])
at = lambda tau: (P[0] + V[0] * tau, P[1] + V[1] * tau - g * tau**2 / 2)
# the first return to |r| = l: |r| < l just after the release (the bob falls inside the circle)
assert mp.hypot(*at(mp.mpf("0.01"))) < l
grid = [mp.mpf(k) / 1000 for k in range(10, 3000)]
k = next(i for i, tau in enumerate(grid) if mp.hypot(*at(tau)) >= l)
tau = mp.findroot(lambda tau: mp.hypot(*at(tau)) - l, (grid[k - 1], grid[k]), solver="anderson")
x, y = at(tau)
vx, vy = V[0], V[1] - g * tau
n_in = (-x / l, -y / l)  # the cord's pull, toward O
vn = vx * n_in[0] + vy * n_in[1]  # the gap's rate (the gap opens inward): < 0 as the cord straightens
vt = vx * (-y / l) + vy * (x / l)  # across the cord, (cos, sin)(theta) with (x, y) = l (sin, -cos)
check("bob t_slack", t_slack, "0.527529055311618")
check("bob theta_slack_deg", ths * 180 / mp.pi, "110.652629518225")
check("bob t_taut", t_slack + tau, "1.30497995964184")
check("bob theta_taut", mp.atan2(x, -y), "0.489427173932131")
check("bob vn_taut", vn, "-4.71070275247336")
check("bob T_after", m * vt**2 / 2, "2.76131703586534")

# 4. the disk pushed until it slips
m, r, d, P0, v0, mus, muk = mp.mpf(8), mp.mpf("0.15"), mp.mpf(2), mp.mpf(80), mp.mpf(1), mp.mpf("0.2"), mp.mpf("0.15")
P = lambda x: P0 * mp.sin(mp.pi * x / d)
xs = d / mp.pi * mp.asin(3 * mus * m * g / P0)
v = lambda x: mp.sqrt(v0**2 + 4 / (3 * m) * (P0 * d / mp.pi) * (1 - mp.cos(mp.pi * x / d)))
ts = mp.quad(lambda x: 1 / v(x), [0, xs])
sol = mp.odefun(lambda t, y: [y[1], (P(y[0]) - muk * m * g) / m], 0, [xs, v(xs)])
tau = mp.mpf("0.3")
for k in range(1, 31):
    xk, vk = sol(tau * k / 30)
    assert vk + r * (-v(xs) / r - 2 * muk * g / r * tau * k / 30) > 0, "the slip stops"
x1, xd1 = sol(tau)
w1 = -v(xs) / r - 2 * muk * g / r * tau
check("disk t_slip", ts, "0.333325313335315")
check("disk x_slip", xs, "0.400641364134971")
check("disk x(t_slip + 0.3)", x1, "1.17380263935945")
check("disk x_dot(t_slip + 0.3)", xd1, "3.75192520196304")
check("disk phi_dot(t_slip + 0.3)", w1, "-16.6895879706387")

# 5. the ball lifted off the floor
t1 = mp.mpf("0.1")
v, y = g * t1 / 2, g * t1**2 / 2
assert mp.almosteq(mp.quad(lambda t: 3 * g * (1 - t / t1) - g, [0, t1]), v)  # the lift's impulse, per unit mass
vn = mp.sqrt(v**2 + 2 * g * y)
t_strike = t1 + (v + vn) / g
check("ball t_strike", t_strike, "0.261803398874989")
check("ball vn_strike", -vn, "-1.09679134296365")
check("ball t_strike2", t_strike + 2 * (vn / 2) / g, "0.373606797749979")

# 6. the disk thrown without spin
v0, muk, r = mp.mpf(3), mp.mpf("0.2"), mp.mpf("0.2")
ts = v0 / (3 * muk * g)
xs = v0 * ts - muk * g * ts**2 / 2
check("disk2 t_roll", ts, "0.509683995922528")
check("disk2 x(1)", xs + 2 * v0 / 3 * (1 - ts), "2.25484199796126")
print("ok")
