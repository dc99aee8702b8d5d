#!/usr/bin/python3
"""Independent high-precision reference table for gradcontact (tests/data/references.jsonl).

Run with Debian's python and python3-mpmath (no pip):

    /usr/bin/python3 tests/data/generate_references.py            # writes references.jsonl + a report
    /usr/bin/python3 tests/data/generate_references.py --quick    # small subset, for development

What it does
------------
Every reference value is computed from the GENERAL rules of the MDR for the power-law graded half-space
E(z) = E0 (z/c0)^k (chapter 9), never from the chapter's closed forms:

* g(x) of (9.2) by quadrature.  For the power-law profiles f = A r^n (cone n = 1, paraboloid n = 2,
  concave paraboloid n = 2 with A = -h0/a^2) g is homogeneous, g(x) = kappa(n,k) A x^n exactly, so
  kappa(n,k) = int_0^1 n s^(n-1) (1-s^2)^((k-1)/2) ds is computed once per (n,k) by quadrature and the
  scaling is used (also for g'(x) = n kappa A x^(n-1)).
* d(a) = g(a) (9.10); adhesive: w1D(a) = -Delta_l(a) (9.46) i.e. d = g(a) - Delta_l(a).
* F = int_{-a}^{a} c_N(x) w1D(x) dx (9.11), c_N(x) = cN0 (|x|/c0)^k, cN0 = (sum (1-nu_i^2)/(h_N E0_i))^-1
  (9.4; one body on a rigid indenter: cN0 = h_N E0/(1-nu^2)), by quadrature.
* p(r;a) (9.12) with the delta contribution of the jump of w1D at x = a:
      p = cN0/(pi c0^k) [ int_r^a g'(x)(x^2-r^2)^((k-1)/2) dx + w1D(a-) (a^2-r^2)^((k-1)/2) ],  0 for r >= a,
  w(r;a) = (2 cos(k pi/2)/pi) int_0^min(r,a) x^k w1D(x) (r^2-x^2)^(-(1+k)/2) dx, by quadrature; at r = 0
  the limit w(0) = w1D(0) * [(2 cos(k pi/2)/pi) int_0^1 s^k (1-s^2)^(-(1+k)/2) ds] (the bracket by quadrature).
* constant pressure / optimal profile: the stress -> 1D map (9.13); its integral is homogeneous,
  int_x^a r (r^2-x^2)^(-(1+k)/2) dr = (a^2-x^2)^((1-k)/2) * j(k), j(k) = int_0^1 s^(-k) ds by quadrature,
  then (9.11), (9.12) by quadrature (the pressure is recomputed from w1D and must give p0 back).
* critical states: force control = the minimum over a of F(a), displacement control = the minimum over a
  of d(a): the sign change of the derivative is bracketed on a geometric scan and refined with
  mp.findroot; the derivatives are the exact Leibniz derivatives of the MDR quantities,
      d'(a) = g'(a) - Delta_l'(a),  F'(a) = 2 cN0 c0^-k [ -a^k Delta_l(a) + d'(a) int_0^a x^k dx ];
  eq. 9.48 is NOT used.  jkr_concave: periphery = w1D(a) = -Delta_l(a) (9.46), centre = p(0) = -sigma_th
  from the MDR pressure, governing = the one reached first on unloading (the larger depth),
  transition_h0 by findroot of d_P(h0) - d_C(h0).
* tangential: Ciavarella-Jaeger superposition (9.77, 9.81) of MDR pressures, forces and depths;
  stick/slip radii by findroot on the MDR force; the dissipated energy is the loop area
  |closed integral F_x du0| by quadrature along the hysteresis (unloading and reloading branch
  parametrised by the slip radius b, F_N(b) = F_N(a)(b/a)^(k+3) by the exact homogeneity of (9.11)), not 9.86.
* coefficients beta, C, h_N, h_T (9.5-9.7, 9.79) are definitions and are evaluated from their formulas;
  alpha = cN0/cT0 (9.78).

Quadrature: mpmath tanh-sinh on pieces split at the midpoint; on each piece the algebraic end-point
singularity (x - P)^e (e > -1, P an end point or a nearby singular point just outside the interval)
is removed by the substitution x - P = t^(1/(1+e)).  Working precision 56 digits, table written with
34 significant digits.  Every 7th row and every row near the contact edge is recomputed at 72 digits with a
different subdivision of the quadrature intervals, and the agreement is reported.

Inputs are exact binary doubles: k in {-0.990234375, -0.900390625, -2^-27, 0, 2^-27, 0.5, 0.900390625,
0.990234375} (for the issue's -0.99, -0.9, -1e-8, 0, 1e-8, 0.5, 0.9, 0.99), c0/a in {2^-10, 1, 2^10}
(for 1e-3, 1, 1e3), r/a in {0, 0.5, 1-2^-20, 1, 1+2^-20, 1.5, 10, 1000} (1 +- 2^-20 for 1 +- 1e-6),
a = 2^-13 m, so that r is exact.  nu in {0, 0.3, 0.49999} are the doubles nearest to those decimals.
All inputs are written with repr() of the python float (round-trips exactly) and mpmath evaluates
at the exact double value (mpf(float)).

Besides, every printed closed form of the chapter is evaluated in mpmath at every row where it applies and
compared with the MDR value; disagreements > 1e-25 (relative) are listed in the report (stdout and
tests/data/closed_form_check.txt); they are the evidence behind analytic/ERRATA.md.

The group "classical.*" holds k = 0 rows computed from the textbook formulas (Boussinesq, Sneddon, Hertz,
uniform pressure (elliptic integrals), JKR, Kendall, Mindlin, Mindlin-Deresiewicz), independent of MDR.

The groups "stress.*" hold rows in the regions where a double evaluation can cancel, with inputs that
are not exact binary stand-ins: p(0) with n + k -> 1 (tiny k), r and c within 1e-5 of a (at a contact radius that
is not a power of two), small fractions x of 1 - (1 - x)^p on the loading branch, small oscillation amplitudes.

Every row also gets a "conditioning": the relative change of its value when each input alone moves by half an
ulp (up or down, the larger), summed over the inputs, by the same rules at 34 digits (conditioning()). It is what
the rounding of the inputs justifies; cases/tools/stress.cc and tests/analytic/test_references.cc allow it plus the
method's own rounding, and no more.
"""
import argparse
import copy
import json
import math
import os
import sys
import time

import mpmath as mp
from mpmath import mpf

WORK_DPS = 56
CHECK_DPS = 72
OUT_DIGITS = 34
HERE = os.path.dirname(os.path.abspath(__file__))


class Infinite(Exception):
    pass


def X(v):
    """exact value of a JSON input (python float/int) as mpf"""
    return mpf(v)


def fmt(v):
    if v == 0:
        return "0"
    return mp.nstr(v, OUT_DIGITS, strip_zeros=False, min_fixed=0, max_fixed=0)


# --------------------------------------------------------------------------------------------
# quadrature
# --------------------------------------------------------------------------------------------
QSTAT = {"maxerr": mpf(0)}


def qs(h, Plo, alo, Phi, ahi, L=None, U=None, brk=()):
    """int_L^U h(x, x-Plo, Phi-x) dx, h ~ (x-Plo)^alo near Plo and ~ (Phi-x)^ahi near Phi
    (Plo <= L < U <= Phi; Plo/Phi may be singular points just outside [L, U])."""
    L = mpf(Plo) if L is None else mpf(L)
    U = mpf(Phi) if U is None else mpf(U)
    Plo = mpf(Plo)
    Phi = mpf(Phi)
    D = Phi - Plo
    mid = (L + U) / 2
    pts = {L, U, mid}
    if QSTAT.get("check"):
        # check mode: a different subdivision, so that the check is an independent quadrature path
        pts.update({L + (U - L) / 5, U - (U - L) / 7})
    for b in brk:
        if L < b < U:
            pts.add(mpf(b))
    pts = sorted(pts)
    tot = mpf(0)
    for y0, y1 in zip(pts[:-1], pts[1:]):
        if y1 <= mid:
            e = 1 + alo
            ie = 1 / e

            def f(t, e=e, ie=ie):
                dl = t ** ie
                return h(Plo + dl, dl, D - dl) * dl / (e * t)
            v, er = mp.quad(f, [(y0 - Plo) ** e, (y1 - Plo) ** e], error=True)
        else:
            e = 1 + ahi
            ie = 1 / e

            def f(t, e=e, ie=ie):
                dh = t ** ie
                return h(Phi - dh, D - dh, dh) * dh / (e * t)
            v, er = mp.quad(f, [(Phi - y1) ** e, (Phi - y0) ** e], error=True)
        if v != 0:
            rel = abs(er / v)
            if rel > QSTAT["maxerr"]:
                QSTAT["maxerr"] = rel
        tot += v
    return tot


_cache = {}


def cached(key, fn):
    key = (mp.mp.dps,) + key
    if key not in _cache:
        _cache[key] = fn()
    return _cache[key]


# --------------------------------------------------------------------------------------------
# coefficients (definitions 9.5-9.7, 9.79)
# --------------------------------------------------------------------------------------------
def beta(k, nu):
    return mp.sqrt((1 + k) * (1 - k * nu / (1 - nu)))


def Ccoef(k, nu):
    b = beta(k, nu)
    return 2 ** (1 + k) * mp.gamma((3 + k + b) / 2) * mp.gamma((3 + k - b) / 2) / (mp.pi * mp.gamma(2 + k))


def hN(k, nu):
    b = beta(k, nu)
    return (2 * (1 + k) * mp.cos(k * mp.pi / 2) * mp.gamma(1 + k / 2)
            / (mp.sqrt(mp.pi) * Ccoef(k, nu) * b * mp.sin(b * mp.pi / 2) * mp.gamma((1 + k) / 2)))


def hT(k, nu):
    b = beta(k, nu)
    num = 2 * b * mp.cos(k * mp.pi / 2) * mp.gamma(1 + k / 2)
    den = ((1 - nu ** 2) * mp.sqrt(mp.pi) * Ccoef(k, nu) * mp.sin(b * mp.pi / 2) * mp.gamma((3 + k) / 2)
           + b * (1 + nu) * mp.gamma(1 + k / 2))
    return num / den


class Med:
    """equivalent medium (9.4, 9.78) of a request"""

    def __init__(self, req):
        m = req["material"]
        self.E0, self.c0, self.k, self.nu = X(m["E0"]), X(m["c0"]), X(m["k"]), X(m["nu"])
        mats = [m] + ([req["material2"]] if "material2" in req else [])
        k = self.k
        self.cN0 = 1 / mp.fsum((1 - X(q["nu"]) ** 2) / (hN(k, X(q["nu"])) * X(q["E0"])) for q in mats)
        self.cT0 = 1 / mp.fsum(1 / (hT(k, X(q["nu"])) * X(q["E0"])) for q in mats)
        self.alpha = self.cN0 / self.cT0
        self.cosk = mp.cos(k * mp.pi / 2)
        self.c0k = self.c0 ** k
        self.hN = hN(k, self.nu)
        self.Estar = self.E0 / (1 - self.nu ** 2)


# --------------------------------------------------------------------------------------------
# the MDR engine
# --------------------------------------------------------------------------------------------
def kappa(n, k):
    """kappa(n,k) = int_0^1 n s^(n-1) (1-s^2)^((k-1)/2) ds  (9.2 for f = r^n at x = 1), by quadrature"""
    def run():
        return qs(lambda x, dl, dh: n * dl ** (n - 1) * (dh * (1 + x)) ** ((k - 1) / 2), 0, n - 1, 1, (k - 1) / 2)
    return cached(("kappa", n, k), run)


def g_direct(n, A, k, x):
    """(9.2) evaluated directly by quadrature for f = A r^n (used to confirm the homogeneity scaling)"""
    return x ** (1 - k) * qs(lambda r, dl, dh: n * A * dl ** (n - 1) * (dh * (x + r)) ** ((k - 1) / 2),
                             0, n - 1, x, (k - 1) / 2)


class Prof:
    def __init__(self, n, A, k):
        self.n, self.A = mpf(n), mpf(A)
        self.kap = kappa(self.n, k)
        self.gpc = self.n * self.kap * self.A   # g'(x) = gpc x^(n-1)

    def g(self, x):
        return self.kap * self.A * x ** self.n

    def gp(self, x):
        return self.gpc * x ** (self.n - 1)


def profile(req, med):
    case = req["case"]
    geo = req.get("geometry", {})
    k = med.k
    if case in ("flat_punch", "jkr_flat_punch"):
        return None
    if case == "cone":
        return Prof(1, X(geo["tan_theta"]), k)
    if case in ("paraboloid", "jkr_paraboloid", "tangential_sphere", "oscillating_sphere"):
        return Prof(2, 1 / (2 * X(geo["R"])), k)
    if case in ("power_law", "jkr_power_law"):
        return Prof(X(geo["n"]), X(geo["A"]), k)
    if case in ("concave_paraboloid", "jkr_concave"):
        return Prof(2, -X(geo["h0"]) / X(req["a"]) ** 2, k)
    raise ValueError(case)


def g_of(prof, x):
    return mpf(0) if prof is None else prof.g(x)


def Ik(k, a):
    """int_0^a x^k dx by quadrature"""
    return qs(lambda x, dl, dh: dl ** k, 0, k, a, 0)


