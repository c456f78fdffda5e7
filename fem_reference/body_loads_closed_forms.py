#!/usr/bin/env python3
"""Symbolic check of the closed forms that axisymmetric_fem_body_loads_test.cc compares the
FEM with (issue 14). Run by hand (needs sympy): python3 fem_reference/body_loads_closed_forms.py

For each solution, written in the same form as in the test, it checks
  * compatibility: the four stresses are D (e(u) - e_th) of the displacement given,
    e(u) = (du_r/dr, du_z/dz, u_r/r, du_r/dz + du_z/dr), e_th = alpha T (1, 1, 1, 0);
  * equilibrium: d s_rr/dr + d s_rz/dz + (s_rr - s_tt)/r + f_r = 0,
                 d s_rz/dr + d s_zz/dz + s_rz/r + f_z = 0;
  * the boundary conditions of the test's section;
  * the support reactions and energies the test states in closed form.
Every check prints 0 (or True) when it holds; the script exits 1 otherwise.
"""
import sys

import sympy as sp

r, z, a, b, h, E, nu, rho, w, g, alpha, T0, Tr, Tz, s = sp.symbols(
    'r z a b h E nu rho omega g alpha T0 T_r T_z s', real=True)
lam = E * nu / ((1 + nu) * (1 - 2 * nu))
mu = E / (2 * (1 + nu))
failures = []


def check(name, expr):
    value = sp.simplify(expr)
    ok = value == 0 or value is sp.true
    print(f"  {name}: {value}")
    if not ok:
        failures.append(name)


def stress_of(u_r, u_z, T):
    e = [sp.diff(u_r, r), sp.diff(u_z, z), u_r / r, sp.diff(u_r, z) + sp.diff(u_z, r)]
    th = alpha * T
    trace = e[0] + e[1] + e[2] - 3 * th
    return [lam * trace + 2 * mu * (e[0] - th), lam * trace + 2 * mu * (e[1] - th),
            lam * trace + 2 * mu * (e[2] - th), mu * e[3]]


def verify(name, stress, u_r, u_z, T, f_r, f_z):
    print(name)
    from_u = stress_of(u_r, u_z, T)
    for k, label in enumerate(['rr', 'zz', 'tt', 'rz']):
        check(f"sigma_{label} - D (e(u) - e_th)_{label}", from_u[k] - stress[k])
    s_rr, s_zz, s_tt, s_rz = stress
    check("equilibrium r", sp.diff(s_rr, r) + sp.diff(s_rz, z) + (s_rr - s_tt) / r + f_r)
    check("equilibrium z", sp.diff(s_rz, r) + sp.diff(s_zz, z) + s_rz / r + f_z)


# 1. Rotating hollow cylinder a < r < b in plane strain (u_z = 0: symmetry on both ends).
k = (3 - 2 * nu) * rho * w**2 / (8 * (1 - nu))
s_rr = k * (a**2 + b**2 - a**2 * b**2 / r**2 - r**2)
s_tt = k * (a**2 + b**2 + a**2 * b**2 / r**2 - (1 + 2 * nu) / (3 - 2 * nu) * r**2)
s_zz = nu * (s_rr + s_tt)
u_r = r * ((1 - nu**2) * s_tt - nu * (1 + nu) * s_rr) / E
verify("rotating hollow cylinder", [s_rr, s_zz, s_tt, 0], u_r, 0, 0, rho * w**2 * r, 0)
check("free inner surface sigma_rr(a)", s_rr.subs(r, a))
check("free outer surface sigma_rr(b)", s_rr.subs(r, b))
check("top reaction 2 pi int_a^b sigma_zz r dr - pi nu rho omega^2 (b^4 - a^4) / 2",
      2 * sp.pi * sp.integrate(s_zz * r, (r, a, b)) - sp.pi * nu * rho * w**2 * (b**4 - a**4) / 2)
#    The solid cylinder is a = 0 (the a^2 terms vanish; u_r = 0 on the axis).
s0 = [x.subs(a, 0) for x in (s_rr, s_zz, s_tt)]
u0 = sp.simplify(u_r.subs(a, 0))
verify("rotating solid cylinder (a = 0)", [s0[0], s0[1], s0[2], 0], u0, 0, 0, rho * w**2 * r, 0)
check("u_r on the axis", sp.limit(u0, r, 0))
check("sigma_rr(0) - sigma_tt(0) (finite hoop strain on the axis)",
      sp.limit(s0[0] - s0[2], r, 0))

# 2. Hollow cylinder in plane strain, T = T0 + T_r r, free inner and outer surfaces.
T = T0 + Tr * r
I = sp.integrate((T0 + Tr * s) * s, (s, a, r))
print("thermal hollow cylinder: I(r) = int_a^r T s ds")
check("I(r) - [T0 (r^2 - a^2)/2 + T_r (r^3 - a^3)/3]",
      I - (T0 * (r**2 - a**2) / 2 + Tr * (r**3 - a**3) / 3))
