#!/usr/bin/env python3
"""The cost of a ctest run: its slowest tests and the test time of each tier and label.

usage: ctest_times.py <build dir> <junit xml written by ctest --output-junit> [--slowest N]

The tiers are the labels that ./vv test selects: quick (label quick), default (every test without the label
slow, ./vv test and CI) and all (./vv test --all). A test's labels and declared resources come from
`ctest --show-only=json-v1` in the build folder, its time from the junit file. Prints markdown; exits 0 unless
the files cannot be read (the test run's own status is the caller's).
"""
import json
import subprocess
import sys
import xml.etree.ElementTree as ET


def labels_and_memory(build_dir):
    listing = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build_dir, check=True,
                             capture_output=True, text=True).stdout
    info = {}
    for test in json.loads(listing)["tests"]:
        labels, memory = [], 0
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                labels = prop["value"]
            elif prop["name"] == "RESOURCE_GROUPS":
                for group in prop["value"]:
                    for need in group["requirements"]:
                        if need[".type"] == "memory_gb":
                            memory += need["slots"]
        info[test["name"]] = (labels, memory)
    return info


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    build_dir, junit = argv[1], argv[2]
    slowest = int(argv[argv.index("--slowest") + 1]) if "--slowest" in argv else 15
    info = labels_and_memory(build_dir)
    suite = ET.parse(junit).getroot()
    runs = []
    for case in suite.iter("testcase"):
        if case.get("status") in ("notrun", "disabled"):
            continue
        name = case.get("name")
        labels, memory = info.get(name, ([], 0))
        runs.append((float(case.get("time", "0")), name, labels, memory, case.get("status")))
    runs.sort(reverse=True)

    print(f"\n## Test cost ({len(runs)} tests run, {float(suite.get('time', '0')):.0f} s wall)\n")
    print(f"The {min(slowest, len(runs))} slowest:\n")
    print("| s | test | labels | memory (GB, declared) |")
    print("|---:|---|---|---:|")
    for seconds, name, labels, memory, status in runs[:slowest]:
        failed = "" if status == "run" else f" ({status})"
        print(f"| {seconds:.1f} | {name}{failed} | {', '.join(labels)} | {memory or ''} |")

    tiers = {"quick": lambda l: "quick" in l, "default (all but slow)": lambda l: "slow" not in l,
             "slow": lambda l: "slow" in l}
    print("\nTest time by tier and label (sum of the tests' own times; wall time is less under -j):\n")
    print("| tier or label | tests | s |")
    print("|---|---:|---:|")
    for tier, member in tiers.items():
        chosen = [r for r in runs if member(r[2])]
        print(f"| tier: {tier} | {len(chosen)} | {sum(r[0] for r in chosen):.0f} |")
    by_label = {}
    for seconds, _, labels, _, _ in runs:
        for label in labels or ["(none)"]:
            count, total = by_label.get(label, (0, 0.0))
            by_label[label] = (count + 1, total + seconds)
    for label, (count, total) in sorted(by_label.items(), key=lambda item: -item[1][1]):
        print(f"| label: {label} | {count} | {total:.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
