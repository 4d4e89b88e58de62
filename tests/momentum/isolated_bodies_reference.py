"""Independent re-derivation (sympy, Newton-Euler per body with the interaction forces as unknowns)
of the claimed forms and values of the derivations that isolate bodies (issue 13, part 1):
derivations/momentum/{disk_axle_reaction, gears_time_tooth_force, disk_rolls_incline_time,
drum_cord_tension, disk_on_ice_pulled}.yaml and derivations/energy/gears_tooth_force_energy.yaml.
Run: python3 tests/momentum/isolated_bodies_reference.py — every line must say form_equal=True and OK.
"""
import sympy as sp
from sympy import sin, cos, sqrt, pi, Rational as Q
def sigfig(x, s):
    x = float(x); return float(f"{x:.{s-1}e}")
def cmp(name, mine, form, claimed, sf, subs):
    d = sp.simplify(mine - form)
    v = float(mine.subs(subs))
    ok_v = sigfig(v, sf) == claimed
    print(f"  {name}: mine={sp.simplify(mine)}  = {v:.6g}; form_equal={d==0}; value {claimed} ({sf} sf) -> {sigfig(v,sf)} {'OK' if ok_v else 'MISMATCH'}")

def cross(a, b): return a[0]*b[1]-a[1]*b[0]

# ---------- 1. disk_axle_reaction
print("disk_axle_reaction")
m,r,M,P,g,t2 = sp.symbols('m r M P g t2', positive=True)
Rx,Ry,w2 = sp.symbols('R_x R_y omega2')
cordF = (-P,0); cordAt=(0,-r)
eqs = [sp.Eq(m*0, (Rx + cordF[0])*t2),            # x momentum (centre fixed)
       sp.Eq(m*0, (Ry + cordF[1] - m*g)*t2),      # y momentum
       sp.Eq(m*r**2/2*w2, (M + cross(cordAt, cordF))*t2)]  # about O (pin, weight: no moment)
s = sp.solve(eqs,[Rx,Ry,w2],dict=True)[0]
sub = {m:20,r:Q(3,10),M:15,P:40,g:Q(981,100),t2:3}
cmp('omega2', s[w2], 2*(M-P*r)*t2/(m*r**2), 10.00, 4, sub)
cmp('Rx', s[Rx], P, 40.00, 4, sub)
cmp('Ry', s[Ry], m*g, 196.2, 4, sub)
cmp('R', sqrt(s[Rx]**2+s[Ry]**2), sqrt(P**2+m**2*g**2), 200.24, 5, sub)
print("  bottom-point velocity with omega>0 is +x: cord is wound in while pulled -x (P does negative work)")

# ---------- 2. gears
print("gears_time_tooth_force")
mA,kA,rA,mB,kB,rB,M,nA,t = sp.symbols('m_A k_A r_A m_B k_B r_B M n_A t', positive=True)
Fy = sp.symbols('F_y')   # y-force of mesh ON gear A at pitch point (rA,0); on B it is -Fy
wA = nA; wB = -rA/rB*nA     # from rA*phiA + rB*phiB = 0
pitch = (rA, 0)
eqA = sp.Eq(mA*kA**2*wA, (M + cross((pitch[0]-0, 0), (0, Fy)))*t)
eqB = sp.Eq(mB*kB**2*wB, cross((pitch[0]-(rA+rB), 0), (0, -Fy))*t)
s = sp.solve([eqA,eqB],[Fy,t],dict=True)[0]
sub = {mA:10,kA:Q(1,10),rA:Q(15,100),mB:30,kB:Q(1,4),rB:Q(3,10),M:20,nA:600*2*pi/60}
T = s[t]; Jy = s[Fy]*T
cmp('t2', T, nA*(mA*kA**2*rB**2+mB*kB**2*rA**2)/(M*rB**2), 1.7868, 5, sub)
cmp('J', sp.Abs(Jy), mB*kB**2*rA*nA/rB**2, 196.35, 5, sub)
cmp('Jy', Jy, -mB*kB**2*rA*nA/rB**2, -196.35, 5, sub)
cmp('F', sp.Abs(Jy)/T, M*mB*kB**2*rA/(mA*kA**2*rB**2+mB*kB**2*rA**2), 109.89, 5, sub)

