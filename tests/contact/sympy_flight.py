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
print("ok")
