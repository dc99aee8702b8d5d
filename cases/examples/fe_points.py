#!/usr/bin/env python3
"""Many FE points from a script: `gradcontact eval` with "method": "fe" (JSON Lines).

Usage: python3 cases/examples/fe_points.py [GRADCONTACT] [--k K] [--tolerance TOL]
       (GRADCONTACT defaults to build/cases/gradcontact)

Writes one batch of requests to one `gradcontact eval` process: the force and the depth of a paraboloid at ten
contact radii, its pressure p(r) at three radii and its surface displacement w(2 a), each answered twice, by the FE
model at the asked relative tolerance ("method": "fe") and by the closed form (the default method). The FE answers
{"id", "value", "error_estimate", "relative_error_estimate", "dofs"} or {"id", "error"} when it cannot vouch for a
value (the accuracy contract, fem/README.md). One FE state per (k, nu, tolerance, profile) answers every E0, c0,
contact radius and R by the power law's similarity, so the whole batch costs one ladder of FE solves. The request
vocabulary is in analytic/README.md.

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

# One process for the whole batch: the requests go in, one answer a line comes out, in order.
run = subprocess.run([args.gradcontact, "eval"], input="\n".join(lines) + "\n", capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"gradcontact eval failed ({run.returncode}): {run.stderr}")
answers = {}
for line in run.stdout.splitlines():
    answer = json.loads(line)
    answers[answer["id"]] = answer

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
