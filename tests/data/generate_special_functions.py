#!/usr/bin/env python3
"""Reference values for analytic/special_functions.h, from mpmath at 40 digits.

Independent path: mpmath's hyp2f1 and direct tanh-sinh quadrature of the defining integrals with the
interval split at the singular end points (an unsplit mpmath quad of int_z^1 t^(x-1)(1-t)^(y-1) dt
near z = 1 was seen to lose 12 digits). Every value is computed twice, at 40 and at 50 digits, and
the row is kept only where both agree to 30 digits.

Inputs are exact doubles (written with repr, which round-trips). Output: special_functions.csv with
columns function,a,b,c,z,reference (reference with 34 significant digits). The function hyp2f1_minus_one is
2F1(a, b; c; z) - 1, the difference formed at 40 and 50 digits.

Run: /usr/bin/python3 tests/data/generate_special_functions.py
"""
import mpmath as mp

KS = [-0.9990234375, -0.99, -0.9, -0.5, -1e-08, 0.0, 1e-08, 0.25, 0.5, 0.9, 0.99, 0.9990234375]
ZS = [0.0, 0.125, 0.5, 0.7, 0.9, 0.99, 1.0 - 2.0**-20, 1.0 - 2.0**-40, 1.0]
# 2F1 - 1 of the optimal profile (9.73) above z = 1/2, and where it is small beside the connection
# formula's region (a b -> 0 as k -> -1): the difference of F and 1 cancels there.
KS_MINUS_ONE = [-0.953125, -0.9375, -0.921875, -0.90625, -0.875, -0.84375, -0.75]
ZS_MINUS_ONE = [0.515625, 0.6875, 0.7578125]


def hyp(a, b, c, z):
    return mp.hyp2f1(a, b, c, z)


def beta_upper(z, x, y):
    # int_z^1 t^(x-1) (1-t)^(y-1) dt, split so that each singular end point is an interval end.
    f = lambda t: t ** (x - 1) * (1 - t) ** (y - 1)
    if z >= mp.mpf(1) / 2:
        w = 1 - z
        g = lambda s: (1 - s) ** (x - 1) * s ** (y - 1)
        return mp.quad(g, [0, w / 2, w])
    pts = [z, 2 * z, mp.mpf(1) / 2, 1] if 2 * z < mp.mpf(1) / 2 else [z, mp.mpf(1) / 2, 1]
    return mp.quad(f, pts)


def incomplete_beta(z, x, y):
    if x > 0:
        return mp.betainc(x, y, 0, z)
    # continuation (9.21)
    return z ** x / x * mp.hyp2f1(x, 1 - y, 1 + x, z)


def rows():
    for k in KS:
        for z in ZS:
            yield ("hyp2f1", (k - 1) / 2, (1 + k) / 2, 1.0, z)   # 9.40 / 9.71 inside
            yield ("hyp2f1", (1 + k) / 2, (1 + k) / 2, 2.0, z)   # 9.40 / 9.71 outside
    for k, z in [(k, z) for k in KS for z in ZS if z > 0.5] + [(k, z) for k in KS_MINUS_ONE for z in ZS_MINUS_ONE]:
        yield ("hyp2f1_minus_one", (k - 1) / 2, (1 + k) / 2, 1.0, z)   # 9.73
    for x in [-2.5, -2.0, -1.5, -1.0, -0.5, -1e-08, 0.0, 1e-08, 0.25, 1.5]:
        for y in [0.0009765625, 0.25, 0.75, 0.9990234375]:
            for z in [1e-06, 0.125, 0.4921875, 0.5, 0.75, 1.0 - 2.0**-20]:
                yield ("beta_upper", x, y, 0.0, z)
                if x > 0 or x != int(x):
                    yield ("incomplete_beta", x, y, 0.0, z)


def value(fn, a, b, c, z):
    a, b, c, z = (mp.mpf(v) for v in (a, b, c, z))
    if fn == "hyp2f1":
        return hyp(a, b, c, z)
    if fn == "hyp2f1_minus_one":
        return hyp(a, b, c, z) - 1
    if fn == "beta_upper":
        return beta_upper(z, a, b)
    return incomplete_beta(z, a, b)


def main():
    out = ["function,a,b,c,z,reference"]
    dropped = 0
    for fn, a, b, c, z in rows():
        mp.mp.dps = 40
        v40 = value(fn, a, b, c, z)
        mp.mp.dps = 50
        v50 = value(fn, a, b, c, z)
        if v50 == 0 or abs(v40 / v50 - 1) > mp.mpf(10) ** -30:
            dropped += 1
            continue
        out.append(f"{fn},{a!r},{b!r},{c!r},{z!r},{mp.nstr(v50, 34, strip_zeros=False)}")
    with open(__file__.replace("generate_special_functions.py", "special_functions.csv"), "w") as f:
        f.write("\n".join(out) + "\n")
    print(f"{len(out) - 1} rows written, {dropped} dropped (40 vs 50 digits disagreed)")


if __name__ == "__main__":
    main()