c = alpha * E / ((1 - nu) * r**2)
t_rr = c * ((r**2 - a**2) / (b**2 - a**2) * I.subs(r, b) - I)
t_tt = c * ((r**2 + a**2) / (b**2 - a**2) * I.subs(r, b) + I - T * r**2)
t_zz = nu * (t_rr + t_tt) - alpha * E * T
t_u = r * ((t_tt - nu * (t_rr + t_zz)) / E + alpha * T)
verify("thermal hollow cylinder", [t_rr, t_zz, t_tt, 0], t_u, 0, T, 0, 0)
check("free inner surface", t_rr.subs(r, a))
check("free outer surface", t_rr.subs(r, b))

# 3. Laterally confined column 0 < r < R, 0 < z < h (symmetry at z = 0 and on r = R, the
#    axis, top free) under gravity and T = T0 + T_z z: u_r = 0.
R = sp.symbols('R', positive=True)
Tc = T0 + Tz * z
c_zz = -rho * g * (h - z)
c_rr = nu / (1 - nu) * c_zz - E * alpha * Tc / (1 - nu)
c_uz = -rho * g * (h * z - z**2 / 2) / (lam + 2 * mu) + \
    (1 + nu) / (1 - nu) * alpha * (T0 * z + Tz * z**2 / 2)
verify("confined column", [c_rr, c_zz, c_rr, 0], 0, c_uz, Tc, 0, -rho * g)
check("u_z(z = 0)", c_uz.subs(z, 0))
check("top free sigma_zz(h)", c_zz.subs(z, h))
check("bottom reaction -2 pi int_0^R sigma_zz(0) r dr - weight",
      -2 * sp.pi * sp.integrate(c_zz.subs(z, 0) * r, (r, 0, R)) - rho * g * sp.pi * R**2 * h)
check("side reaction 2 pi R int_0^h sigma_rr dz - closed form",
      2 * sp.pi * R * sp.integrate(c_rr, (z, 0, h)) -
      2 * sp.pi * R * (-nu / (1 - nu) * rho * g * h**2 / 2
                       - E * alpha / (1 - nu) * (T0 * h + Tz * h**2 / 2)))
check("strain energy 1/2 int s.C s r dr dz - closed form (thermal part only, g = 0)",
      (sp.integrate(sp.integrate(
          ((2 * (1 - nu) * c_rr**2) / (2 * E)).subs(g, 0) * r, (r, 0, R)), (z, 0, h))) -
      E * alpha**2 / (1 - nu) * R**2 / 2 * sp.integrate(Tc**2, (z, 0, h)))

# 4. Uniform temperature T0 on any section free to expand about the origin (symmetry edges
#    on lines through the origin): u = alpha T0 (r, z), no stress.
verify("uniform temperature", [0, 0, 0, 0], alpha * T0 * r, alpha * T0 * z, T0, 0, 0)

# 5. Rotating solid sphere of radius b (derived here with a polynomial ansatz; the test
#    uses it on the quarter disk with the equator symmetry and the axis).
q = 5 * (nu - 1) * (5 * nu + 7)
p_rr = rho * w**2 * ((5 * nu**2 - nu - 12) * b**2 + (12 + nu - 5 * nu**2) * r**2
                     + (9 + 7 * nu) * z**2) / q
p_zz = rho * w**2 * (5 * nu**2 + 6 * nu - 3) * (2 * r**2 + z**2 - b**2) / q
p_tt = rho * w**2 * ((5 * nu**2 - nu - 12) * b**2 + (5 * nu**2 + 7 * nu + 4) * r**2
                     + (9 + 7 * nu) * z**2) / q
p_rz = -rho * w**2 * (5 * nu**2 + 6 * nu - 3) * r * z / q
p_ur = -rho * w**2 * r * ((-12 * nu**2 - 8 * nu + 12) * b**2
                          + (5 * nu**3 + 8 * nu**2 - nu - 4) * r**2
                          + (5 * nu**3 + 13 * nu**2 - nu - 9) * z**2) / (E * q)
p_uz = -rho * w**2 * z * ((10 * nu**3 + 3 * nu**2 - 18 * nu - 3) * b**2
                          + (-2 * nu**2 + 4 * nu + 6) * r**2
                          + (3 * nu**2 + 4 * nu + 1) * z**2) / (E * q)
verify("rotating solid sphere", [p_rr, p_zz, p_tt, p_rz], p_ur, p_uz, 0, rho * w**2 * r, 0)
phi = sp.symbols('phi', real=True)
on_sphere = {r: b * sp.cos(phi), z: b * sp.sin(phi)}
check("traction-free sphere, t_r",
      (p_rr * sp.cos(phi) + p_rz * sp.sin(phi)).subs(on_sphere, simultaneous=True))
check("traction-free sphere, t_z",
      (p_rz * sp.cos(phi) + p_zz * sp.sin(phi)).subs(on_sphere, simultaneous=True))
check("equator u_z(z = 0)", p_uz.subs(z, 0))
check("equator sigma_rz(z = 0)", p_rz.subs(z, 0))

print("all checks hold" if not failures else f"FAILED: {failures}")
sys.exit(1 if failures else 0)
