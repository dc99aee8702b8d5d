#!/usr/bin/env python3
"""The thin-layer coefficient A of the error-function grading at w << a, the reference of its FE check.

E(z) = E_b [1 + (m - 1) erfc(z/w)], m = E_s / E_b, under a rigid frictionless flat punch of radius a >> w.
Far from the edge of the punch (distance s >> w) the graded skin is a thin layer: through it the in-plane
strains (eps_rr, eps_tt) and the tractions (sigma_zz = -p, sigma_rz = 0) are those of the homogeneous surface.
At fixed depth, U1 - U0 = 1/2 \\int eps0 : (C1 - C0) : eps1 dV exactly (C1 the graded, C0 the homogeneous
stiffness, same nu), which for the thin layer is, per unit surface area,

    1/2 [ E_b eps_rr^2 / (1 - nu^2) \\int (e - 1) dz + p^2 / M_b \\int (1 - 1/e) dz ],   e = E / E_b,

M_b = E_b (1 - nu) / ((1 + nu)(1 - 2 nu)) (the cross terms in eps_rr p cancel for a constant nu; eps_tt is
bounded). Under Sneddon's punch p = E_b d / (pi (1 - nu^2) sqrt(a^2 - r^2)) and, from the radial surface
displacement u_r = -(1 - 2 nu)(1 + nu) / (E r) \\int_0^r p s ds (Johnson, Contact Mechanics, 3.1),
eps_rr = -(1 - 2 nu)(1 + nu) p / E_b + O(1) near the edge inside; outside r > a both are bounded. So
p^2 ~ 1 / (a - r) makes the layer energy diverge like ln(a / w) at the edge, cut off where s ~ w:

    F / F_Sneddon(E_b) - 1 = (w/a) [A ln(a/w) + B],
    A = (1 - 2 nu) [(1 - 2 nu) J1 + J2] / (2 pi (1 - nu)^2),
    J1 = \\int_0^inf (e - 1) dz / w = (m - 1) / sqrt(pi),   J2 = \\int_0^inf (1 - 1/e) dz / w,

B = O(1) from s ~ w and s ~ a (not computed here). J2 by mpmath tanh-sinh quadrature at 30 and 40 digits,
printed to the agreement.

Run: /usr/bin/python3 tests/data/generate_erfc_layer.py [m ...]   (nu = 0.3)
"""
import sys

import mpmath as mp


def coefficients(m, nu):
    m = mp.mpf(m)
    nu = mp.mpf(nu)
    J1 = (m - 1) / mp.sqrt(mp.pi)
    J2 = mp.quad(lambda x: (m - 1) * mp.erfc(x) / (1 + (m - 1) * mp.erfc(x)), [0, 1, 3, mp.inf])
    A = (1 - 2 * nu) * ((1 - 2 * nu) * J1 + J2) / (2 * mp.pi * (1 - nu) ** 2)
    return J1, J2, A


if __name__ == "__main__":
    nu = "0.3"
    for m in (sys.argv[1:] or ["2", "0.5"]):
        mp.mp.dps = 30
        low = coefficients(m, nu)
        mp.mp.dps = 40
        high = coefficients(m, nu)
        digits = int(-mp.log10(abs(high[2] / low[2] - 1) + mp.mpf(10) ** -40))
        n = min(digits, 25)
        print(f"m = {m}, nu = {nu}: J1 = {mp.nstr(high[0], n)}, J2 = {mp.nstr(high[1], n)}, "
              f"A = {mp.nstr(high[2], n)}  ({digits} digits agree at 30 / 40 dps)")