def mdr_force(med, prof, a, d):
    k = med.k
    if prof is None:
        I = qs(lambda x, dl, dh: dl ** k * d, 0, k, a, 0)
    else:
        I = qs(lambda x, dl, dh: dl ** k * (d - prof.g(x)), 0, k, a, 0)
    return 2 * med.cN0 / med.c0k * I


def mdr_pressure(med, prof, a, d, r):
    if r >= a:
        return mpf(0)
    k = med.k
    w1Da = d - g_of(prof, a)
    term = w1Da * ((a - r) * (a + r)) ** ((k - 1) / 2)
    if prof is not None:
        if r == 0:
            e = prof.n + k - 2
            if e <= -1:
                raise Infinite("p(0) infinite for n + k <= 1")
            I = qs(lambda x, dl, dh: prof.gpc * dl ** e, 0, e, a, 0)
        else:
            I = qs(lambda x, dl, dh: prof.gp(x) * (dl * (x + r)) ** ((k - 1) / 2), r, (k - 1) / 2, a, 0)
        term += I
    return med.cN0 / (mp.pi * med.c0k) * term


def w0_norm(k):
    """(2 cos(k pi/2)/pi) int_0^1 s^k (1-s^2)^(-(1+k)/2) ds (= 1): the r -> 0 limit of (9.12)"""
    def run():
        ex = -(1 + k) / 2
        I = qs(lambda x, dl, dh: dl ** k * (dh * (1 + x)) ** ex, 0, k, 1, ex)
        return 2 * mp.cos(k * mp.pi / 2) / mp.pi * I
    return cached(("w0norm", k), run)


def mdr_disp_gen(med, w1D, a, r, w1D0, near_a=None):
    """w(r) of (9.12) for a 1D displacement w1D(x, dist_to_a) (smooth inside [0,a))"""
    k = med.k
    if r == 0:
        return w1D0 * w0_norm(k)
    ex = -(1 + k) / 2
    if r <= a:
        def h(x, dl, dh):
            return dl ** k * w1D(x, (a - r) + dh) * (dh * (r + x)) ** ex
        I = qs(h, 0, k, r, ex)
    elif r - a < a / 2:
        # virtual anchor at r just outside [0, a]; geometric break points resolve the nearby singularity
        brk = [a - (r - a) * mpf(4) ** j for j in range(0, 60) if (r - a) * mpf(4) ** j < a / 2]
        def h(x, dl, dh):
            return dl ** k * w1D(x, dh - (r - a)) * (dh * (r + x)) ** ex
        I = qs(h, 0, k, r, ex, U=a, brk=brk)
    else:
        def h(x, dl, dh):
            return dl ** k * w1D(x, dh) * (((r - a) + dh) * (r + x)) ** ex
        I = qs(h, 0, k, a, 0)
    return 2 * med.cosk / mp.pi * I


def mdr_disp(med, prof, a, d, r):
    return mdr_disp_gen(med, lambda x, da: d - g_of(prof, x), a, r, d - g_of(prof, 0))


def dl_adh(med, dgamma, a):
    """Delta_l(a) of (9.45)/(9.46), with E* h_N -> cN0"""
    return mp.sqrt(2 * mp.pi * dgamma * med.c0k * a ** (1 - med.k) / med.cN0)


# ---- constant pressure / optimal profile (9.13) ----
def jk(k):
    """j(k) = int_0^1 s^(-k) ds: int_x^a r (r^2-x^2)^(-(1+k)/2) dr = (a^2-x^2)^((1-k)/2) j(k)"""
    return cached(("jk", k), lambda: qs(lambda x, dl, dh: dl ** (-k), 0, -k, 1, 0))


def w1D_stress_direct(med, p0, a, x):
    """(9.13) by direct quadrature (check of the homogeneity scaling)"""
    k = med.k
    ex = -(1 + k) / 2
    I = qs(lambda r, dl, dh: r * p0 * (dl * (r + x)) ** ex, x, ex, a, 0)
    return 2 * med.c0k * med.cosk / med.cN0 * I


class ConstP:
    def __init__(self, med, p0, a):
        self.med, self.p0, self.a = med, p0, a
        k = med.k
        self.W0 = 2 * med.c0k * med.cosk * p0 * jk(k) / med.cN0

    def w1D(self, x, da):
        """w1D(x) with da = a - x given accurately"""
        return self.W0 * (da * (self.a + x)) ** ((1 - self.med.k) / 2)

    def depth(self):
        return self.W0 * self.a ** (1 - self.med.k)

    def force(self):
        med, a, k = self.med, self.a, self.med.k
        I = qs(lambda x, dl, dh: dl ** k * self.w1D(x, dh), 0, k, a, (1 - k) / 2)
        return 2 * med.cN0 / med.c0k * I

    def pressure(self, r):
        med, a, k = self.med, self.a, self.med.k
        if r >= a:
            return mpf(0)
        # w1D'(x) = -W0 (1-k) x (a^2-x^2)^(-(1+k)/2)
        def h(x, dl, dh):
            return self.W0 * (1 - k) * x * (dh * (a + x)) ** (-(1 + k) / 2) * (dl * (x + r)) ** ((k - 1) / 2)
        if r == 0:
            def h0(x, dl, dh):
                return self.W0 * (1 - k) * dl ** k * (dh * (a + x)) ** (-(1 + k) / 2)
            I = qs(h0, 0, k, a, -(1 + k) / 2)
        else:
            I = qs(h, r, (k - 1) / 2, a, -(1 + k) / 2)
        return med.cN0 / (mp.pi * med.c0k) * I

    def disp(self, r):
        med, a, k = self.med, self.a, self.med.k
        if r == 0:
            return self.depth() * w0_norm(k)
        ex = -(1 + k) / 2
        if r < a:
            # anchors 0 and r; a - x = (a-r) + dh; refine toward r where a is close
            brk = [r - (a - r) * mpf(4) ** j for j in range(0, 40) if (a - r) * mpf(4) ** j < r / 2]
            def h(x, dl, dh):
                return dl ** k * self.w1D(x, (a - r) + dh) * (dh * (r + x)) ** ex
            I = qs(h, 0, k, r, ex, brk=brk)
        elif r == a:
            def h(x, dl, dh):
                return dl ** k * self.W0 * (a + x) ** ((1 - k) / 2) * dh ** (-k) * (r + x) ** ex
            I = qs(h, 0, k, a, -k)
        else:
            brk = [a - (r - a) * mpf(4) ** j for j in range(0, 40) if (r - a) * mpf(4) ** j < a / 2]
            def h(x, dl, dh):
                return dl ** k * self.w1D(x, dh) * (((r - a) + dh) * (r + x)) ** ex
            I = qs(h, 0, k, a, (1 - k) / 2, brk=brk)
        return 2 * med.cosk / mp.pi * I


# --------------------------------------------------------------------------------------------
# critical states by optimisation
# --------------------------------------------------------------------------------------------
def root(f, x0):
    """secant iteration started at x0 (two close start points, so the scale of x0 is kept)"""
    x0 = mpf(x0)
    return mp.findroot(f, (x0, x0 * (1 + mpf(2) ** -20)), solver="secant")


def find_min(dfun, a_ref):
    """root of the derivative dfun where it changes sign from - to + (exponential search, then findroot);
    the MDR derivative is negative below the critical radius and positive above it"""
    step = mpf(2) ** 4
    lo = hi = mpf(a_ref)
    if dfun(lo) >= 0:
        while dfun(lo) >= 0:
            lo /= step
            if lo < mpf(10) ** -300:
                raise RuntimeError("no minimum found")
        hi = lo * step
    else:
        while dfun(hi) < 0:
            hi *= step
            if hi > mpf(10) ** 300:
                raise RuntimeError("no minimum found")
        lo = hi / step
    return mp.findroot(dfun, (lo, hi), solver="anderson")


def jkr_critical(med, prof, a_ref, dgamma, control):
    k = med.k

    def dprime(a):
        return (0 if prof is None else prof.gp(a)) - (1 - k) / (2 * a) * dl_adh(med, dgamma, a)

    def Fprime(a):
        return 2 * med.cN0 / med.c0k * (-(a ** k) * dl_adh(med, dgamma, a) + dprime(a) * Ik(k, a))
    f = Fprime if control == "force" else dprime
    ac = find_min(f, a_ref)
    dc = g_of(prof, ac) - dl_adh(med, dgamma, ac)
    Fc = mdr_force(med, prof, ac, dc)
    return ac, dc, Fc


def concave_crit(med, a, h0, dgamma, sigma, mech):
    """jkr_concave: returns (rim depth d = d0 + h0, d0, force)"""
    k = med.k
    prof = Prof(2, -h0 / a ** 2, k)
    if mech == "periphery":
        d0 = prof.g(a) - dl_adh(med, dgamma, a)
    elif mech == "centre":
        # p(0) = cN0/(pi c0^k) [ int_0^a g'(x) x^(k-1) dx + (d0 - g(a)) a^(k-1) ] = -sigma
        I = qs(lambda x, dl, dh: prof.gpc * dl ** k, 0, k, a, 0)
        d0 = prof.g(a) + (-sigma * mp.pi * med.c0k / med.cN0 - I) * a ** (1 - k)
    else:
        P = concave_crit(med, a, h0, dgamma, sigma, "periphery")
        C = concave_crit(med, a, h0, dgamma, sigma, "centre")
        return P if P[0] >= C[0] else C
    return d0 + h0, d0, mdr_force(med, prof, a, d0)


def concave_transition(med, a, dgamma, sigma, h_guess):
    f = lambda h0: (concave_crit(med, a, h0, dgamma, sigma, "periphery")[0]
                    - concave_crit(med, a, h0, dgamma, sigma, "centre")[0])
    return mp.findroot(f, (h_guess, 2 * h_guess), solver="secant")


# --------------------------------------------------------------------------------------------
# tangential (Ciavarella-Jaeger, 9.77 / 9.81)
# --------------------------------------------------------------------------------------------
def radius_from_force(med, prof, Ftarget, guess, a_scale=None):
    """b with F_N(b) = Ftarget on the paraboloid, findroot on the MDR force"""
    if Ftarget <= 0:
        return mpf(0)
    f = lambda b: mdr_force(med, prof, b, prof.g(b)) - Ftarget
    return root(f, guess)


class Osc:
    def __init__(self, med, prof, a, mu, FA):
        self.med, self.prof, self.a, self.mu = med, prof, a, mu
        k = med.k
        self.FN = mdr_force(med, prof, a, prof.g(a))
        self.da = prof.g(a)
        self.FA = FA
        if FA is not None:
            self.c = self.rad(self.FN - FA / mu)
            self.uA = mu * med.alpha * (self.da - prof.g(self.c))

    def rad(self, Ft):
        if Ft <= 0:
            return mpf(0)
        k = self.med.k
        guess = self.a * (Ft / self.FN) ** (1 / (k + 3))   # homogeneity, refined on the MDR force
        return radius_from_force(self.med, self.prof, Ft, guess)

    def rad_d(self, dt):
        return root(lambda b: self.prof.g(b) - dt, mp.sqrt(dt / (self.prof.kap * self.prof.A)))

    def p(self, r, b):
        if b == 0 or r >= b:
            return mpf(0)
        return mdr_pressure(self.med, self.prof, b, self.prof.g(b), r)

    # branch helpers: returns (state radius, sign structure)
    def traction(self, r, branch, Fx):
        mu, a = self.mu, self.a
        pa = self.p(r, a)
        if branch == "loading":
            c = self.rad(self.FN - Fx / mu)
            return mu * (pa - self.p(r, c))
        tauA = mu * (pa - self.p(r, self.c))
        if branch == "unloading":
            b = self.rad(self.FN - (self.FA - Fx) / (2 * mu))
            return tauA - 2 * mu * (pa - self.p(r, b))
        b = self.rad(self.FN - (Fx + self.FA) / (2 * mu))
        return -tauA + 2 * mu * (pa - self.p(r, b))

    def u_at(self, branch, Fx):
        mu, al = self.mu, self.med.alpha
        if branch == "loading":
            c = self.rad(self.FN - Fx / mu)
            return mu * al * (self.da - self.prof.g(c))
        if branch == "unloading":
            b = self.rad(self.FN - (self.FA - Fx) / (2 * mu))
            return self.uA - 2 * mu * al * (self.da - self.prof.g(b))
        b = self.rad(self.FN - (Fx + self.FA) / (2 * mu))
        return -self.uA + 2 * mu * al * (self.da - self.prof.g(b))

    def F_at(self, branch, u0):
        mu, al = self.mu, self.med.alpha
        FNf = lambda b: mdr_force(self.med, self.prof, b, self.prof.g(b)) if b > 0 else mpf(0)
        if branch == "loading":
            c = self.rad_d(self.da - u0 / (mu * al))
            return mu * (self.FN - FNf(c))
        if branch == "unloading":
            b = self.rad_d(self.da - (self.uA - u0) / (2 * mu * al))
            return self.FA - 2 * mu * (self.FN - FNf(b))
        b = self.rad_d(self.da - (u0 + self.uA) / (2 * mu * al))
        return -self.FA + 2 * mu * (self.FN - FNf(b))

    def energy(self):
        """|closed integral F_x du0| around the loop A -> E -> A, both branches parametrised by b in [c, a]"""
        mu, al, a, k = self.mu, self.med.alpha, self.a, self.med.k
        FN, FA, prof = self.FN, self.FA, self.prof

        def integrand(b):
            Fb = FN * (b / a) ** (k + 3)
            F_unl = FA - 2 * mu * (FN - Fb)
            F_rel = -FA + 2 * mu * (FN - Fb)
            dub = 2 * mu * al * prof.gp(b)   # du0/db on unloading; -du0/db on reloading
            return (F_unl - F_rel) * dub
        # unloading: u from uA (b=a) down to -uA (b=c): int_{a}^{c} F_unl du/db db; reloading back
        v = mp.quad(integrand, [self.c, a])
        return abs(v)


