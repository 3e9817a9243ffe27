#!/usr/bin/python3
"""Snapshot of a hopper-discharge run (examples/hopper_discharge.toml): the beads seen from the
side (x-z, the slice |y| < 5 mm) at the output nearest a given time, with the hopper's outline,
and the discharged mass from outlets.csv against time, with the least-squares rate over its
middle part (from 20 % to 80 % of the final mass) beside Beverloo's W = C rho_b sqrt(g) (D - k d)^2.5
for C = 0.58, k = 1.5 and a bulk density of 0.6 rho (Beverloo, Leniger & van de Velde 1961; for
comparison only: one orifice size is no fit of C and k).

usage: hopper_snapshot.py OUT_DIR PNG [--time T]   (T [s], default 0.7)
Hopper and beads as in the example: orifice D = 12 mm, cone to R = 30 mm at z = 30 mm, wall to
90 mm; beads d = 2 mm, rho = 2500 kg/m^3.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ORIFICE, RADIUS, CONE, HEIGHT = 0.006, 0.03, 0.03, 0.09  # m
DIAMETER, DENSITY, G = 0.002, 2500.0, 9.81


def main():
    out, png = sys.argv[1], sys.argv[2]
    when = float(sys.argv[sys.argv.index("--time") + 1]) if "--time" in sys.argv else 0.7
    rows = list(csv.DictReader(open(f"{out}/particles.csv")))
    times = sorted({float(r["t"]) for r in rows})
    t_shot = min(times, key=lambda t: abs(t - when))
    shot = [r for r in rows if float(r["t"]) == t_shot and abs(float(r["y"])) < 0.005]
    x = np.array([float(r["x"]) for r in shot])
    z = np.array([float(r["z"]) for r in shot])
    flow = list(csv.DictReader(open(f"{out}/outlets.csv")))
    t = np.array([float(r["t"]) for r in flow])
    mass = np.array([float(r["mass"]) for r in flow])
    middle = (mass > 0.2 * mass[-1]) & (mass < 0.8 * mass[-1])
    rate, offset = np.polyfit(t[middle], mass[middle], 1)
    beverloo = 0.58 * 0.6 * DENSITY * math.sqrt(G) * (2 * ORIFICE - 1.5 * DIAMETER) ** 2.5

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.8))
    for side in (-1, 1):
        left.plot([side * ORIFICE, side * RADIUS, side * RADIUS], [0, CONE, HEIGHT], "k-")
    left.scatter(x, z, s=6, c=z, cmap="viridis")
    left.set_aspect("equal")
    left.set_xlim(-1.3 * RADIUS, 1.3 * RADIUS)
    left.set_ylim(-0.035, HEIGHT)
    left.set_xlabel("x [m]")
    left.set_ylabel("z [m]")
    left.set_title(f"beads with |y| < 5 mm at t = {t_shot:.2f} s")
    right.plot(t, mass * 1e3, label="outlets.csv")
    right.plot(t[middle], (rate * t[middle] + offset) * 1e3, "r--", label=f"fit: {rate * 1e3:.1f} g/s")
    right.set_xlabel("t [s]")
    right.set_ylabel("discharged mass [g]")
    right.set_title(f"discharge (Beverloo, C = 0.58, k = 1.5: {beverloo * 1e3:.1f} g/s)")
    right.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    print(f"discharge rate {rate:.4g} kg/s over the middle of the discharge; Beverloo (C 0.58, k 1.5) {beverloo:.4g} kg/s")


if __name__ == "__main__":
    main()
