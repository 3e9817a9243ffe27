#!/usr/bin/python3
"""Snapshot of a rotating-drum run (examples/rotating_drum.toml): the bed seen along the drum's
axis (+y) at the last output, with the free surface's angle fitted to the highest bead in each of
the central bins of x, and the drive torque -ty of the wall "drum" from walls.csv against time.

usage: drum_snapshot.py OUT_DIR PNG [--radius R]   (R: drum radius [m], default 0.05)
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    out, png = sys.argv[1], sys.argv[2]
    radius = float(sys.argv[sys.argv.index("--radius") + 1]) if "--radius" in sys.argv else 0.05
    rows = list(csv.DictReader(open(f"{out}/particles.csv")))
    t_last = max(float(r["t"]) for r in rows)
    x = np.array([float(r["x"]) for r in rows if float(r["t"]) == t_last])
    z = np.array([float(r["z"]) for r in rows if float(r["t"]) == t_last])
    # Free surface: the highest bead per bin over the central 60 % of the drum's width.
    edges = np.linspace(-0.6 * radius, 0.6 * radius, 13)
    top_x, top_z = [], []
    for a, b in zip(edges[:-1], edges[1:]):
        inside = (x >= a) & (x < b)
        if inside.any():
            k = np.argmax(np.where(inside, z, -np.inf))
            top_x.append(x[k])
            top_z.append(z[k])
    slope, intercept = np.polyfit(top_x, top_z, 1)
    angle = math.degrees(math.atan(abs(slope)))
    loads = [r for r in csv.DictReader(open(f"{out}/walls.csv")) if r["wall"] == "drum"]
    t = [float(r["t"]) for r in loads]
    drive = [-float(r["ty"]) for r in loads]

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.5))
    left.add_patch(plt.Circle((0, 0), radius, fill=False, color="k"))
    left.scatter(x, z, s=4, c=z, cmap="viridis")
    xs = np.array([-0.6 * radius, 0.6 * radius])
    left.plot(xs, slope * xs + intercept, "r-", label=f"free surface, {angle:.1f} deg")
    left.set_aspect("equal")
    left.set_xlim(-1.1 * radius, 1.1 * radius)
    left.set_ylim(-1.1 * radius, 1.1 * radius)
    left.set_xlabel("x [m]")
    left.set_ylabel("z [m]")
    left.set_title(f"bed at t = {t_last:.2f} s, seen along the axis")
    left.legend(loc="upper right")
    right.plot(t, drive)
    right.set_xlabel("t [s]")
    right.set_ylabel("drive torque -ty [N m]")
    right.set_title("walls.csv: torque on the drum")
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    print(f"t = {t_last} s: surface angle {angle:.1f} deg, mean drive torque over the last half "
          f"{np.mean(drive[len(drive) // 2:]):.4g} N m")


if __name__ == "__main__":
    main()
