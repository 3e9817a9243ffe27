#!/usr/bin/python3
"""The ball's deepest point from a (t, z) CSV of the DEM8 impact case.

    penetration.py CURVE.csv BED_TOP [BALL_RADIUS]

BED_TOP [m]: the settled bed's top (max z + r of the bed particles, convert_impact.py's bed.txt);
BALL_RADIUS [m] defaults to 0.01. Prints the lowest ball centre z [m] and its time [s] (at the
CSV's 0.5 ms sampling), the penetration depth [m] of the ball's lowest point below the bed top
(BED_TOP - (z_min - radius)), and whether the curve turned back up after that point (if it did
not, the deepest point may lie beyond the end of the run).
"""
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: penetration.py CURVE.csv BED_TOP [BALL_RADIUS]")
    bed_top = float(sys.argv[2])
    radius = float(sys.argv[3]) if len(sys.argv) == 4 else 0.01
    rows = []
    with open(sys.argv[1]) as stream:
        for no, line in enumerate(stream, start=1):
            if no == 1 or not line.strip():
                continue
            fields = line.split(",")
            if len(fields) != 2:
                sys.exit(f"penetration.py: {sys.argv[1]}:{no}: expected `t,z`, found '{line.strip()}'")
            rows.append((float(fields[0]), float(fields[1])))
    if not rows:
        sys.exit(f"penetration.py: {sys.argv[1]}: no (t, z) rows")
    t_min, z_min = min(rows, key=lambda row: row[1])
    rebounded = rows[-1][1] > z_min
    print(f"lowest z {z_min:.6f} m at t {t_min * 1e3:.2f} ms; penetration below bed top "
          f"{(bed_top - (z_min - radius)) * 1e3:.2f} mm (bed top {bed_top:.6f} m); "
          f"{'turned back up after it' if rebounded else 'STILL DESCENDING at the end of the run'}; "
          f"last t {rows[-1][0] * 1e3:.2f} ms")


if __name__ == "__main__":
    main()
