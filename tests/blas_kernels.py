#!/usr/bin/env python3
"""The same answers under every BLAS kernel this CPU runs.

usage: blas_kernels.py <gradcontact> <figure.json> <scratch folder> [series title ...]

OpenBLAS picks its kernels by CPU (Prescott, Sandybridge, Haswell, Zen, SkylakeX, Cooperlake, ...), or by the
variable OPENBLAS_CORETYPE. Their sums round differently, so an ill-conditioned factorisation can pivot differently
from one kernel to the next. The requirement: every FE point of the figure (or of the named series only) passes
its check under every kernel the CPU can run, and equals the first kernel's value within a tenth of its tolerance
(the figure's tolerance is relative to the largest |y| of its reference curve, recovered from the csv's error and
reference columns). Each kernel is confirmed by asking OpenBLAS which core it loaded under that setting; one it
does not load is reported and skipped. Exit code 0 when all agree, 1 otherwise.
"""
import csv
import ctypes
import json
import os
import subprocess
import sys

# The kernels and the CPU flags each needs (OpenBLAS 0.3.21's dynamic x86-64 targets that matter here).
KERNELS = [
    ("Prescott", {"pni"}),  # SSE3, "pni" in /proc/cpuinfo
    ("Sandybridge", {"avx"}),
    ("Haswell", {"avx2", "fma"}),
    ("Zen", {"avx2", "fma"}),
    ("SkylakeX", {"avx512f", "avx512bw", "avx512dq", "avx512vl"}),
    ("Cooperlake", {"avx512f", "avx512bw", "avx512dq", "avx512vl", "avx512_bf16"}),
]


def cpu_flags():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("flags"):
                return set(line.split(":", 1)[1].split())
    return set()


def loaded_core(kernel):
    """The core OpenBLAS loads with OPENBLAS_CORETYPE=kernel, asked in a child process (it reads the variable once)."""
    probe = ("import ctypes\nl = ctypes.CDLL('libopenblas.so.0')\n"
             "l.openblas_get_corename.restype = ctypes.c_char_p\nprint(l.openblas_get_corename().decode())")
    env = dict(os.environ, OPENBLAS_CORETYPE=kernel)
    out = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True)
    return out.stdout.strip()


def trimmed_figure(figure, series, folder):
    """The figure with only the named FE series and the reference curves they are checked against."""
    with open(figure) as f:
        spec = json.load(f)
    if series:
        keep = set(series)
        for curve in spec["curves"]:
            if curve["title"] in series:
                keep.update(curve.get("check", {}).get("curves", []))
        spec["curves"] = [c for c in spec["curves"] if c["title"] in keep]
        missing = set(series) - {c["title"] for c in spec["curves"]}
        if missing:
            raise SystemExit(f"blas_kernels: {figure} has no series {sorted(missing)}")
    path = os.path.join(folder, os.path.basename(figure))
    with open(path, "w") as f:
        json.dump(spec, f, indent=1)
    return path, spec["name"]


def points(csv_path):
    rows, count = {}, {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            if row["tolerance"] in ("", "-"):
                continue
            # keyed by the point's place in its series: its abscissa moves with the FE's own critical radius
            index = count[row["series"]] = count.get(row["series"], -1) + 1
            rows[(row["series"], index)] = row
    scale = {}
    for (series, _), row in rows.items():
        error = float(row["error"])
        if error > 0:
            scale.setdefault(series, abs(float(row["value"]) - float(row["reference"])) / error)
    return rows, scale


def main(argv):
    if len(argv) < 4:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    gradcontact, figure, folder = argv[1], argv[2], argv[3]
    os.makedirs(folder, exist_ok=True)
    path, name = trimmed_figure(figure, argv[4:], folder)
    flags = cpu_flags()
    runs, failed = {}, False
    print("| kernel | loaded | figure check | seconds |\n|---|---|---|---:|")
    for kernel, needs in KERNELS:
        if not needs <= flags:
            print(f"| {kernel} | (the CPU lacks {', '.join(sorted(needs - flags))}) | skipped | |")
            continue
        core = loaded_core(kernel)
        if core.lower() != kernel.lower():
            print(f"| {kernel} | {core or 'unknown'} (not this kernel) | skipped | |")
            continue
        reports = os.path.join(folder, kernel)
        env = dict(os.environ, OPENBLAS_CORETYPE=kernel)
        started = os.times().elapsed
        result = subprocess.run([gradcontact, "figures", path, "--reports", reports, "--no-cache"], env=env,
                                capture_output=True, text=True)
        seconds = os.times().elapsed - started
        ok = result.returncode == 0
        failed |= not ok
        print(f"| {kernel} | {core} | {'pass' if ok else 'FAIL'} | {seconds:.1f} |")
        if not ok:
            print((result.stdout + result.stderr).strip()[-2000:])
            continue
        runs[kernel] = points(os.path.join(reports, "figures", name + ".csv"))
    if len(runs) < 2 and not failed:
        print("blas_kernels: fewer than two kernels ran; nothing to compare")
    first = next(iter(runs), None)
    if first:
        base, scale = runs[first]
        print(f"\nAgainst {first}:\n\n| kernel | series | point | value | {first} | |difference| / (tolerance max|y|) |")
        print("|---|---|---:|---:|---:|---:|")
        for kernel, (rows, _) in list(runs.items())[1:]:
            for key, row in base.items():
                other = rows.get(key)
                if other is None:
                    print(f"| {kernel} | {key[0]} | {key[1]} | missing | | |")
                    failed = True
                    continue
                ratio = abs(float(other["value"]) - float(row["value"])) / (float(row["tolerance"]) *
                                                                            scale.get(key[0], 1.0))
                bad = not ratio <= 0.1
                failed |= bad
                if bad or kernel == list(runs)[-1]:
                    print(f"| {kernel} | {key[0]} | {key[1]} | {other['value']} | {row['value']} | {ratio:.2e}"
                          f"{' (over 0.1)' if bad else ''} |")
    print("blas_kernels: " + ("FAIL" if failed else "every kernel gives the same answers"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