# --------------------------------------------------------------------------------------------
# evaluation of one request by the MDR rules
# --------------------------------------------------------------------------------------------
def evaluate(req):
    case, q = req["case"], req["quantity"]
    med = Med(req)
    k = med.k
    geo = req.get("geometry", {})
    r = X(req["r"]) if "r" in req else None
    a = X(req["a"]) if "a" in req else None
    if case == "coefficients":
        nu = med.nu
        return {"h_N": lambda: hN(k, nu), "h_T": lambda: hT(k, nu), "beta": lambda: beta(k, nu),
                "C": lambda: Ccoef(k, nu), "alpha": lambda: med.alpha}[q]()
    if case in ("flat_punch", "cone", "paraboloid", "power_law", "concave_paraboloid"):
        prof = profile(req, med)
        if q == "contact_radius":
            if "d" in req:
                dt = X(req["d"])
                return root(lambda aa: prof.g(aa) - dt, (dt / (prof.kap * prof.A)) ** (1 / prof.n))
            Ft = X(req["F"])
            guess = X(req["a_guess"])
            return root(lambda aa: mdr_force(med, prof, aa, prof.g(aa)) - Ft, guess)
        if case == "flat_punch":
            d = X(req["d"])
        elif case == "concave_paraboloid":
            d = X(req["d0"])
        else:
            d = prof.g(a)
        if q == "depth":
            return d
        if q == "force":
            return mdr_force(med, prof, a, d)
        if q == "pressure":
            return mdr_pressure(med, prof, a, d, r)
        if q == "displacement":
            return mdr_disp(med, prof, a, d, r)
    if case in ("constant_pressure", "optimal_profile"):
        p0 = X(geo["p0"]) if case == "constant_pressure" else -X(req["sigma_th"])
        cp = ConstP(med, p0, a)
        if q == "depth":
            return cp.depth()
        if q == "force":
            return cp.force()
        if q == "pressure":
            return cp.pressure(r)
        if q == "displacement":
            return cp.disp(r)
        if q == "profile":
            return cp.disp(mpf(0)) - cp.disp(r)
    if case in ("jkr_flat_punch", "jkr_paraboloid", "jkr_power_law"):
        prof = profile(req, med)
        dg = X(req["dgamma"])
        if q.startswith("critical_"):
            if case == "jkr_flat_punch":
                dc = -dl_adh(med, dg, a)
                vals = (a, dc, mdr_force(med, None, a, dc))
            else:
                key = ("crit", json.dumps([req["material"], req.get("material2"), geo, req["dgamma"], req["control"]],
                                            default=repr))
                vals = cached(key, lambda: jkr_critical(med, prof, X(req["a_guess"]), dg, req["control"]))
            return vals[["critical_radius", "critical_depth", "critical_force"].index(q)]
        if q == "contact_radius":
            guess = X(req["a_guess"])
            if "d" in req:
                dt = X(req["d"])
                return root(lambda aa: prof.g(aa) - dl_adh(med, dg, aa) - dt, guess)
            Ft = X(req["F"])
            return root(lambda aa: mdr_force(med, prof, aa, prof.g(aa) - dl_adh(med, dg, aa)) - Ft, guess)
        if case == "jkr_flat_punch":
            d = X(req["d"])
        else:
            d = prof.g(a) - dl_adh(med, dg, a)
        if q == "depth":
            return d
        if q == "force":
            return mdr_force(med, prof, a, d)
        if q == "pressure":
            return mdr_pressure(med, prof, a, d, r)
        if q == "displacement":
            return mdr_disp(med, prof, a, d, r)
    if case == "jkr_concave":
        dg, sig = X(req["dgamma"]), X(req["sigma_th"])
        if q == "transition_h0":
            return concave_transition(med, a, dg, sig, X(req["h_guess"]))
        h0 = X(geo["h0"])
        drim, d0, F = concave_crit(med, a, h0, dg, sig, req.get("mechanism", "governing"))
        if q == "critical_depth":
            return drim
        if q == "critical_force":
            return F
        if q == "pressure":
            return mdr_pressure(med, Prof(2, -h0 / a ** 2, k), a, d0, r)
    if case == "tangential_sphere":
        prof = profile(req, med)
        mu = X(req["mu"])
        o = Osc(med, prof, a, mu, None)
        if q == "stick_radius":
            return o.rad(o.FN - X(req["Fx"]) / mu)
        # the stick radius given, or the one of the force Fx (findroot on the MDR force)
        c = X(req["c"]) if "c" in req else o.rad(o.FN - X(req["Fx"]) / mu)
        if q == "traction":
            return mu * (o.p(r, a) - o.p(r, c))
        if q == "tangential_force":
            return mu * (o.FN - mdr_force(med, prof, c, prof.g(c)))
        if q == "tangential_displacement":
            return mu * med.alpha * (prof.g(a) - prof.g(c))
    if case == "oscillating_sphere":
        prof = profile(req, med)
        o = Osc(med, prof, a, X(req["mu"]), X(req["FA"]))
        if q == "traction":
            return o.traction(r, req["branch"], X(req["Fx"]))
        if q == "tangential_displacement":
            return o.u_at(req["branch"], X(req["Fx"]))
        if q == "hysteresis_force":
            return o.F_at(req["branch"], X(req["u0"]))
        if q == "dissipated_energy":
            return o.energy()
    raise ValueError("unsupported %s/%s" % (case, q))


# --------------------------------------------------------------------------------------------
# the chapter's printed closed forms (for the misprint search only)
# --------------------------------------------------------------------------------------------
def Binc(z, x, y):
    """incomplete beta, continued to x <= 0 by (9.21)"""
    if z == 0:
        return mpf(0) if x > 0 else mp.inf
    return z ** x / x * mp.hyp2f1(x, 1 - y, 1 + x, z)


def Bc(x, y):
    return mp.beta(x, y)


def near_pole(fn, k, eps=mpf(10) ** -22):
    """limit of a closed form f(k) that has a removable Gamma pole at k: (f(k+eps)+f(k-eps))/2 at high dps"""
    with mp.workdps(mp.mp.dps + 60):
        return (fn(k + eps) + fn(k - eps)) / 2


