#!/usr/bin/python3
"""Side by side: the ball's z(t) of several DEM8 impact runs, on the times they share.

    compare_curves.py NAME=CURVE.csv NAME=CURVE.csv [...]

Prints a table of t [ms] and each run's z [mm] at the times present in all CSVs (`t,z` [s, m],
run_impact.sh's output), then the largest |z difference| [mm] of each run against the first.
"""
import sys


def read_curve(spec):
    if "=" not in spec:
        sys.exit(f"compare_curves.py: expected NAME=CURVE.csv, found '{spec}'")
    name, path = spec.split("=", 1)
    curve = {}
    with open(path) as stream:
        for no, line in enumerate(stream, start=1):
            if no == 1 or not line.strip():
                continue
            fields = line.split(",")
            if len(fields) != 2:
                sys.exit(f"compare_curves.py: {path}:{no}: expected `t,z`, found '{line.strip()}'")
            curve[round(float(fields[0]) * 1e7)] = float(fields[1])  # key: t in units of 0.1 us
    return name, curve


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: compare_curves.py NAME=CURVE.csv NAME=CURVE.csv [...]")
    runs = [read_curve(spec) for spec in sys.argv[1:]]
    times = sorted(set.intersection(*(set(curve) for _, curve in runs)))
    print("t_ms " + " ".join(f"{name:>12s}" for name, _ in runs))
    for t in times:
        print(f"{t * 1e-4:5.1f} " + " ".join(f"{curve[t] * 1e3:12.4f}" for _, curve in runs))
    first = runs[0][1]
    for name, curve in runs[1:]:
        worst = max(times, key=lambda t: abs(curve[t] - first[t]))
        print(f"largest |{name} - {runs[0][0]}| = {abs(curve[worst] - first[worst]) * 1e3:.4f} mm at t {worst * 1e-4:.1f} ms")


if __name__ == "__main__":
    main()
