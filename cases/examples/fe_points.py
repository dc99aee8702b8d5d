#!/usr/bin/env python3
"""Many FE points from a script: `gradcontact eval` with "method": "fe" (JSON Lines).

Usage: python3 cases/examples/fe_points.py [GRADCONTACT] [--k K] [--tolerance TOL]
       (GRADCONTACT defaults to build/cases/gradcontact)

Keeps one `gradcontact eval` process open and sends it one request at a time, reading each answer before the
next: the force and the depth of a paraboloid at ten contact radii, its pressure p(r) at three radii and its
surface displacement w(2 a), each answered twice, by the FE model at the asked relative tolerance ("method": "fe")
and by the closed form (the default method). The FE answers {"id", "value", "error_estimate",
"relative_error_estimate", "dofs", "formulation"} or {"id", "error"} when it cannot vouch for a value (the accuracy
contract, fem/README.md). One FE state per (k, nu, tolerance, profile) answers every E0, c0, contact radius and R by
the power law's similarity: the first FE request costs one ladder of FE solves, the later ones back substitutions.
The request vocabulary is in analytic/README.md.

Prints one row per point and exits 1 when an FE answer is an error, or is further from the closed form than the
asked tolerance (relative to the value; a pressure relative to the largest |p| sampled, p(0) here).
"""
import argparse
import json
import subprocess
import sys

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("gradcontact", nargs="?", default="build/cases/gradcontact")
parser.add_argument("--k", type=float, default=0.5, help="exponent of E(z) = E0 (z/c0)^k")
parser.add_argument("--tolerance", type=float, default=1e-4, help="relative error asked of the FE, [1e-8, 1e-2]")
args = parser.parse_args()

material = {"E0": 1e9, "c0": 1e-3, "k": args.k, "nu": 0.3}
geometry = {"R": 1e-2}
a0 = 1e-4
points = []  # (label, request without id/method, scale key)
for i in range(10):
    a = a0 * 2 ** (i / 3)
    for quantity in ("force", "depth"):
        points.append((f"{quantity}(a = {a:.3e})", {"quantity": quantity, "a": a}, None))
for s in (0.0, 0.5, 0.9):
    points.append((f"p(r = {s} a)", {"quantity": "pressure", "a": a0, "r": s * a0}, "p0"))
points.append(("w(r = 2 a)", {"quantity": "displacement", "a": a0, "r": 2 * a0}, None))

lines = []
for n, (_, request, _) in enumerate(points):
    base = {"case": "paraboloid", "material": material, "geometry": geometry, **request}
    lines.append(json.dumps({"id": f"fe-{n}", "method": "fe", "tolerance": args.tolerance, **base}))
    lines.append(json.dumps({"id": f"cf-{n}", **base}))

# One process kept open: each request is written and its answer read before the next is sent (eval answers a line as
# soon as it is complete and flushes it). `gradcontact eval --batch` reads the whole input first instead, so that the
# FE samples every pressure and displacement of one state in one ladder run.
process = subprocess.Popen([args.gradcontact, "eval"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, bufsize=1)
answers = {}
for line in lines:
    process.stdin.write(line + "\n")
    process.stdin.flush()
    reply = process.stdout.readline()
    if not reply:
        sys.exit(f"gradcontact eval stopped answering: {process.stderr.read()}")
    answer = json.loads(reply)
    answers[answer["id"]] = answer
process.stdin.close()
if process.wait() != 0:
    sys.exit(f"gradcontact eval failed ({process.returncode}): {process.stderr.read()}")

p0 = answers[f"cf-{[label for label, _, _ in points].index('p(r = 0.0 a)')}"]["value"]
failures = 0
print(f"{'point':<22} {'FE':>14} {'closed form':>14} {'rel. error':>10} {'estimate':>10} {'DoFs':>8}")
for n, (label, _, scale) in enumerate(points):
    fe, cf = answers[f"fe-{n}"], answers[f"cf-{n}"]
    if "error" in fe or "error" in cf:
        failures += 1
        print(f"{label:<22} error: {fe.get('error', cf.get('error'))}")
        continue
    error = abs(fe["value"] - cf["value"]) / abs(p0 if scale == "p0" else cf["value"])
    verdict = "" if error <= args.tolerance else "  FAIL"
    failures += verdict != ""
    print(f"{label:<22} {fe['value']:>14.8e} {cf['value']:>14.8e} {error:>10.2e} "
          f"{fe['relative_error_estimate']:>10.2e} {fe['dofs']:>8}{verdict}")
print(f"{len(points)} FE points at tolerance {args.tolerance:g}, k = {args.k:g}: "
      + ("all within the tolerance" if failures == 0 else f"{failures} FAILED"))
sys.exit(1 if failures else 0)