def closed_forms(req):
    """list of (label, value) of the printed chapter formulas for this request"""
    case, q = req["case"], req["quantity"]
    med = Med(req)
    k, nu, E0, c0 = med.k, med.nu, med.E0, med.c0
    if "material2" in req:
        if q == "dissipated_energy":
            # 9.86 written with the medium's tangential modulus: h_T E0 -> 2 cT0 (universal form)
            R, mu, FA = X(req["geometry"]["R"]), X(req["mu"]), X(req["FA"])
            a = X(req["a"])
            FN = 4 * med.cN0 * a ** (k + 3) / (c0 ** k * (k + 1) ** 2 * (k + 3) * R)
            qq = FA / (mu * FN)
            return [("9.86 with h_T E0 -> 2 cT0, two bodies", 2 * (k + 3) ** 2 * (k + 1) * mu ** 2 * FN ** 2 * c0 ** k
                     / ((k + 5) * med.cT0 * a ** (k + 1))
                     * (1 - (1 - qq) ** ((k + 5) / (k + 3)) - (k + 5) / (2 * (k + 3)) * qq * (1 + (1 - qq) ** (2 / (k + 3)))))]
        return []
    h = hN(k, nu)
    Es = E0 / (1 - nu ** 2)
    cs = mp.cos(k * mp.pi / 2)
    geo = req.get("geometry", {})
    r = X(req["r"]) if "r" in req else None
    a = X(req["a"]) if "a" in req else None
    out = []
    B1 = lambda z: Binc(z, (1 + k) / 2, (1 - k) / 2)

    def wflat(d, rr, aa):
        if rr <= aa:
            return d
        return cs * d / mp.pi * B1(aa ** 2 / rr ** 2)
    if case == "coefficients":
        if q == "h_N" and k == 0:
            out.append(("classical h_N(0,nu)=1", mpf(1)))
        return out
    if case == "flat_punch":
        d = X(req["d"])
        if q == "force":
            out.append(("9.16 F", 2 * h * E0 * d * a ** (1 + k) / ((1 - nu ** 2) * (1 + k) * c0 ** k)))
        if q == "pressure" and r < a:
            out.append(("9.16 p", h * E0 * d / (mp.pi * (1 - nu ** 2) * c0 ** k * (a ** 2 - r ** 2) ** ((1 - k) / 2))))
        if q == "displacement" and r > a:
            out.append(("9.16 w", wflat(d, r, a)))
    if case == "cone":
        t = X(geo["tan_theta"])
        Bh = Bc(mpf(1) / 2, (1 + k) / 2)
        if q == "depth":
            out.append(("9.20 d", a * t * Bh / 2))
        if q == "force":
            out.append(("9.20 F", h * t * Bh * E0 * a ** (k + 2) / ((1 - nu ** 2) * c0 ** k * (k + 1) * (k + 2))))
        if q == "pressure" and r < a:
            def pc(kk):
                hh = hN(kk, nu)
                Bhh = Bc(mpf(1) / 2, (1 + kk) / 2)
                return (hh * t * Bhh * E0 * r ** kk / (4 * mp.pi * (1 - nu ** 2) * c0 ** kk)
                        * (Bc(-kk / 2, (1 + kk) / 2) - Binc(r ** 2 / a ** 2, -kk / 2, (1 + kk) / 2)))
            if r == 0:
                if k > 0:
                    out.append(("9.20 p (r->0 limit)", h * t * Bh * E0 / (4 * mp.pi * (1 - nu ** 2) * c0 ** k)
                                * (a ** k / (k / 2))))
            elif k == 0:
                out.append(("9.20 p (k=0 pole, limit)", near_pole(pc, k)))
            else:
                out.append(("9.20 p", pc(k)))
        if q == "displacement" and r > a:
            z = a ** 2 / r ** 2
            pre = t * Bh * cs * a / (2 * mp.pi)
            out.append(("9.20 w printed (3+k)/2", pre * (B1(z) - r / a * Binc(z, (3 + k) / 2, (1 - k) / 2))))
            out.append(("9.20 w corrected (2+k)/2", pre * (B1(z) - r / a * Binc(z, (2 + k) / 2, (1 - k) / 2))))
    if case == "paraboloid":
        R = X(geo["R"])
        if q == "depth":
            out.append(("9.26 d", a ** 2 / ((k + 1) * R)))
        if q == "force":
            out.append(("9.26 F", 4 * h * E0 * a ** (k + 3) / ((1 - nu ** 2) * c0 ** k * (k + 1) ** 2 * (k + 3) * R)))
        if q == "pressure" and r < a:
            out.append(("9.26 p", 2 * h * E0 * a ** (k + 1) / (mp.pi * (1 - nu ** 2) * c0 ** k * (k + 1) ** 2 * R)
                        * (1 - (r / a) ** 2) ** ((1 + k) / 2)))
        if q == "displacement" and r > a:
            z = a ** 2 / r ** 2
            out.append(("9.26 w", a ** 2 * cs / ((k + 1) * mp.pi * R) * (B1(z) - r ** 2 / a ** 2 * Binc(z, (3 + k) / 2, (1 - k) / 2))))
    if case in ("power_law", "jkr_power_law"):
        n, A = X(geo["n"]), X(geo["A"])
        kap = n / 2 * Bc(n / 2, (k + 1) / 2)
        adh = case == "jkr_power_law"
        dg = X(req["dgamma"]) if adh else 0
        Dl = mp.sqrt(2 * mp.pi * dg * c0 ** k * a ** (1 - k) / (Es * h)) if (adh and a is not None) else 0
        tag = "9.58" if adh else "9.30"
        ptag = "9.59" if adh else "9.30"
        if q == "depth":
            out.append((tag + " d", kap * A * a ** n - Dl))
        if q == "force":
            Fv = 2 * h * kap * n * A * E0 * a ** (n + k + 1) / ((1 - nu ** 2) * c0 ** k * (k + 1) * (n + k + 1))
            if adh:
                Fv -= mp.sqrt(8 * mp.pi * h * dg * Es * a ** (3 + k) / ((k + 1) ** 2 * c0 ** k))
            out.append((tag + " F", Fv))
        if q == "pressure" and r < a:
            def pp(kk):
                hh = hN(kk, nu)
                kp = n / 2 * Bc(n / 2, (kk + 1) / 2)
                x = (1 - kk - n) / 2
                v = (hh * kp * n * A * E0 / (2 * mp.pi * (1 - nu ** 2) * c0 ** kk) * r ** (n + kk - 1)
                     * (Bc(x, (1 + kk) / 2) - Binc(r ** 2 / a ** 2, x, (1 + kk) / 2)))
                if adh:
                    v -= (mp.sqrt(2 * hh * dg * Es * a ** (kk - 1) / (mp.pi * c0 ** kk))
                          * (1 - (r / a) ** 2) ** ((kk - 1) / 2))
                return v
            xx = (1 - k - n) / 2
            if r == 0:
                pass
            elif xx <= 0 and xx == mp.floor(xx):
                out.append((ptag + " p (Gamma pole, limit)", near_pole(pp, k)))
            else:
                out.append((ptag + " p", pp(k)))
        if q == "displacement" and r > a:
            z = a ** 2 / r ** 2
            v = cs * kap * A * a ** n / mp.pi * (B1(z) - (r / a) ** n * Binc(z, (1 + k + n) / 2, (1 - k) / 2))
            if adh:
                v -= cs / mp.pi * Dl * B1(z)
            out.append((ptag + " w", v))
        if adh and q.startswith("critical_") and 2 * n + k - 1 > 0:
            Ct = 2 / (3 + k) if req["control"] == "force" else 2 / (1 - k)
            ac = (2 * mp.pi * dg * c0 ** k / (h * Es * Ct ** 2 * kap ** 2 * n ** 2 * A ** 2)) ** (1 / (2 * n + k - 1))
            dc = (((2 * mp.pi * dg * c0 ** k / (h * Es)) ** n * (1 / (Ct * n * kap * A)) ** (1 - k)) ** (1 / (2 * n + k - 1))
                  * (1 - n * Ct) / (n * Ct))
            Fc = (2 * (1 - Ct * (n + k + 1)) / (Ct * (n + k + 1) * (k + 1))
                  * ((2 * mp.pi * dg) ** (n + k + 1) * (c0 ** k / (h * Es)) ** (2 - n)
                     * (1 / (Ct * n * kap * A)) ** (k + 3)) ** (1 / (2 * n + k - 1)))
            out.append({"critical_radius": ("9.60 a_c", ac), "critical_depth": ("9.61 d_c", dc),
                        "critical_force": ("9.61 F_c", Fc)}[q])
            if q == "critical_force" and req["control"] == "force" and n != 1:
                # 9.62 (Jin et al.): f = r^n/(n R^(n-1)) i.e. R = (n A)^(-1/(n-1))
                R = (n * A) ** (-1 / (n - 1))
                v = (2 * (1 - k - 2 * n) / (3 * mp.pi * (n + k + 1) * (k + 1))
                     * ((2 * mp.pi) ** (n + k + 1) * ((1 - nu ** 2) / h) ** (2 - n) * ((3 + k) / (2 * kap)) ** (k + 3)
                        * (R / c0) ** (k * (n - 2)) * (E0 * R / dg) ** (n - 2)) ** (1 / (2 * n + k - 1)))
                out.append(("9.62 F_c/(1.5 pi dgamma R)", v * mpf(3) / 2 * mp.pi * dg * R))
    if case == "concave_paraboloid":
        h0, d0 = X(geo["h0"]), X(req["d0"])
        if q == "force":
            out.append(("9.34 F", 2 * h * E0 * a ** (k + 1) / ((1 - nu ** 2) * (1 + k) * c0 ** k) * (d0 + 2 * h0 / (k + 3))))
        if q == "pressure" and r < a:
            out.append(("9.34 p", h * E0 / (mp.pi * (1 - nu ** 2) * c0 ** k * (a ** 2 - r ** 2) ** ((1 - k) / 2))
                        * (d0 + 2 * h0 / (k + 1) ** 2 * (k - 1 + 2 * r ** 2 / a ** 2))))
        if q == "displacement":
            if r > a:
                z = a ** 2 / r ** 2
                out.append(("9.34 w", cs / mp.pi * (d0 * B1(z) + 2 * h0 / (k + 1) * r ** 2 / a ** 2 * Binc(z, (3 + k) / 2, (1 - k) / 2))))
            else:
                out.append(("9.32 w=d0-f", d0 + h0 * r ** 2 / a ** 2))
    if case in ("constant_pressure", "optimal_profile"):
        if case == "constant_pressure":
            p0 = X(geo["p0"])
            wc = 2 * c0 ** k * (1 - nu ** 2) * cs * p0 * a ** (1 - k) / (h * (1 - k) * E0)
            lab = "9.39/9.40"
        else:
            sig = X(req["sigma_th"])
            wc = -2 * c0 ** k * cs * a ** (1 - k) / (h * (1 - k) * Es) * sig
            lab = "9.72/9.71"
            p0 = -sig
        if q == "depth":
            out.append((lab + " w_c", wc))
            if case == "constant_pressure":
                out.append(("9.39 (F form)", 2 * c0 ** k * (1 - nu ** 2) * cs * p0 * mp.pi * a ** 2 / (h * (1 - k) * E0 * mp.pi * a ** (1 + k))))
        if q == "force":
            out.append(("9.70 F" if case == "optimal_profile" else "F=p0 pi a^2", p0 * mp.pi * a ** 2))
        if q == "pressure" and r < a:
            out.append(("9.37/9.69 p", p0))
        if q == "displacement" or q == "profile":
            def wcf(rr):
                if rr <= a:
                    return wc * mp.hyp2f1((k - 1) / 2, (1 + k) / 2, 1, rr ** 2 / a ** 2)
                return wc * (1 - k) / 2 * (a / rr) ** (1 + k) * mp.hyp2f1((1 + k) / 2, (1 + k) / 2, 2, a ** 2 / rr ** 2)
            if q == "displacement":
                out.append((lab + " w", wcf(r)))
            else:
                out.append(("9.73 f_opt", wc * (1 - mp.hyp2f1((k - 1) / 2, (1 + k) / 2, 1, r ** 2 / a ** 2))))
    if case == "jkr_flat_punch":
        dg = X(req["dgamma"])
        Dl = mp.sqrt(2 * mp.pi * dg * c0 ** k * a ** (1 - k) / (Es * h))
        if q in ("force", "pressure", "displacement"):
            d = X(req["d"])
            if q == "force":
                out.append(("9.50 F", 2 * h * E0 * d * a ** (1 + k) / ((1 - nu ** 2) * (1 + k) * c0 ** k)))
            if q == "pressure" and r < a:
                out.append(("9.50 p", h * E0 * d / (mp.pi * (1 - nu ** 2) * c0 ** k * (a ** 2 - r ** 2) ** ((1 - k) / 2))))
            if q == "displacement":
                out.append(("9.50 w", wflat(d, r, a)))
        if q == "critical_depth":
            out.append(("9.51 d_c", -Dl))
        if q == "critical_force":
            out.append(("9.52 F_c", -mp.sqrt(8 * mp.pi * dg * h * Es * a ** (3 + k) / ((k + 1) ** 2 * c0 ** k))))
    if case == "jkr_paraboloid":
        R, dg = X(geo["R"]), X(req["dgamma"])
        if a is not None:
            Dl = mp.sqrt(2 * mp.pi * dg * c0 ** k * a ** (1 - k) / (Es * h))
        if q == "depth":
            out.append(("9.53 d", a ** 2 / ((k + 1) * R) - Dl))
        if q == "force":
            out.append(("9.53 F", 4 * h * Es * a ** (k + 3) / (c0 ** k * (k + 1) ** 2 * (k + 3) * R)
                        - mp.sqrt(8 * mp.pi * dg * h * Es * a ** (3 + k) / ((k + 1) ** 2 * c0 ** k))))
        if q == "pressure" and r < a:
            out.append(("9.53 p", 2 * h * Es * a ** (k + 1) / (mp.pi * c0 ** k * (k + 1) ** 2 * R) * (1 - (r / a) ** 2) ** ((1 + k) / 2)
                        - mp.sqrt(2 * h * dg * Es * a ** (k - 1) / (mp.pi * c0 ** k)) * (1 - (r / a) ** 2) ** ((k - 1) / 2)))
        if q == "displacement" and r > a:
            z = a ** 2 / r ** 2
            out.append(("9.53 w", a ** 2 * cs / ((k + 1) * mp.pi * R)
                        * ((1 - (1 + k) * R * mp.sqrt(2 * mp.pi * dg * c0 ** k * a ** (-3 - k) / (Es * h))) * B1(z)
                           - r ** 2 / a ** 2 * Binc(z, (3 + k) / 2, (1 - k) / 2))))
        if q.startswith("critical_"):
            Ct = 2 / (3 + k) if req["control"] == "force" else 2 / (1 - k)
            base = mp.pi * (1 + k) ** 2 * R ** 2 * dg * c0 ** k / (2 * Ct ** 2 * h * Es)
            ac = base ** (1 / (3 + k))
            if q == "critical_radius":
                out.append(("9.55 a_c", ac))
            if q == "critical_depth":
                out.append(("9.56 d_c", (1 - 2 * Ct) / ((1 + k) * R) * base ** (2 / (3 + k))))
            if q == "critical_force":
                out.append(("9.56 F_c", (1 - Ct * (3 + k)) / (Ct ** 2 * (3 + k)) * 2 * mp.pi * dg * R))
                if req["control"] == "force":
                    out.append(("9.56 F_c force", -(k + 3) / 2 * mp.pi * dg * R))
                else:
                    out.append(("9.56 F_c displ", -(1 - k) * (5 + 3 * k) / (2 * (3 + k)) * mp.pi * dg * R))
    if case == "jkr_concave":
        dg, sig = X(req["dgamma"]), X(req["sigma_th"])
        Dl = mp.sqrt(2 * mp.pi * dg * c0 ** k * a ** (1 - k) / (h * Es))
        mech = req.get("mechanism", "governing")
        if q == "transition_h0":
            out.append(("derived from 9.65=9.67", (1 + k) ** 2 / 4 * (mp.pi * c0 ** k * a ** (1 - k) * sig / (h * Es) - Dl)))
            return out
        h0 = X(geo["h0"])
        dP = -Dl - h0 * (1 - k) / (1 + k)
        dC = -mp.pi * c0 ** k * a ** (1 - k) / (h * Es) * sig + (3 + k ** 2) / (1 + k) ** 2 * h0
        FP = (-mp.sqrt(8 * mp.pi * h * dg * Es * a ** (3 + k) / ((1 + k) ** 2 * c0 ** k))
              - 8 * h * Es * h0 * a ** (1 + k) / ((k + 1) ** 2 * (k + 3) * c0 ** k))
        FC = -2 * mp.pi * a ** 2 / (1 + k) * sig + 16 * h * h0 * Es * a ** (k + 1) / ((k + 1) ** 3 * (k + 3) * c0 ** k)
        if mech == "governing":
            mech = "periphery" if dP >= dC else "centre"
        if q == "critical_depth":
            out.append(("9.65 d_P" if mech == "periphery" else "9.67 d_C", dP if mech == "periphery" else dC))
        if q == "critical_force":
            out.append(("9.66 F_P" if mech == "periphery" else "9.68 F_C", FP if mech == "periphery" else FC))
        if q == "pressure" and r < a:
            if mech == "periphery":
                out.append(("9.66 p_P", h * Es / (mp.pi * c0 ** k * (a ** 2 - r ** 2) ** ((1 - k) / 2))
                            * (-Dl - 4 * h0 / (k + 1) ** 2 * (1 - r ** 2 / a ** 2))))
            else:
                out.append(("9.68 p_C", 1 / (a ** 2 - r ** 2) ** ((1 - k) / 2)
                            * (-a ** (1 - k) * sig + 4 * h * h0 * Es * r ** 2 / (mp.pi * (k + 1) ** 2 * c0 ** k * a ** 2))))
    if case in ("tangential_sphere", "oscillating_sphere"):
        R, mu = X(geo["R"]), X(req["mu"])
        hT_ = hT(k, nu)
        FN = 4 * h * E0 * a ** (k + 3) / ((1 - nu ** 2) * c0 ** k * (k + 1) ** 2 * (k + 3) * R)
        da = a ** 2 / ((k + 1) * R)
        al = h / ((1 - nu ** 2) * hT_)
        pre = 2 * h * E0 / (mp.pi * (1 - nu ** 2) * c0 ** k * (k + 1) ** 2 * R)
        P = lambda rr, b: (b ** 2 - rr ** 2) ** ((1 + k) / 2) if rr < b else mpf(0)
        if case == "tangential_sphere":
            if q == "stick_radius":
                out.append(("9.80 F_x inverted", a * (1 - X(req["Fx"]) / (mu * FN)) ** (1 / (k + 3))))
                return out
            # the stick radius given, or 9.80 inverted for the force Fx
            c = X(req["c"]) if "c" in req else a * (1 - X(req["Fx"]) / (mu * FN)) ** (1 / (k + 3))
            if q == "traction":
                out.append(("9.80 tau", mu * pre * (P(r, a) - P(r, c))))
            if q == "tangential_force":
                out.append(("9.80 F_x", mu * FN * (1 - (c / a) ** (k + 3))))
            if q == "tangential_displacement":
                out.append(("9.80 u0", mu * h / ((1 - nu ** 2) * hT_) * da * (1 - (c / a) ** 2)))
            return out
        FA = X(req["FA"])
        c = a * (1 - FA / (mu * FN)) ** (1 / (k + 3))
        uA = mu * al * da * (1 - (c / a) ** 2)
        br = req.get("branch")
        if q == "traction" and br == "unloading":
            Fx = X(req["Fx"])
            b = a * (1 - (FA - Fx) / (2 * mu * FN)) ** (1 / (k + 3))
            tau = pre * (-P(r, a) + 2 * P(r, b) - P(r, c))
            out.append(("9.82 tau printed (no mu)", tau))
            out.append(("9.82 tau with mu", mu * tau))
        if q == "tangential_displacement" and br == "unloading":
            Fx = X(req["Fx"])
            b = a * (1 - (FA - Fx) / (2 * mu * FN)) ** (1 / (k + 3))
            out.append(("9.83 u0", uA - 2 * mu * al * da * (1 - (b / a) ** 2)))
        if q == "hysteresis_force":
            u0 = X(req["u0"])
            uA85 = mu * al * da * (1 - (1 - FA / (mu * FN)) ** (2 / (k + 3)))
            if br == "unloading":
                out.append(("9.84 A->E (9.85 u_A)", FA - 2 * mu * FN * (1 - (1 + (u0 - uA85) / (2 * al * mu * da)) ** ((k + 3) / 2))))
            if br == "reloading":
                out.append(("9.84 E->F (9.85 u_A)", -FA + 2 * mu * FN * (1 - (1 - (u0 + uA85) / (2 * al * mu * da)) ** ((k + 3) / 2))))
        if q == "dissipated_energy":
            qq = FA / (mu * FN)
            W = (4 * (k + 3) ** 2 * (k + 1) * mu ** 2 * FN ** 2 * c0 ** k / ((k + 5) * hT_ * E0 * a ** (k + 1))
                 * (1 - (1 - qq) ** ((k + 5) / (k + 3)) - (k + 5) / (2 * (k + 3)) * qq * (1 + (1 - qq) ** (2 / (k + 3)))))
            out.append(("9.86 printed (h_T E0)", W))
            cT0 = hT_ * E0
            out.append(("9.86 with h_T E0 -> 2 cT0 (rigid: x1/2)", W / 2))
            if k == 0:
                G = E0 / (2 * (1 + nu))
                Gs = 4 * G / (2 - nu)
                out.append(("9.87 with G*=4G/(2-nu)", 18 * mu ** 2 * FN ** 2 / (5 * Gs * a)
                            * (1 - (1 - qq) ** (mpf(5) / 3) - mpf(5) / 6 * qq * (1 + (1 - qq) ** (mpf(2) / 3)))))
    return out


