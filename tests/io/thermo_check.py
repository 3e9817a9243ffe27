"""thermo.csv of two runs checked against formulas.

Falling sphere (thermo_fall.toml): from rest under gravity g, velocity Verlet gives v = g t after
any number of steps (constant force: the scheme is exact up to rounding), so the translational
kinetic energy is m (g t)^2 / 2 with m = rho 4/3 pi r^3, to 1e-12 relative (1000 steps of ~1e-16
rounding each); no contacts, no rotation.
Resting sphere (thermo_rest.toml, on_wall): one wall contact at every output, no pair contact, and
a kinetic energy far below m g delta (delta = m g / kn, the elastic energy scale of its resting
overlap): it stays at rest, with the elastic energy kn delta^2 / 2 in its spring, delta = r - z.

usage: /usr/bin/python3 thermo_check.py VERIDEM FALL_SCENE REST_SCENE OUT_DIR
"""
import csv
import math
import subprocess
import sys

veridem, fall, rest, out = sys.argv[1:5]
g, rho, r, kn = 9.81, 1000.0, 0.01, 1e4
m = rho * 4.0 / 3.0 * math.pi * r**3
columns = ["t", "particles", "pair_contacts", "wall_contacts", "kinetic_translational", "kinetic_rotational",
           "elastic"]


def rows(scene, name):
    subprocess.run([veridem, "run", scene, "--quiet", "--out", f"{out}/{name}"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    table = list(csv.DictReader(open(f"{out}/{name}/thermo.csv")))
    if list(table[0].keys()) != columns:
        raise SystemExit(f"FAIL: columns {list(table[0].keys())}")
    if len(table) != 11:
        raise SystemExit(f"FAIL: {len(table)} rows, expected 11 (t = 0, 0.01, ..., 0.1)")
    return table


for row in rows(fall, "fall"):
    t = float(row["t"])
    expected = 0.5 * m * (g * t) ** 2
    measured = float(row["kinetic_translational"])
    if abs(measured - expected) > 1e-12 * expected:
        raise SystemExit(f"FAIL: falling, t = {t}: kinetic energy {measured} J, expected {expected} J")
    if (row["particles"], row["pair_contacts"], row["wall_contacts"], float(row["kinetic_rotational"]),
            float(row["elastic"])) != ("1", "0", "0", 0.0, 0.0):
        raise SystemExit(f"FAIL: falling, t = {t}: {row}")
scale = m * g * (m * g / kn)
rest_rows = rows(rest, "rest")
heights = {p["t"]: float(p["z"]) for p in csv.DictReader(open(f"{out}/rest/particles.csv"))}
for row in rest_rows:
    if (row["particles"], row["pair_contacts"], row["wall_contacts"]) != ("1", "0", "1"):
        raise SystemExit(f"FAIL: resting: {row}")
    if float(row["kinetic_translational"]) + float(row["kinetic_rotational"]) > 1e-3 * scale:
        raise SystemExit(f"FAIL: resting: kinetic energy {row['kinetic_translational']} J, scale {scale} J")
    # The spring holds the overlap delta = r - z (particles.csv at the same t): elastic energy
    # kn delta^2 / 2, to 1e-9 relative (delta ~ 4e-6 m from a difference of ~1e-2 m loses ~1e-13).
    z = heights[row["t"]]
    expected = 0.5 * kn * (r - z) ** 2
    if abs(float(row["elastic"]) - expected) > 1e-9 * expected:
        raise SystemExit(f"FAIL: resting: elastic energy {row['elastic']} J, kn (r - z)^2 / 2 = {expected} J")
print("thermo.csv: OK (free fall m (g t)^2 / 2 within 1e-12; resting sphere: one wall contact)")
