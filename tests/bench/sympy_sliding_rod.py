"""The sliding rod (derivations/energy/sliding_rod.yaml) derived, solved and evaluated with
sympy.physics.mechanics, start to finish: the yardstick a whole `kinergy solve` is timed against
(tests/bench/solve_scaling.py). A rod of length l slides with end A on a horizontal floor and end
B on a vertical wall, released from rest standing vertical; its angular velocity when it makes
theta2 = 30 deg with the floor. Prints omega2 to 15 digits.
"""
import sympy as sp
from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

theta = dynamicsymbols("theta")
m, l, g, th2, w = sp.symbols("m l g theta2 omega", positive=True)
N = ReferenceFrame("N")
R = N.orientnew("R", "Axis", [theta, N.z])
O = Point("O")
O.set_vel(N, 0)
# G at (l/2 cos theta, l/2 sin theta): A on the floor, B on the wall
G = O.locatenew("G", l / 2 * sp.cos(theta) * N.x + l / 2 * sp.sin(theta) * N.y)
G.set_vel(N, G.pos_from(O).dt(N))
rod = RigidBody("rod", G, R, m, (inertia(R, 0, 0, m * l**2 / 12), G))
rod.potential_energy = m * g * G.pos_from(O).dot(N.y)
T = rod.kinetic_energy(N)
V = rod.potential_energy
qd = theta.diff()
# energy from standing vertical at rest (theta = pi/2) to theta2
T2 = T.subs(qd, w).subs(theta, th2)
V1, V2 = V.subs(theta, sp.pi / 2), V.subs(theta, th2)
sols = sp.solve(sp.Eq(T2 + V2, V1), w)
omega2 = sp.simplify(sols[0])
value = omega2.subs({l: sp.Rational(12, 10), g: sp.Rational(981, 100), th2: sp.pi / 6, m: 1})
print(sp.N(value, 15))