# --------------------------------------------------------------------------------------------
# classical k = 0 formulas (independent of MDR)
# --------------------------------------------------------------------------------------------
def classical(req):
    case, q = req["case"], req["quantity"]
    m = req["material"]
    E, nu = X(m["E0"]), X(m["nu"])
    Es = E / (1 - nu ** 2)
    G = E / (2 * (1 + nu))
    Gs = 4 * G / (2 - nu)   # one elastic body on a rigid indenter
    geo = req.get("geometry", {})
    a = X(req["a"]) if "a" in req else None
    r = X(req["r"]) if "r" in req else None
    if case == "coefficients":
        return {"h_N": mpf(1), "h_T": 2 / ((1 + nu) * (2 - nu)), "beta": mpf(1), "C": 2 / mp.pi,
                "alpha": (2 - nu) / (2 * (1 - nu))}[q]
    if case == "flat_punch":   # Boussinesq
        d = X(req["d"])
        if q == "force":
            return 2 * Es * a * d
        if q == "pressure":
            return Es * d / (mp.pi * mp.sqrt(a ** 2 - r ** 2))
        if q == "displacement":
            return d if r <= a else 2 * d / mp.pi * mp.asin(a / r)
    if case == "cone":   # Sneddon / Love
        t = X(geo["tan_theta"])
        if q == "depth":
            return mp.pi / 2 * a * t
        if q == "force":
            return mp.pi / 2 * Es * a ** 2 * t
        if q == "pressure":
            return Es * t / 2 * mp.acosh(a / r)
        if q == "displacement":
            if r <= a:
                return mp.pi / 2 * a * t - r * t
            return t * (a * mp.asin(a / r) - r + mp.sqrt(r ** 2 - a ** 2))
    if case == "paraboloid":   # Hertz
        R = X(geo["R"])
        if q == "depth":
            return a ** 2 / R
        if q == "force":
            return 4 * Es * a ** 3 / (3 * R)
        if q == "pressure":
            return 2 * Es * a / (mp.pi * R) * mp.sqrt(1 - r ** 2 / a ** 2)
        if q == "displacement":
            if r <= a:
                return a ** 2 / R - r ** 2 / (2 * R)
            return ((2 * a ** 2 - r ** 2) * mp.asin(a / r) + a * mp.sqrt(r ** 2 - a ** 2)) / (mp.pi * R)
        if q == "contact_radius":
            return (3 * X(req["F"]) * R / (4 * Es)) ** (mpf(1) / 3)
    if case == "constant_pressure":   # uniform circular load (Love), E(m) with parameter m = modulus^2
        p0 = X(geo["p0"])
        if q == "depth":
            return 2 * (1 - nu ** 2) * p0 * a / E
        if q == "displacement":
            if r <= a:
                return 4 * (1 - nu ** 2) * p0 * a / (mp.pi * E) * mp.ellipe(r ** 2 / a ** 2)
            m_ = a ** 2 / r ** 2
            return 4 * (1 - nu ** 2) * p0 * r / (mp.pi * E) * (mp.ellipe(m_) - (1 - m_) * mp.ellipk(m_))
    if case == "jkr_paraboloid":   # JKR
        R, dg = X(geo["R"]), X(req["dgamma"])
        if q == "force":
            return 4 * Es * a ** 3 / (3 * R) - mp.sqrt(8 * mp.pi * dg * Es * a ** 3)
        if q == "depth":
            return a ** 2 / R - mp.sqrt(2 * mp.pi * dg * a / Es)
        if q == "pressure":
            return (2 * Es * a / (mp.pi * R) * mp.sqrt(1 - r ** 2 / a ** 2)
                    - mp.sqrt(2 * dg * Es / (mp.pi * a)) / mp.sqrt(1 - r ** 2 / a ** 2))
        if req.get("control") == "force":
            ac = (9 * mp.pi * dg * R ** 2 / (8 * Es)) ** (mpf(1) / 3)
            if q == "critical_force":
                return -mpf(3) / 2 * mp.pi * dg * R
        else:
            ac = (mp.pi * dg * R ** 2 / (8 * Es)) ** (mpf(1) / 3)
            if q == "critical_force":
                return -mpf(5) / 6 * mp.pi * dg * R
        if q == "critical_radius":
            return ac
        if q == "critical_depth":
            return ac ** 2 / R - mp.sqrt(2 * mp.pi * dg * ac / Es)
    if case == "jkr_flat_punch":   # Kendall
        dg = X(req["dgamma"])
        if q == "critical_force":
            return -mp.sqrt(8 * mp.pi * dg * Es * a ** 3)
        if q == "critical_depth":
            return -mp.sqrt(2 * mp.pi * dg * a / Es)
    if case in ("tangential_sphere", "oscillating_sphere"):   # Cattaneo-Mindlin, Mindlin-Deresiewicz
        R, mu = X(geo["R"]), X(req["mu"])
        FN = 4 * Es * a ** 3 / (3 * R)
        p0 = 3 * FN / (2 * mp.pi * a ** 2)
        if case == "tangential_sphere":
            c = X(req["c"])
            if q == "traction":
                v = mp.sqrt(1 - r ** 2 / a ** 2)
                if r < c:
                    v -= c / a * mp.sqrt(1 - r ** 2 / c ** 2)
                return mu * p0 * v
            if q == "tangential_force":
                return mu * FN * (1 - (c / a) ** 3)
            if q == "tangential_displacement":
                return 3 * mu * FN / (4 * Gs * a) * (1 - (c / a) ** 2)
        if q == "dissipated_energy":
            qq = X(req["FA"]) / (mu * FN)
            return (9 * (2 - nu) * mu ** 2 * FN ** 2 / (10 * G * a)
                    * (1 - (1 - qq) ** (mpf(5) / 3) - mpf(5) / 6 * qq * (1 + (1 - qq) ** (mpf(2) / 3))))
    raise ValueError("no classical formula for %s/%s" % (case, q))


# --------------------------------------------------------------------------------------------
# conditioning: what the rounding of the inputs alone justifies
# --------------------------------------------------------------------------------------------
COND_DPS = 34
SCALAR_INPUTS = ("a", "r", "d", "F", "d0", "dgamma", "sigma_th", "mu", "c", "Fx", "FA", "u0")


def input_paths(req):
    """the numeric inputs of a request: material (and of material2 E0 and nu: k and c0 are shared),
    geometry, the scalar loads and radii"""
    paths = [("material", key) for key in ("E0", "c0", "k", "nu")]
    if "material2" in req:
        paths += [("material2", key) for key in ("E0", "nu")]
    paths += [("geometry", key) for key in sorted(req.get("geometry", {}))]
    paths += [(key,) for key in SCALAR_INPUTS if key in req]
    return paths


def leaf(req, path):
    node = req
    for key in path:
        node = node[key]
    return node


def perturbed(req, path, delta):
    q = copy.deepcopy(req)
    node = q
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = mpf(node[path[-1]]) + delta
    return q


def conditioning(req, hidden):
    """sum over the inputs of the larger relative change of the value when that input alone moves by half an
    ulp (up or down), by the same MDR rules at COND_DPS digits. A double implementation that rounds its inputs
    correctly and loses nothing else is wrong by at most this much (to first order) plus its own rounding;
    the stability table allows that and no more. Inputs equal to 0 are exact (skipped); a perturbation that
    leaves the domain is skipped."""
    with mp.workdps(COND_DPS):
        base = with_mdr(req, hidden)
        if base == 0:
            return 0.0
        total = mpf(0)
        for path in input_paths(req):
            x = float(leaf(req, path))
            if x == 0:
                continue
            half = mpf(math.ulp(x)) / 2
            worst = mpf(0)
            for delta in (half, -half):
                try:
                    v = with_mdr(perturbed(req, path, delta), hidden)
                except (Infinite, ValueError, ZeroDivisionError):
                    continue
                worst = max(worst, abs(v - base))
            total += worst
        return float(total / abs(base))


# --------------------------------------------------------------------------------------------
# the grid
# --------------------------------------------------------------------------------------------
A_REF = 2.0 ** -13          # contact radius, m
E0 = 1.0e9
KS = [-0.990234375, -0.900390625, -2.0 ** -27, 0.0, 2.0 ** -27, 0.5, 0.900390625, 0.990234375]
NUS = [0.0, 0.3, 0.49999]
C0S = [2.0 ** -10, 1.0, 2.0 ** 10]          # c0/a
RS_IN = [0.0, 0.5, 1 - 2.0 ** -20]
RS_ALL = [0.0, 0.5, 1 - 2.0 ** -20, 1.0, 1 + 2.0 ** -20, 1.5, 10.0, 1000.0]
RS_OUT = [1 - 2.0 ** -20, 1.0, 1 + 2.0 ** -20, 1.5, 10.0, 1000.0]
# thinner (nu, c0/a) set, at k in KS_THIN
THIN = [(0.0, 1.0), (0.49999, 1.0), (0.3, 2.0 ** -10), (0.3, 2.0 ** 10), (0.0, 2.0 ** -10), (0.49999, 2.0 ** 10)]
KS_THIN = [-0.900390625, 0.5]
R_PARAB = 2.0 ** -6
TAN_T = 0.25
DGAMMA = 0.0625
MU = 0.375
NS = [0.5, 1.0, 1.5, 2.0, 3.0]


def mat(k, nu=0.3, c0a=1.0, E=E0):
    return {"E0": E, "c0": c0a * A_REF, "k": k, "nu": nu}


def A_for(n):
    """power-law coefficient with f(a) ~ a^2/(2R), rounded to a power of two"""
    return 2.0 ** round(math.log2(A_REF ** (2 - n) / (2 * R_PARAB)))


def f2(v):
    """mp value -> double input"""
    return float(v)


class Builder:
    def __init__(self, quick=False):
        self.rows = []
        self.quick = quick

    def add(self, group, case, quantity, material, geometry, **inp):
        req = {"id": len(self.rows) + 1, "case": case, "quantity": quantity, "material": material}
        if "material2" in inp:
            req["material2"] = inp.pop("material2")
        req["geometry"] = geometry
        hidden = {}
        for key in ("a_guess", "h_guess"):
            if key in inp:
                hidden[key] = inp.pop(key)
        for key, v in inp.items():
            req[key] = v
        req["group"] = group
        self.rows.append((req, hidden))
        return req


def rtag(ra):
    return {0.0: "centre", 0.5: "half", 1 - 2.0 ** -20: "edge_in", 1.0: "edge", 1 + 2.0 ** -20: "edge_out",
            1.5: "near", 10.0: "far", 1000.0: "farfar"}.get(ra, "r")


def with_mdr(req, hidden):
    full = dict(req)
    full.update(hidden)
    return evaluate(full)


