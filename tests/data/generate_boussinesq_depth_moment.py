#!/usr/bin/env python3
"""The depth moment of Boussinesq's strain energy, the reference of the shifted power law at z0 >> a.

E(z) = E_s (1 + z/z0)^k = E_s (1 + k z/z0 + ...) stiffens a homogeneous half-space (E_s, nu) slowly. At
fixed punch depth the first-order change of the force is the change of the strain energy U = F d / 2
with the unperturbed strains, dF/F = (k/z0) \\int z w dV / U, w the energy density of Sneddon's punch.
Far from the punch (a << R) that is Boussinesq's point load F: w = F^2 g(theta) / (E R^4), theta from the
z axis, so \\int z w dV over a < R < z0 is (F^2/E) I ln(z0/a), I = 2 pi \\int_0^{pi/2} g cos sin dtheta.
With U = F^2 (1 - nu^2) / (4 E a) (Sneddon: d = F (1 - nu^2) / (2 E a)):

    F / F_Sneddon(E_s) - 1 = k (a/z0) [c1 ln(z0/a) + c2],   c1 = 4 I / (1 - nu^2),

c2 = O(1) from R ~ a and R ~ z0 (not computed here). Boussinesq (Johnson, Contact Mechanics, 3.1), z
into the body, rho = sqrt(r^2 + z^2), load F in +z at the origin:

    u_r = F (1 + nu) / (2 pi E rho) [r z / rho^2 - (1 - 2 nu) r / (rho + z)],
    u_z = F (1 + nu) / (2 pi E rho) [2 (1 - nu) + z^2 / rho^2].

The strains come from mpmath's numerical derivatives, the angular integral from tanh-sinh quadrature,
both at 30 digits; the value is computed twice (30 and 40 digits) and printed to the agreement.

Run: /usr/bin/python3 tests/data/generate_boussinesq_depth_moment.py [nu ...]   (a few seconds)
"""
import sys

import mpmath as mp


def depth_moment_coefficient(nu):
    nu = mp.mpf(nu)
    E = mp.mpf(1)
    F = mp.mpf(1)
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    c = F * (1 + nu) / (2 * mp.pi * E)

    def u_r(r, z):
        rho = mp.sqrt(r * r + z * z)
        return c / rho * (r * z / rho**2 - (1 - 2 * nu) * r / (rho + z))

    def u_z(r, z):
        rho = mp.sqrt(r * r + z * z)
        return c / rho * (2 * (1 - nu) + z * z / rho**2)

    def energy_density(theta):
        # on the unit sphere R = 1, where w = g(theta)
        r, z = mp.sin(theta), mp.cos(theta)
        e_rr = mp.diff(lambda x: u_r(x, z), r)
        e_tt = u_r(r, z) / r
        e_zz = mp.diff(lambda x: u_z(r, x), z)
        g_rz = mp.diff(lambda x: u_r(r, x), z) + mp.diff(lambda x: u_z(x, z), r)
        trace = e_rr + e_tt + e_zz
        return (lam * trace**2 + 2 * mu * (e_rr**2 + e_tt**2 + e_zz**2) + mu * g_rz**2) / 2

    I = 2 * mp.pi * mp.quad(lambda t: energy_density(t) * mp.cos(t) * mp.sin(t), [0, mp.pi / 4, mp.pi / 2])
    return 4 * I / (1 - nu**2)


if __name__ == "__main__":
    for nu in (sys.argv[1:] or ["0.3"]):
        mp.mp.dps = 30
        low = depth_moment_coefficient(nu)
        mp.mp.dps = 40
        high = depth_moment_coefficient(nu)
        digits = int(-mp.log10(abs(high / low - 1) + mp.mpf(10) ** -40))
        print(f"nu = {nu}: c1 = {mp.nstr(high, min(digits, 25))}  ({digits} digits agree at 30 / 40 dps)")
