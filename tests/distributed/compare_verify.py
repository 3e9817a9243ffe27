#!/usr/bin/env python3
"""Compares `veridem verify --json` results of the same cases on several rank counts.

usage: compare_verify.py ONE.json OTHER.json [OTHER.json ...] [--max-relative R]

Every quantity of every case in ONE (one process) must be in each OTHER with the same verdict,
and its measured value within R relative to ONE's (R = 0: the same bits). With R = none the values
and verdicts are printed, not compared: in chaotic many-particle flows the round-off of another
summation order grows to the spread of the realisations, so each rank count is another draw of
the case's statistics, and a quantity near its threshold may pass in one draw and fail in another
(docs/bulk-checks.md gives the comparison); the cases and their quantities must then only all be
there. Exits 1 on a mismatch.
"""
import json
import re
import sys

NUMBER = r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?"


def load(path):
    with open(path) as f:
        return {c["name"]: c for c in json.load(f)["cases"]}


def main(argv):
    limit = 0.0
    if "--max-relative" in argv:
        k = argv.index("--max-relative")
        limit = float("inf") if argv[k + 1] == "none" else float(argv[k + 1])
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
            theirs = other[name]["quantities"]
            if other[name]["passed"] != case["passed"]:
                print(f"{path}: {name}: verdict {other[name]['passed']} against {case['passed']}")
                bad += 0 if limit == float("inf") else 1
            if len(theirs) != len(case["quantities"]):
                print(f"{path}: {name}: {len(theirs)} quantities against {len(case['quantities'])}")
                bad += 1
                continue
            # In the case's order; a name may hold a measured number ("at z = 3.27 D").
            for q, t in zip(case["quantities"], theirs):
                if re.sub(NUMBER, "#", q["name"]) != re.sub(NUMBER, "#", t["name"]):
                    print(f"{path}: {name}: quantity '{t['name']}' where '{q['name']}' was")
                    bad += 1
                    continue
                a, b = q["measured"], t["measured"]
                if a is None or b is None:
                    same = a is None and b is None
                    diff = 0.0 if same else float("inf")
                else:
                    diff = abs(a - b) / max(abs(a), 1e-300) if a != b else 0.0
                if limit == float("inf"):
                    verdicts = "" if t["passed"] == q["passed"] else f", verdict {t['passed']} against {q['passed']}"
                    print(f"    {name}: {q['name']}: {a!r} vs {b!r} (relative difference {diff:.3g}{verdicts}) [{path}]")
                    continue
                ok = diff <= limit and t["passed"] == q["passed"]
                print(f"{'ok ' if ok else 'BAD'} {name}: {q['name']}: {a!r} vs {b!r} "
                      f"(relative difference {diff:.3g}) [{path}]")
                bad += 0 if ok else 1
    what = "every case and quantity there" if limit == float("inf") else f"the same results (relative {limit:g})"
    print(f"PASS: {what}" if bad == 0 else f"FAIL: {bad} differences")
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