def build(B):
    a = A_REF
    main = [(k, 0.3, 1.0) for k in KS]
    thin = [(k, nu, c0a) for k in KS_THIN for (nu, c0a) in THIN]
    quick = B.quick
    ks_main = [k for k in KS] if not quick else [-0.900390625, 0.0, 0.5]
    main = [(k, 0.3, 1.0) for k in ks_main]
    if quick:
        thin = thin[:2]

    # ---------------- coefficients ----------------
    for k in ks_main:
        nus = NUS + ([1 / (2 + k)] if k > 0 else [])
        for nu in nus:
            for qn in ("h_N", "h_T", "beta", "C", "alpha"):
                B.add("coefficients." + qn, "coefficients", qn, mat(k, nu), {})
    # two-body alpha
    for k in ks_main[::2]:
        B.add("coefficients.alpha.two_body", "coefficients", "alpha", mat(k, 0.3), {},
              material2={"E0": 3.0e9, "c0": A_REF, "k": k, "nu": 0.0})

    # ---------------- profile cases ----------------
    def profile_rows(case, geo_of, extra_of, rs_p, rs_w, main_, thin_, cr=True, depth=True):
        for (k, nu, c0a) in main_ + thin_:
            isthin = (k, nu, c0a) in thin_ and (k, nu, c0a) not in main_
            m = mat(k, nu, c0a)
            geo = geo_of(k)
            ex = extra_of(k)
            sub = "" if not isthin else ".nu_c0"
            if depth:
                B.add(case + ".depth" + sub, case, "depth", m, geo, a=a, **ex)
            B.add(case + ".force" + sub, case, "force", m, geo, a=a, **ex)
            for ra in (rs_p if not isthin else [0.5]):
                B.add(case + ".pressure." + rtag(ra) + sub, case, "pressure", m, geo, a=a, r=ra * a, **ex)
            for ra in (rs_w if not isthin else [0.5, 1.5]):
                B.add(case + ".displacement." + rtag(ra) + sub, case, "displacement", m, geo, a=a, r=ra * a, **ex)
            if cr and not isthin:
                req = {"case": case, "quantity": "depth", "material": m, "geometry": geo, "a": a}
                req.update(ex)
                dv = evaluate(req)
                B.add(case + ".contact_radius.from_d", case, "contact_radius", m, geo, d=f2(dv))
                req["quantity"] = "force"
                Fv = evaluate(req)
                B.add(case + ".contact_radius.from_F", case, "contact_radius", m, geo, F=f2(Fv), a_guess=a)

    none = lambda k: {}
    profile_rows("flat_punch", lambda k: {}, lambda k: {"d": 2.0 ** -23}, [0.0, 0.5, 1 - 2.0 ** -20],
                 RS_ALL, main, thin, cr=False, depth=False)
    profile_rows("cone", lambda k: {"tan_theta": TAN_T}, none, RS_IN, RS_ALL, main, thin)
    profile_rows("paraboloid", lambda k: {"R": R_PARAB}, none, RS_IN + [0.9375], RS_ALL, main, thin)
    for n in NS:
        mainn = main if n in (0.5, 3.0) else [x for x in main if x[0] in (-0.990234375, -2.0 ** -27, 0.0, 0.5, 0.990234375)]
        profile_rows("power_law", lambda k, n=n: {"n": n, "A": A_for(n)}, none, RS_IN,
                     [0.0, 0.5, 1 - 2.0 ** -20, 1 + 2.0 ** -20, 10.0], mainn, thin[:2])
    # concave paraboloid (complete contact: d0 > 2(1-k) h0/(1+k)^2)
    h0 = 2.0 ** -24
    profile_rows("concave_paraboloid", lambda k: {"h0": h0},
                 lambda k: {"d0": float(h0 * (2 * (1 - k) / (1 + k) ** 2 + 0.5))},
                 RS_IN, RS_ALL, main, thin, cr=False, depth=False)

    # ---------------- constant pressure / optimal profile ----------------
    for case in ("constant_pressure", "optimal_profile"):
        for (k, nu, c0a) in main + thin:
            isthin = (k, nu, c0a) in thin
            m = mat(k, nu, c0a)
            sub = ".nu_c0" if isthin else ""
            if case == "constant_pressure":
                geo, ex = {"p0": 2.0 ** 20}, {}
            else:
                geo, ex = {}, {"sigma_th": 2.0 ** 22}
            B.add(case + ".depth" + sub, case, "depth", m, geo, a=a, **ex)
            B.add(case + ".force" + sub, case, "force", m, geo, a=a, **ex)
            for ra in ([0.0, 0.5, 1 - 2.0 ** -20] if not isthin else [0.5]):
                B.add(case + ".pressure." + rtag(ra) + sub, case, "pressure", m, geo, a=a, r=ra * a, **ex)
            for ra in (RS_ALL[1:] if not isthin else [0.5, 1.5]):
                B.add(case + ".displacement." + rtag(ra) + sub, case, "displacement", m, geo, a=a, r=ra * a, **ex)
            if case == "optimal_profile":
                for ra in ([0.5, 1 - 2.0 ** -20, 1.0] if not isthin else [0.5]):
                    B.add(case + ".profile." + rtag(ra) + sub, case, "profile", m, geo, a=a, r=ra * a, **ex)

    # ---------------- JKR ----------------
    for (k, nu, c0a) in main + thin:
        isthin = (k, nu, c0a) in thin
        m = mat(k, nu, c0a)
        sub = ".nu_c0" if isthin else ""
        # flat punch
        ds = [2.0 ** -23, -2.0 ** -26]
        for d in (ds if not isthin else ds[:1]):
            B.add("jkr_flat_punch.force" + sub, "jkr_flat_punch", "force", m, {}, a=a, d=d, dgamma=DGAMMA)
            for ra in ([0.0, 0.5, 1 - 2.0 ** -20] if not isthin else [0.5]):
                B.add("jkr_flat_punch.pressure." + rtag(ra) + sub, "jkr_flat_punch", "pressure", m, {},
                      a=a, d=d, dgamma=DGAMMA, r=ra * a)
            for ra in ([0.5, 1 + 2.0 ** -20, 10.0] if not isthin else [1.5]):
                B.add("jkr_flat_punch.displacement." + rtag(ra) + sub, "jkr_flat_punch", "displacement", m, {},
                      a=a, d=d, dgamma=DGAMMA, r=ra * a)
        for ctl in ("force", "displacement"):
            for qn in ("critical_depth", "critical_force"):
                B.add("jkr_flat_punch." + qn + sub, "jkr_flat_punch", qn, m, {}, a=a, dgamma=DGAMMA, control=ctl)

    def jkr_rows(case, geo, main_, thin_, rs_p, rs_w, n=2.0):
        for (k, nu, c0a) in main_ + thin_:
            isthin = (k, nu, c0a) in thin_
            m = mat(k, nu, c0a)
            sub = ".nu_c0" if isthin else ""
            B.add(case + ".depth" + sub, case, "depth", m, geo, a=a, dgamma=DGAMMA)
            B.add(case + ".force" + sub, case, "force", m, geo, a=a, dgamma=DGAMMA)
            for ra in (rs_p if not isthin else [0.5]):
                B.add(case + ".pressure." + rtag(ra) + sub, case, "pressure", m, geo, a=a, dgamma=DGAMMA, r=ra * a)
            for ra in (rs_w if not isthin else [0.5, 1.5]):
                B.add(case + ".displacement." + rtag(ra) + sub, case, "displacement", m, geo, a=a, dgamma=DGAMMA, r=ra * a)
            if 2 * n + k - 1 > 0.05:   # a minimum of d(a) and of F(a) exists
                for ctl in ("force", "displacement"):
                    for qn in ("critical_radius", "critical_depth", "critical_force"):
                        if qn == "critical_depth" and ctl == "force" and abs(n - (3 + k) / 2) < 1e-6:
                            continue   # d_c = 0 exactly at k = 0 (ill-conditioned near it): no relative reference
                        B.add(case + "." + qn + "." + ctl + sub, case, qn, m, geo, dgamma=DGAMMA, control=ctl, a_guess=a)
                if not isthin:
                    req = {"case": case, "quantity": "depth", "material": m, "geometry": geo, "a": a, "dgamma": DGAMMA}
                    dv = evaluate(req)
                    req["quantity"] = "force"
                    Fv = evaluate(req)
                    if dv > 0:
                        B.add(case + ".contact_radius.from_d", case, "contact_radius", m, geo, dgamma=DGAMMA, d=f2(dv), a_guess=a)
                    if Fv > 0:
                        B.add(case + ".contact_radius.from_F", case, "contact_radius", m, geo, dgamma=DGAMMA, F=f2(Fv), a_guess=a)

    jkr_rows("jkr_paraboloid", {"R": R_PARAB}, main, thin, [0.0, 0.5, 1 - 2.0 ** -20],
             [0.0, 0.5, 1 - 2.0 ** -20, 1.0, 1 + 2.0 ** -20, 1.5, 10.0, 1000.0])
    for n in NS:
        mainn = [x for x in main if x[0] in (-0.990234375, -2.0 ** -27, 0.0, 0.5, 0.990234375)] if not quick else main
        jkr_rows("jkr_power_law", {"n": n, "A": A_for(n)}, mainn, thin[:1], [0.0, 0.5, 1 - 2.0 ** -20],
                 [0.5, 1 + 2.0 ** -20, 10.0], n=n)

    # jkr_concave: sigma_th chosen so that the transition h0 is positive
    for (k, nu, c0a) in main + thin:
        isthin = (k, nu, c0a) in thin
        m = mat(k, nu, c0a)
        sub = ".nu_c0" if isthin else ""
        # float estimates, only to choose inputs
        req = {"case": "jkr_concave", "quantity": "x", "material": m, "geometry": {}, "a": a}
        med = Med(req)
        Dl = float(dl_adh(med, mpf(DGAMMA), mpf(a)))
        scale = float(mp.pi * med.c0k * mpf(a) ** (1 - med.k) / med.cN0)
        sig = float(2.0 ** round(math.log2(3 * Dl / scale)))
        ht = (1 + k) ** 2 / 4 * (scale * sig - Dl)
        hs = [float(2.0 ** round(math.log2(ht / 4))), float(2.0 ** round(math.log2(ht * 4)))]
        B.add("jkr_concave.transition_h0" + sub, "jkr_concave", "transition_h0", m, {"h0": hs[0]},
              a=a, dgamma=DGAMMA, sigma_th=sig, h_guess=ht)
        for h0 in (hs if not isthin else hs[:1]):
            for mech in ("periphery", "centre", "governing"):
                for qn in ("critical_depth", "critical_force"):
                    B.add("jkr_concave." + qn + "." + mech + sub, "jkr_concave", qn, m, {"h0": h0},
                          a=a, dgamma=DGAMMA, sigma_th=sig, mechanism=mech)
                if not isthin and mech != "governing":
                    for ra in (0.0, 0.5, 1 - 2.0 ** -20):
                        B.add("jkr_concave.pressure." + mech + "." + rtag(ra), "jkr_concave", "pressure", m, {"h0": h0},
                              a=a, dgamma=DGAMMA, sigma_th=sig, mechanism=mech, r=ra * a)

    # ---------------- tangential ----------------
    for (k, nu, c0a) in main + thin:
        isthin = (k, nu, c0a) in thin
        m = mat(k, nu, c0a)
        sub = ".nu_c0" if isthin else ""
        geo = {"R": R_PARAB}
        c = 0.75 * a
        for ra in ([0.0, 0.5, 0.875, 1 - 2.0 ** -20] if not isthin else [0.5]):
            B.add("tangential_sphere.traction." + rtag(ra) + sub, "tangential_sphere", "traction", m, geo,
                  a=a, mu=MU, c=c, r=ra * a)
        B.add("tangential_sphere.tangential_force" + sub, "tangential_sphere", "tangential_force", m, geo, a=a, mu=MU, c=c)
        B.add("tangential_sphere.tangential_displacement" + sub, "tangential_sphere", "tangential_displacement", m, geo,
              a=a, mu=MU, c=c)
        req = {"case": "paraboloid", "quantity": "force", "material": m, "geometry": geo, "a": a}
        FN = evaluate(req)
        for qf in ([0.125, 0.5, 0.875, 0.999] if not isthin else [0.5]):
            B.add("tangential_sphere.stick_radius" + sub, "tangential_sphere", "stick_radius", m, geo,
                  a=a, mu=MU, Fx=f2(qf * MU * FN))
        # oscillating
        FA = f2(0.9 * MU * FN)
        base = dict(a=a, mu=MU, FA=FA)
        B.add("oscillating_sphere.dissipated_energy" + sub, "oscillating_sphere", "dissipated_energy", m, geo, **base)
        if not isthin:
            B.add("oscillating_sphere.dissipated_energy.small", "oscillating_sphere", "dissipated_energy", m, geo,
                  a=a, mu=MU, FA=f2(0.125 * MU * FN))
        for fx in ([0.5, 0.0, -0.5] if not isthin else [0.0]):
            for br in (["unloading", "reloading", "loading"] if not isthin else ["unloading"]):
                if br == "loading" and fx <= 0:
                    continue
                Fx = f2(fx * FA) if br != "reloading" else f2(-fx * FA)
                for ra in ([0.0, 0.5, 0.875, 1 - 2.0 ** -20] if not isthin else [0.5]):
                    B.add("oscillating_sphere.traction.%s.%s" % (br, rtag(ra)) + sub, "oscillating_sphere", "traction",
                          m, geo, Fx=Fx, branch=br, r=ra * a, **base)
                B.add("oscillating_sphere.tangential_displacement." + br + sub, "oscillating_sphere",
                      "tangential_displacement", m, geo, Fx=Fx, branch=br, **base)
        o = Osc(Med({"material": m}), profile({"case": "paraboloid", "geometry": geo, "a": a}, Med({"material": m})),
                mpf(a), mpf(MU), mpf(FA))
        for fu in ([0.75, 0.0, -0.75] if not isthin else [0.0]):
            for br in ("unloading", "reloading"):
                B.add("oscillating_sphere.hysteresis_force." + br + sub, "oscillating_sphere", "hysteresis_force",
                      m, geo, u0=f2(fu * o.uA), branch=br, **base)
        if not isthin:
            B.add("oscillating_sphere.hysteresis_force.loading", "oscillating_sphere", "hysteresis_force",
                  m, geo, u0=f2(0.5 * o.uA), branch="loading", **base)

    # ---------------- two bodies ----------------
    for k in [-0.900390625, 0.5]:
        m1 = mat(k, 0.3)
        m2 = {"E0": 3.0e9, "c0": A_REF, "k": k, "nu": 0.0}
        geo = {"R": R_PARAB}
        B.add("two_body.paraboloid.force", "paraboloid", "force", m1, geo, a=a, material2=m2)
        B.add("two_body.paraboloid.pressure", "paraboloid", "pressure", m1, geo, a=a, r=0.5 * a, material2=m2)
        B.add("two_body.paraboloid.displacement", "paraboloid", "displacement", m1, geo, a=a, r=1.5 * a, material2=m2)
        B.add("two_body.tangential_sphere.tangential_displacement", "tangential_sphere", "tangential_displacement",
              m1, geo, a=a, mu=MU, c=0.5 * a, material2=m2)
        med2 = Med({"material": m1, "material2": m2})
        FN2 = float(mdr_force(med2, profile({"case": "paraboloid", "geometry": geo}, med2), mpf(a),
                              profile({"case": "paraboloid", "geometry": geo}, med2).g(mpf(a))))
        B.add("two_body.oscillating_sphere.dissipated_energy", "oscillating_sphere", "dissipated_energy",
              m1, geo, a=a, mu=MU, FA=0.5 * MU * FN2, material2=m2)
        m2s = dict(m1)
        med3 = Med({"material": m1, "material2": m2s})
        pr3 = profile({"case": "paraboloid", "geometry": geo}, med3)
        FN3 = float(mdr_force(med3, pr3, mpf(a), pr3.g(mpf(a))))
        B.add("two_body.identical.oscillating_sphere.dissipated_energy", "oscillating_sphere", "dissipated_energy",
              m1, geo, a=a, mu=MU, FA=0.5 * MU * FN3, material2=m2s)

    # ---------------- classical k = 0 ----------------
    for nu in (0.3, 0.0):
        m = mat(0.0, nu)
        B.add("classical.coefficients", "coefficients", "h_N", m, {})
        B.add("classical.coefficients", "coefficients", "h_T", m, {})
        B.add("classical.coefficients", "coefficients", "C", m, {})
        B.add("classical.coefficients", "coefficients", "alpha", m, {})
        d = 2.0 ** -23
        B.add("classical.boussinesq", "flat_punch", "force", m, {}, a=a, d=d)
        for ra in (0.0, 0.5, 1 - 2.0 ** -20):
            B.add("classical.boussinesq", "flat_punch", "pressure", m, {}, a=a, d=d, r=ra * a)
        for ra in (0.5, 1 + 2.0 ** -20, 1.5, 10.0):
            B.add("classical.boussinesq", "flat_punch", "displacement", m, {}, a=a, d=d, r=ra * a)
        g = {"tan_theta": TAN_T}
        B.add("classical.sneddon", "cone", "depth", m, g, a=a)
        B.add("classical.sneddon", "cone", "force", m, g, a=a)
        for ra in (0.5, 1 - 2.0 ** -20):
            B.add("classical.sneddon", "cone", "pressure", m, g, a=a, r=ra * a)
        for ra in (0.5, 1.0, 1.5, 10.0):
            B.add("classical.sneddon", "cone", "displacement", m, g, a=a, r=ra * a)
        g = {"R": R_PARAB}
        B.add("classical.hertz", "paraboloid", "depth", m, g, a=a)
        B.add("classical.hertz", "paraboloid", "force", m, g, a=a)
        B.add("classical.hertz", "paraboloid", "contact_radius", m, g, F=1.0, a_guess=a)
        for ra in (0.0, 0.5, 1 - 2.0 ** -20):
            B.add("classical.hertz", "paraboloid", "pressure", m, g, a=a, r=ra * a)
        for ra in (0.5, 1.0, 1 + 2.0 ** -20, 1.5, 10.0):
            B.add("classical.hertz", "paraboloid", "displacement", m, g, a=a, r=ra * a)
        g = {"p0": 2.0 ** 20}
        B.add("classical.uniform_pressure", "constant_pressure", "depth", m, g, a=a)
        for ra in (0.5, 1 - 2.0 ** -20, 1.5, 10.0):
            B.add("classical.uniform_pressure", "constant_pressure", "displacement", m, g, a=a, r=ra * a)
        g = {"R": R_PARAB}
        B.add("classical.jkr", "jkr_paraboloid", "force", m, g, a=a, dgamma=DGAMMA)
        B.add("classical.jkr", "jkr_paraboloid", "depth", m, g, a=a, dgamma=DGAMMA)
        B.add("classical.jkr", "jkr_paraboloid", "pressure", m, g, a=a, dgamma=DGAMMA, r=0.5 * a)
        for ctl in ("force", "displacement"):
            for qn in ("critical_radius", "critical_depth", "critical_force"):
                B.add("classical.jkr", "jkr_paraboloid", qn, m, g, dgamma=DGAMMA, control=ctl, a_guess=a)
        B.add("classical.kendall", "jkr_flat_punch", "critical_force", m, {}, a=a, dgamma=DGAMMA, control="force")
        B.add("classical.kendall", "jkr_flat_punch", "critical_depth", m, {}, a=a, dgamma=DGAMMA, control="force")
        for ra in (0.0, 0.5, 0.875):
            B.add("classical.mindlin", "tangential_sphere", "traction", m, g, a=a, mu=MU, c=0.75 * a, r=ra * a)
        B.add("classical.mindlin", "tangential_sphere", "tangential_force", m, g, a=a, mu=MU, c=0.75 * a)
        B.add("classical.mindlin", "tangential_sphere", "tangential_displacement", m, g, a=a, mu=MU, c=0.75 * a)
        FN = 4 * (E0 / (1 - nu ** 2)) * a ** 3 / (3 * R_PARAB)
        for qf in (0.9, 0.125):
            B.add("classical.mindlin_deresiewicz", "oscillating_sphere", "dissipated_energy", m, g, a=a, mu=MU,
                  FA=qf * MU * FN)

    stress_rows(B)


