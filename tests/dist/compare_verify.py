#!/usr/bin/env python3
"""Compares `veridem verify --json` results of the same cases on several rank counts.

usage: compare_verify.py ONE.json OTHER.json [OTHER.json ...] [--max-relative R]

Every quantity of every case in ONE (one process) must be in each OTHER with the same verdict,
and its measured value within R relative to ONE's (R = 0: the same bits). Prints each quantity's
largest difference; exits 1 on a mismatch.
"""
import json
import sys


def load(path):
    with open(path) as f:
        return {c["name"]: c for c in json.load(f)["cases"]}


def main(argv):
    limit = 0.0
    if "--max-relative" in argv:
        k = argv.index("--max-relative")
        limit = float(argv[k + 1])
        del argv[k:k + 2]
    if len(argv) < 3:
        print(__doc__)
        return 2
    one = load(argv[1])
    others = [(path, load(path)) for path in argv[2:]]
    bad = 0
    for name, case in one.items():
        for path, other in others:
            if name not in other:
                print(f"{path}: case {name} missing")
                bad += 1
                continue
            theirs = {q["name"]: q for q in other[name]["quantities"]}
            if other[name]["passed"] != case["passed"]:
                print(f"{path}: {name}: verdict {other[name]['passed']} against {case['passed']}")
                bad += 1
            for q in case["quantities"]:
                t = theirs.get(q["name"])
                if t is None:
                    print(f"{path}: {name}: quantity '{q['name']}' missing")
                    bad += 1
                    continue
                a, b = q["measured"], t["measured"]
                if a is None or b is None:
                    same = a is None and b is None
                    diff = 0.0 if same else float("inf")
                else:
                    diff = abs(a - b) / max(abs(a), 1e-300) if a != b else 0.0
                ok = diff <= limit and t["passed"] == q["passed"]
                print(f"{'ok ' if ok else 'BAD'} {name}: {q['name']}: {a!r} vs {b!r} "
                      f"(relative difference {diff:.3g}) [{path}]")
                bad += 0 if ok else 1
    print("PASS: the same results" if bad == 0 else f"FAIL: {bad} differences")
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