# ---------- 3. disk rolling incline
print("disk_rolls_incline_time")
m,r,g,b,t2 = sp.symbols('m r g beta t2', positive=True)
Ft, Nn, v2 = sp.symbols('F_t N v2')   # Ft (|F| = -Ft since friction points up-slope for 0<beta<pi/2): friction along +down-slope dir on disk
e = sp.Matrix([cos(b), -sin(b)]); nrm = sp.Matrix([sin(b), cos(b)])
Fvec = Ft*e + Nn*nrm
W = sp.Matrix([0, -m*g])
rel = -r*nrm
w2 = -v2/r
eqs = [sp.Eq(m*v2, ((Fvec+W).dot(e))*t2),
       sp.Eq(0, ((Fvec+W).dot(nrm))*t2),
       sp.Eq(m*r**2/2*w2, cross(rel, Fvec)*t2)]
s = sp.solve(eqs,[Ft,Nn,v2],dict=True)[0]
sub = {m:8,r:Q(15,100),g:Q(981,100),b:20*pi/180,t2:2}
cmp('v2', s[v2], 2*g*sin(b)*t2/3, 4.4736, 5, sub)
cmp('omega2', w2.subs(s), -2*g*sin(b)*t2/(3*r), -29.824, 5, sub)
cmp('F', -s[Ft], m*g*sin(b)/3, 8.9472, 5, sub)
print("  friction sign (along down-slope):", sp.simplify(s[Ft]), "-> up the slope; needs mu >=", sp.simplify((-s[Ft])/s[Nn]), "=", float(((-s[Ft])/s[Nn]).subs(sub)))

# ---------- 4. drum
print("drum_cord_tension")
m,M,R,g,t2 = sp.symbols('m M R g t2', positive=True)
T, v2 = sp.symbols('T v2')
w2 = v2/R   # y = R phi - a
eqs = [sp.Eq(m*v2, (-m*g + T)*t2),
       sp.Eq(M*R**2/2*w2, cross((R,0),(0,-T))*t2)]
s = sp.solve(eqs,[T,v2],dict=True)[0]
sub = {m:5,M:20,R:Q(1,4),g:Q(981,100),t2:3}
cmp('v2', s[v2], -2*m*g*t2/(M+2*m), -9.810, 4, sub)
cmp('T', s[T], m*g*M/(M+2*m), 32.70, 4, sub)

# ---------- 5. disk on ice
print("disk_on_ice_pulled")
m,r,P,th,g,t2 = sp.symbols('m r P theta g t2', positive=True)
N, vx, vy, w2 = sp.symbols('N vx vy omega2')
Pv = (P*cos(th), P*sin(th))
eqs = [sp.Eq(m*vx, Pv[0]*t2), sp.Eq(m*0, (N + Pv[1] - m*g)*t2),
       sp.Eq(m*r**2/2*w2, (cross((0,r),Pv) + cross((0,-r),(0,N)))*t2)]
s = sp.solve(eqs,[vx,N,w2],dict=True)[0]
sub = {m:4,r:Q(1,5),P:10,th:pi/6,g:Q(981,100),t2:2}
cmp('v2', s[vx], P*cos(th)*t2/m, 4.330, 4, sub)
cmp('omega2', s[w2], -2*P*cos(th)*t2/(m*r), -43.30, 4, sub)
cmp('N', s[N], m*g - P*sin(th), 34.24, 4, sub)
print("  N>0 (stays on ice):", float(s[N].subs(sub)) > 0)

# ---------- 6. gears_tooth_force_energy (work-energy of gear B alone)
print("gears_tooth_force_energy")
mA,kA,rA,mB,kB,rB,M,n = sp.symbols('mA kA rA mB kB rB M n', positive=True)
IA, IB = mA*kA**2, mB*kB**2
wA = sp.sqrt(2*M*n/(IA + IB*rA**2/rB**2))           # whole system: M n = IA wA^2/2 + IB wB^2/2
wB = rA*wA/rB
F = sp.Rational(1, 2)*IB*wB**2/(rA*n)                # gear B: IB wB^2/2 = F * (pitch point's travel rB*(rA/rB)*n)
sub = {mA:10,kA:Q(1,10),rA:Q(15,100),mB:30,kB:Q(25,100),rB:Q(3,10),M:20,n:10*pi}
cmp('omegaA2 [rpm]', wA*30/pi, rB*sqrt(2*M*n/(mA*kA**2*rB**2 + mB*kB**2*rA**2))*30/pi, 448.9, 4, sub)
cmp('F', F, M*mB*kB**2*rA/(mA*kA**2*rB**2 + mB*kB**2*rA**2), 109.89, 5, sub)