# --------------------------------------------------------------------------------------------
# stress regions: inputs that are NOT exact binary stand-ins. The grid above uses k = 2^-27,
# r = a (1 - 2^-20), F_x = fractions 1/8 ... of mu F_N: with such inputs 1 + k, 1 - r/a or 1 - F_x/(mu F_N)
# are formed without rounding, which hides the cancellations these rows are made to expose.
# --------------------------------------------------------------------------------------------
STRESS_KS = [-0.900390625, 0.0, 0.5]
STRESS_EDGE = [7.3e-6, 3.1e-7, 1.7e-9]           # 1 - r/a and 1 - c/a: within 1e-5 of the edge
STRESS_FRACTIONS = [3.7e-4, 2.2e-6]              # F_x/(mu F_N), u0/u_A of the loading branch
STRESS_AMPLITUDES = [1e-3, 2.4e-4, 3.6e-5]       # F_A/(mu F_N), the examples of the loop area
STRESS_A = 1.2345678e-4                          # a contact radius that is not a power of two (edge rows)


def stress_rows(B):
    a = A_REF
    # (A) p(0) ~ 1/(n + k - 1) with n + k - 1 -> 0: tiny k for the cone and the power law n = 1, and
    # n + k -> 1 at k far from 0 (n = 0.75, 1.25); the example first, as given.
    B.add("stress.k0_centre.cone.pressure", "cone", "pressure",
          {"E0": 49467813.677098826, "c0": 1.6332952410350124e-06, "k": 2.6108498551709687e-08, "nu": 0.0},
          {"tan_theta": 0.08939324349288046}, a=50.55419540754115, r=0.0)
    for k in (2.6108498551709687e-08, 7.3e-11, 4.1e-6):
        m = mat(k)
        B.add("stress.k0_centre.cone.pressure", "cone", "pressure", m, {"tan_theta": TAN_T}, a=a, r=0.0)
        B.add("stress.k0_centre.cone.pressure_near_axis", "cone", "pressure", m, {"tan_theta": TAN_T}, a=a, r=a * 3.3e-7)
        B.add("stress.k0_centre.power_law.pressure", "power_law", "pressure", m, {"n": 1.0, "A": A_for(1.0)}, a=a, r=0.0)
        B.add("stress.k0_centre.jkr_power_law.pressure", "jkr_power_law", "pressure", m, {"n": 1.0, "A": A_for(1.0)},
              a=a, dgamma=DGAMMA, r=0.0)
    for n, k in ((0.75, 0.2500000033), (1.25, -0.2499999967)):
        B.add("stress.k0_centre.power_law.pressure", "power_law", "pressure", mat(k), {"n": n, "A": A_for(n)}, a=a, r=0.0)

    # (D) r within 1e-5 of a: 1 - r^2/a^2 from (a - r)(a + r), not from a rounded r/a. The contact radius is
    # not a power of two here (with a = 2^-13, r/a = 1 - x is exact and its square loses only x^2: the
    # rounding that the issue is about would not happen).
    a = STRESS_A
    for k in STRESS_KS:
        m = mat(k)
        m["c0"] = a
        for x in STRESS_EDGE:
            r = a * (1 - x)
            B.add("stress.edge.cone.pressure", "cone", "pressure", m, {"tan_theta": TAN_T}, a=a, r=r)
            B.add("stress.edge.paraboloid.pressure", "paraboloid", "pressure", m, {"R": R_PARAB}, a=a, r=r)
            for n in (0.5, 1.5, 3.0):
                B.add("stress.edge.power_law.pressure", "power_law", "pressure", m, {"n": n, "A": A_for(n)}, a=a, r=r)
            B.add("stress.edge.flat_punch.pressure", "flat_punch", "pressure", m, {}, a=a, d=2.0 ** -23, r=r)
            B.add("stress.edge.jkr_paraboloid.pressure", "jkr_paraboloid", "pressure", m, {"R": R_PARAB},
                  a=a, dgamma=DGAMMA, r=r)
            B.add("stress.edge.jkr_power_law.pressure", "jkr_power_law", "pressure", m, {"n": 1.5, "A": A_for(1.5)},
                  a=a, dgamma=DGAMMA, r=r)
            h0 = 2.0 ** -24
            B.add("stress.edge.concave_paraboloid.pressure", "concave_paraboloid", "pressure", m, {"h0": h0}, a=a,
                  d0=float(h0 * (2 * (1 - k) / (1 + k) ** 2 + 0.5)), r=r)
            # c within 1e-5 of a: 1 - (c/a)^(k+3) and 1 - (c/a)^2 of 9.80
            c = a * (1 - x)
            geo = {"R": R_PARAB}
            B.add("stress.edge.tangential_sphere.tangential_force", "tangential_sphere", "tangential_force", m, geo,
                  a=a, mu=MU, c=c)
            B.add("stress.edge.tangential_sphere.tangential_displacement", "tangential_sphere",
                  "tangential_displacement", m, geo, a=a, mu=MU, c=c)
            B.add("stress.edge.tangential_sphere.traction", "tangential_sphere", "traction", m, geo,
                  a=a, mu=MU, c=c, r=0.5 * a)
        for x in STRESS_EDGE[:2]:
            for ra in (1 - x, 1 + x):
                B.add("stress.edge.cone.displacement", "cone", "displacement", m, {"tan_theta": TAN_T}, a=a, r=a * ra)
                B.add("stress.edge.power_law.displacement", "power_law", "displacement", m, {"n": 1.5, "A": A_for(1.5)},
                      a=a, r=a * ra)

    # (B) 1 - (1 - x)^p with small x: the loading branch at small F_x or u0, from F_x instead of c
    a = A_REF
    for k in STRESS_KS:
        m = mat(k)
        geo = {"R": R_PARAB}
        med = Med({"material": m})
        prof = profile({"case": "paraboloid", "geometry": geo}, med)
        FN = mdr_force(med, prof, mpf(a), prof.g(mpf(a)))
        for f in STRESS_FRACTIONS:
            Fx = f2(f * MU * FN)
            for qn in ("tangential_force", "tangential_displacement", "stick_radius"):
                B.add("stress.small_fraction.tangential_sphere." + qn, "tangential_sphere", qn, m, geo, a=a, mu=MU, Fx=Fx)
            for ra in (0.0, 0.5):
                B.add("stress.small_fraction.tangential_sphere.traction", "tangential_sphere", "traction", m, geo,
                      a=a, mu=MU, Fx=Fx, r=ra * a)
        FA = f2(0.6 * MU * FN)
        o = Osc(med, prof, mpf(a), mpf(MU), mpf(FA))
        for f in STRESS_FRACTIONS:
            base = dict(a=a, mu=MU, FA=FA)
            B.add("stress.small_fraction.oscillating_sphere.hysteresis_force.loading", "oscillating_sphere",
                  "hysteresis_force", m, geo, u0=f2(f * o.uA), branch="loading", **base)
            B.add("stress.small_fraction.oscillating_sphere.tangential_displacement.loading", "oscillating_sphere",
                  "tangential_displacement", m, geo, Fx=f2(f * FA), branch="loading", **base)
            B.add("stress.small_fraction.oscillating_sphere.traction.loading", "oscillating_sphere", "traction", m, geo,
                  Fx=f2(f * FA), branch="loading", r=0.5 * a, **base)

        # (C) small amplitudes: the loop area is O(phi^3), each branch is 1 - (1 - x)^p with x = O(phi), and
        # the middle of the loop (F_x = 0, u0 = 0) is a second difference, O(phi^2)
        for phi in STRESS_AMPLITUDES:
            FA = f2(phi * MU * FN)
            base = dict(a=a, mu=MU, FA=FA)
            o = Osc(med, prof, mpf(a), mpf(MU), mpf(FA))
            B.add("stress.small_amplitude.oscillating_sphere.dissipated_energy", "oscillating_sphere",
                  "dissipated_energy", m, geo, **base)
            for br in ("unloading", "reloading"):
                for fu in (0.75, 0.0, -0.75, -0.999):
                    u0 = f2(fu * o.uA) if br == "unloading" else f2(-fu * o.uA)
                    B.add("stress.small_amplitude.oscillating_sphere.hysteresis_force." + br, "oscillating_sphere",
                          "hysteresis_force", m, geo, u0=u0, branch=br, **base)
                for fx in (0.5, 0.0, -0.5):
                    Fx = f2(fx * FA) if br == "unloading" else f2(-fx * FA)
                    B.add("stress.small_amplitude.oscillating_sphere.tangential_displacement." + br,
                          "oscillating_sphere", "tangential_displacement", m, geo, Fx=Fx, branch=br, **base)
                    if br == "unloading" or fx == 0.0:
                        for ra in (0.0, 0.5):
                            B.add("stress.small_amplitude.oscillating_sphere.traction." + br, "oscillating_sphere",
                                  "traction", m, geo, Fx=Fx, branch=br, r=ra * a, **base)



def extra_checks():
    """checks of printed relations that are not table quantities; returns report lines"""
    L = []
    a = mpf(A_REF)
    # homogeneity used for g(x): direct quadrature of (9.2) vs kappa A x^n
    worst = mpf(0)
    for k in KS:
        for n in NS:
            km = mpf(k)
            x = a * mpf(0.7)
            worst = max(worst, rel(g_direct(mpf(n), mpf(1), km, x), kappa(mpf(n), km) * x ** mpf(n)))
    L.append("(9.2) by direct quadrature at x = 0.7a vs kappa(n,k) x^n (homogeneity): worst %s" % mp.nstr(worst, 3))
    worst = mpf(0)
    for k in KS:
        med = Med({"material": mat(k)})
        cp = ConstP(med, mpf(2) ** 20, a)
        for xf in (0, 0.5, 1 - 2.0 ** -20):
            x = a * mpf(xf)
            worst = max(worst, rel(w1D_stress_direct(med, mpf(2) ** 20, a, x), cp.w1D(x, a - x)))
    L.append("(9.13) by direct quadrature vs (a^2-x^2)^((1-k)/2) j(k) (homogeneity): worst %s" % mp.nstr(worst, 3))
    # 9.29 kappa(1,0) = pi/2, kappa(2,0) = 2
    L.append("(9.29) kappa(1,0) - pi/2 = %s, kappa(2,0) - 2 = %s" % (
        mp.nstr(kappa(mpf(1), mpf(0)) - mp.pi / 2, 3), mp.nstr(kappa(mpf(2), mpf(0)) - 2, 3)))
    # 9.57 / 9.63 dimensionless forms at a = 2 a_c and a = a_c/2
    worst57 = mpf(0)
    for case, n in (("jkr_paraboloid", 2.0), ("jkr_power_law", 1.5), ("jkr_power_law", 3.0)):
        for k in (-0.900390625, 0.0, 0.5, 0.900390625):
            for ctl in ("force", "displacement"):
                req = {"case": case, "material": mat(k), "dgamma": DGAMMA, "control": ctl,
                       "geometry": {"R": R_PARAB} if case == "jkr_paraboloid" else {"n": n, "A": A_for(n)}}
                med = Med(req)
                prof = profile(req, med)
                dg = mpf(DGAMMA)
                ac, dc, Fc = jkr_critical(med, prof, a, dg, ctl)
                km, nm = med.k, mpf(n)
                Ct = 2 / (3 + km) if ctl == "force" else 2 / (1 - km)
                for at in (mpf(2), mpf(1) / 2):
                    if abs(1 - Ct * nm) < mpf(10) ** -6:
                        continue   # d_c = 0 (n = (3+k)/2 under force control)
                    aa = at * ac
                    d = prof.g(aa) - dl_adh(med, dg, aa)
                    F = mdr_force(med, prof, aa, d)
                    dt = 1 / (1 - Ct * nm) * (at ** nm - nm * Ct * at ** ((1 - km) / 2))
                    Ft = 1 / (1 - Ct * (nm + km + 1)) * (at ** (nm + km + 1) - Ct * (nm + km + 1) * at ** ((km + 3) / 2))
                    worst57 = max(worst57, rel(d / dc, dt), rel(F / Fc, Ft))
    L.append("(9.57)/(9.63) dimensionless d/d_c, F/F_c at a = 2a_c, a_c/2 vs MDR: worst %s" % mp.nstr(worst57, 3))
    # 9.22 cone a/a_h at equal force
    worst = mpf(0)
    for k in KS:
        for c0a in C0S:
            req = {"case": "cone", "material": mat(k, 0.3, c0a), "geometry": {"tan_theta": TAN_T}}
            med = Med(req)
            prof = profile(req, med)
            F = mdr_force(med, prof, a, prof.g(a))
            Es = med.E0 / (1 - med.nu ** 2)
            ah = mp.sqrt(2 * F / (mp.pi * Es * mpf(TAN_T)))
            km = med.k
            Bh = mp.beta(mpf(1) / 2, (1 + km) / 2)
            v = ((mp.pi * (1 + km) * (2 + km) / (2 * med.hN * Bh)) ** (1 / (2 + km)) * (med.c0 / ah) ** (km / (2 + km)))
            worst = max(worst, rel(a / ah, v))
    L.append("(9.22) cone a/a_h vs MDR: worst %s" % mp.nstr(worst, 3))
    # 9.35 complete-contact threshold: p(0) = 0 at d0 = 2(1-k) h0/(1+k)^2, and the force form
    worst = mpf(0)
    for k in KS:
        h0 = mpf(2) ** -24
        req = {"case": "concave_paraboloid", "material": mat(k), "geometry": {"h0": float(h0)}, "a": A_REF}
        med = Med(req)
        prof = profile(req, med)
        km = med.k
        d0 = 2 * (1 - km) * h0 / (1 + km) ** 2
        p0 = mdr_pressure(med, prof, a, d0, mpf(0))
        scale = med.cN0 / (mp.pi * med.c0k) * h0 * a ** (km - 1)
        F = mdr_force(med, prof, a, d0)
        F35 = 16 * med.hN * med.E0 * a ** (1 + km) * h0 / ((1 - med.nu ** 2) * med.c0k * (1 + km) ** 3 * (3 + km))
        worst = max(worst, abs(p0 / scale), rel(F, F35))
    L.append("(9.35) p(0) at the threshold d0 (relative to the pressure scale) and F threshold: worst %s" % mp.nstr(worst, 3))
    # 9.44 Gibson: p/w inside a paraboloid contact vs 2E0/(3c0)
    for k, nu in ((0.990234375, 0.49999), (0.990234375, 0.5), (0.9990234375, 0.5)):
        req = {"case": "paraboloid", "material": mat(k, nu), "geometry": {"R": R_PARAB}}
        med = Med(req)
        prof = profile(req, med)
        r = a / 2
        ratio = mdr_pressure(med, prof, a, prof.g(a), r) / mdr_disp(med, prof, a, prof.g(a), r)
        L.append("(9.44) Gibson, k=%s nu=%s: (p/w)/(2E0/(3c0)) - 1 = %s (h_N = %s, pi/2 = %s)" % (
            k, nu, mp.nstr(ratio / (2 * med.E0 / (3 * med.c0)) - 1, 4), mp.nstr(med.hN, 8), mp.nstr(mp.pi / 2, 8)))
    return L

# --------------------------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------------------------
def rel(a, b):
    if a == b:
        return mpf(0)
    return abs(a - b) / max(abs(a), abs(b))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=os.path.join(HERE, "references.jsonl"))
    ap.add_argument("--report", default=os.path.join(HERE, "closed_form_check.txt"))
    ap.add_argument("--check-every", type=int, default=7, help="recompute every n-th row at %d digits" % CHECK_DPS)
    ap.add_argument("--no-conditioning", action="store_true",
                    help="leave out the conditioning column (half-ulp input perturbations, the slow part)")
    ap.add_argument("--only-group", default="", help="keep only the rows whose group starts with this (development)")
    args = ap.parse_args()
    t0 = time.time()
    mp.mp.dps = WORK_DPS
    B = Builder(args.quick)
    build(B)
    if args.only_group:
        B.rows = [(r, h) for (r, h) in B.rows if r["group"].startswith(args.only_group)]
    print("rows:", len(B.rows), "built in %.1f s" % (time.time() - t0), flush=True)

    out_rows = []
    cf = {}          # label -> [count, max rel, example]
    cf_fail = {}     # label -> count of disagreements > 1e-25
    cls_max = mpf(0)
    worst_check = (mpf(0), None)
    nchecked = 0
    skipped = []
    for i, (req, hidden) in enumerate(B.rows):
        mp.mp.dps = WORK_DPS
        try:
            if req["group"].startswith("classical."):
                v = classical(req)
                vm = with_mdr(req, hidden)   # and the MDR at k = 0 for comparison
                e = rel(v, vm)
                cls_max = max(cls_max, e)
                if e > mpf(10) ** -30:
                    print("CLASSICAL MISMATCH", req["group"], req["quantity"], fmt(v), fmt(vm), mp.nstr(e, 3))
            else:
                v = with_mdr(req, hidden)
        except Infinite as ex:
            skipped.append((req["group"], str(ex)))
            continue
        if args.check_every and (i % args.check_every == 0 or "edge" in req["group"] or req["group"].startswith("stress.")):
            mp.mp.dps = CHECK_DPS
            QSTAT["check"] = True
            v2 = classical(req) if req["group"].startswith("classical.") else with_mdr(req, hidden)
            e = rel(v, v2)
            nchecked += 1
            if e > worst_check[0]:
                worst_check = (e, req)
            mp.mp.dps = WORK_DPS
            QSTAT["check"] = False
        # chapter closed forms
        if not req["group"].startswith("classical."):
            try:
                forms = closed_forms(req)
            except (ZeroDivisionError, ValueError) as ex:
                forms = [("closed form failed: %s %s" % (req["case"], req["quantity"]), mp.nan)]
            for lab, cv in forms:
                e = rel(cv, v) if mp.isfinite(cv) else mpf(1)
                s = cf.setdefault(lab, [0, mpf(0), None])
                s[0] += 1
                if e > s[1]:
                    s[1] = e
                    s[2] = (req, fmt(cv), fmt(v))
                if e > mpf(10) ** -25:
                    cf_fail[lab] = cf_fail.get(lab, 0) + 1
        row = dict(req)
        row["reference"] = fmt(v)
        if not args.no_conditioning:
            row["conditioning"] = float("%.3e" % conditioning(req, hidden))
        out_rows.append(row)
        if (i + 1) % 200 == 0:
            print("  %d/%d  %.1f s" % (i + 1, len(B.rows), time.time() - t0), flush=True)

    with open(args.out, "w") as fh:
        for row in out_rows:
            fh.write(json.dumps(row) + "\n")

    lines = []
    lines.append("gradcontact reference generator report")
    lines.append("rows written: %d (skipped: %d)" % (len(out_rows), len(skipped)))
    counts = {}
    for row in out_rows:
        counts[row["case"]] = counts.get(row["case"], 0) + 1
    for c in sorted(counts):
        lines.append("  %-20s %5d" % (c, counts[c]))
    lines.append("self-consistency: %d rows recomputed at %d digits (work %d): worst relative difference %s (%s)"
                 % (nchecked, CHECK_DPS, WORK_DPS, mp.nstr(worst_check[0], 3),
                    worst_check[1]["group"] if worst_check[1] else "-"))
    lines.append("largest quadrature error estimate (relative, per piece): %s" % mp.nstr(QSTAT["maxerr"], 3))
    lines.append("classical k=0 formulas vs MDR: worst relative difference %s" % mp.nstr(cls_max, 3))
    lines.append("")
    lines.append("closed forms of the chapter vs MDR (label: rows, max relative difference; rows > 1e-25)")
    for lab in sorted(cf):
        n, mx, ex = cf[lab]
        flag = "  <-- DISAGREES (%d rows)" % cf_fail[lab] if lab in cf_fail else ""
        lines.append("  %-45s %5d  %s%s" % (lab, n, mp.nstr(mx, 3), flag))
        if lab in cf_fail and ex is not None:
            req, cv, mv = ex
            lines.append("      worst: %s k=%s nu=%s c0=%s %s closed=%s mdr=%s" % (
                req["group"], req["material"]["k"], req["material"]["nu"], req["material"]["c0"],
                {kk: req[kk] for kk in ("a", "r", "d", "d0", "F", "Fx", "u0", "FA", "control", "mechanism", "branch") if kk in req},
                cv, mv))
    lines.append("")
    lines.append("further checks of printed relations (MDR at %d digits):" % WORK_DPS)
    mp.mp.dps = WORK_DPS
    lines.extend("  " + x for x in extra_checks())
    lines.append("skipped rows (infinite values): " + ", ".join(sorted(set(g for g, _ in skipped))))
    lines.append("")
    lines.append("total time %.1f s" % (time.time() - t0))
    txt = "\n".join(lines)
    print(txt)
    with open(args.report, "w") as fh:
        fh.write(txt + "\n")


if __name__ == "__main__":
    main()
