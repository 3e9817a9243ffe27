"""The DEM8 benchmark scenes (bench/dem8/) load and run, shortened, through the real program.

For each case a short copy of the scene is written to WORK_DIR (the shared data's path made
absolute, the duration cut, the energy ledger on where the scene allows it) and run on one thread:

- impact_25k: the ball starts 0.1 mm above the highest bead under it instead of at z = 0.06 m (from
  there it falls 21 ms before it touches; the deepest penetration comes ~4 ms after the touch,
  see bench/dem8/README.md), IMPACT_STEPS steps at dt = 5e-7 s: it strikes the bed;
- drum: DRUM_STEPS steps of the turning drum;
- silo_M1_small as written (the inserter and the outlet: no ledger, they change the particle set)
  SILO_STEPS steps, and the same silo with the inserter and outlet replaced by ~100 spheres on a
  lattice 10 um above the closed gate, with the ledger, SILO_STEPS steps.

Checked: exit status 0; the outputs the scene asks for are written with a row per output
(tracked.csv, zones.csv, species.csv, thermo.csv); with the ledger, |energy_residual| below 1e-2
of the energy dissipated (measurements_check.py's bound; the energy_ledger verification case
bounds it tighter), and the dissipation positive; no particle centre beyond a wall's inner face in
the final state (state.csv). Without the shared data (VERIDEM_SHARED_DEM8_DIR, default
../shared/dem8 beside the repository) the test is skipped (exit status 77) with a message.

usage: /usr/bin/python3 dem8_smoke.py VERIDEM REPOSITORY WORK_DIR
"""
import csv
import math
import os
import pathlib
import re
import subprocess
import sys
import time

veridem, root, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
shared = pathlib.Path(os.environ.get("VERIDEM_SHARED_DEM8_DIR", root.parent / "shared" / "dem8")).resolve()
if not (shared / "README.md").is_file():
    print(f"dem8 smoke: SKIPPED: the DEM8 data is not at {shared} (set VERIDEM_SHARED_DEM8_DIR)")
    sys.exit(77)
IMPACT_STEPS, DRUM_STEPS, SILO_STEPS = 300, 200, 2000
work.mkdir(parents=True, exist_ok=True)
failures = []


def scene_text(name, duration, output_interval, energy):
    text = (root / "bench" / "dem8" / f"{name}.toml").read_text()
    text = text.replace("../../../shared/dem8", shared.as_posix())
    text = re.sub(r"(?m)^duration = .*$", f"duration = {duration!r}", text)
    text = re.sub(r"(?m)^output_interval = .*$", f"output_interval = {output_interval!r}", text)
    if energy:
        text = text.replace("[output]\n", "[output]\nenergy = true\n", 1)
    return text


def run(label, text):
    scene = work / f"{label}.toml"
    scene.write_text(text)
    out = work / label
    start = time.monotonic()
    result = subprocess.run([veridem, "run", str(scene), "--out", str(out), "--quiet", "--threads", "1"],
                            capture_output=True, text=True)
    seconds = time.monotonic() - start
    if result.returncode != 0:
        failures.append(f"{label}: exit status {result.returncode}: {result.stderr.strip()[-400:]}")
        return None
    return out, seconds


def rows(path):
    return list(csv.DictReader(open(path)))


def check_ledger(label, out):
    last = rows(out / "thermo.csv")[-1]
    dissipated = sum(float(last[k]) for k in ("dissipated_normal_damping", "dissipated_tangential_damping",
                                               "dissipated_friction", "dissipated_rolling",
                                               "dissipated_adhesion"))
    residual = float(last["energy_residual"])
    if not dissipated > 0 or abs(residual) > 1e-2 * dissipated:
        failures.append(f"{label}: ledger residual {residual:.3g} J, dissipated {dissipated:.3g} J")
    return residual, dissipated


def final_state(out):
    lines = (out / "state.csv").read_text().splitlines()
    return list(csv.DictReader(lines[1:]))


def check_inside(label, out, inside):
    outside = [p for p in final_state(out)
               if not inside(float(p["x"]), float(p["y"]), float(p["z"]), float(p["radius"]))]
    if outside:
        p = outside[0]
        failures.append(f"{label}: {len(outside)} particle(s) beyond a wall, e.g. id {p['id']} at "
                        f"({p['x']}, {p['y']}, {p['z']})")


def check_rows(label, out, name, per_output, outputs):
    have = len(rows(out / name))
    if have != per_output * outputs:
        failures.append(f"{label}: {name} has {have} rows, expected {per_output} x {outputs} outputs")


report = []

# Impact: the ball placed just above the bed, so that the short run strikes it.
bed = [list(map(float, line.split())) for line in
       (shared / "impact" / "particles_25k.txt").read_text().splitlines()[1:25001]]
# The ball's height at first touch: centre distance 0.01 m + r to the bead it meets first.
touch = max(z + math.sqrt((0.01 + r) ** 2 - x * x - y * y) for r, x, y, z in bed if math.hypot(x, y) < 0.01 + r)
dt = 5e-7
text = scene_text("impact_25k", IMPACT_STEPS * dt, 50 * dt, True)
text = text.replace("position = [0, 0, 0.06]", f"position = [0, 0, {touch + 1e-4!r}]")
done = run("impact_25k", text)
if done:
    out, seconds = done
    check_rows("impact_25k", out, "tracked.csv", 1, IMPACT_STEPS // 50 + 1)
    ball = rows(out / "tracked.csv")
    if not float(ball[-1]["vz"]) > -5:
        failures.append(f"impact_25k: the ball was not slowed by the bed (vz = {ball[-1]['vz']} m/s)")
    residual, dissipated = check_ledger("impact_25k", out)
    check_inside("impact_25k", out, lambda x, y, z, r: abs(x) < 0.049 and abs(y) < 0.03 and z > -0.0902431)
    report.append(f"impact_25k {IMPACT_STEPS} steps {seconds:.1f} s (ball vz {float(ball[-1]['vz']):.3g} m/s, "
                  f"residual {residual:.2g} J of {dissipated:.2g} J)")

# Drum.
dt = 8e-7
done = run("drum", scene_text("drum", DRUM_STEPS * dt, 100 * dt, True))
if done:
    out, seconds = done
    outputs = DRUM_STEPS // 100 + 1
    check_rows("drum", out, "zones.csv", 4, outputs)
    check_rows("drum", out, "species.csv", 3, outputs)
    species = rows(out / "species.csv")[:3]
    if [int(s["count"]) for s in species] != [30000, 8000, 0]:
        failures.append(f"drum: species counts {[s['count'] for s in species]}, expected 30000, 8000, 0")
    residual, dissipated = check_ledger("drum", out)
    check_inside("drum", out, lambda x, y, z, r: math.hypot(x, z) < 0.1 and abs(y) < 0.03)
    report.append(f"drum {DRUM_STEPS} steps {seconds:.1f} s (residual {residual:.2g} J of {dissipated:.2g} J)")

# Silo: as written (filling), then a lattice on the closed gate with the ledger.
dt = 1.5e-6
z_orifice = -0.0593008
done = run("silo_fill", scene_text("silo_M1_small", SILO_STEPS * dt, 500 * dt, False))
if done:
    out, seconds = done
    outputs = SILO_STEPS // 500 + 1
    check_rows("silo_fill", out, "zones.csv", 1, outputs)
    retained = int(rows(out / "zones.csv")[-1]["count"])
    if not retained > 0:
        failures.append("silo_fill: no particle inserted")
    check_inside("silo_fill", out, lambda x, y, z, r: math.hypot(x, y) < 0.1 and z > z_orifice)
    report.append(f"silo fill {SILO_STEPS} steps {seconds:.1f} s ({retained} particles inserted)")
text = scene_text("silo_M1_small", SILO_STEPS * dt, 500 * dt, True)
text = text[:text.index("[[insert]]")] + f"""[[lattice]]
material = "M1"
radius = 0.002
min = [-0.01, -0.01, {z_orifice + 1e-5!r}]
max = [0.01, 0.01, {z_orifice + 0.018!r}]
spacing = 0.0044
""" + text[text.index("[[zone]]"):]
done = run("silo_rest", text)
if done:
    out, seconds = done
    residual, dissipated = check_ledger("silo_rest", out)
    check_inside("silo_rest", out, lambda x, y, z, r: math.hypot(x, y) < 0.1 and z > z_orifice)
    report.append(f"silo on the gate {SILO_STEPS} steps {seconds:.1f} s (residual {residual:.2g} J of "
                  f"{dissipated:.2g} J)")

for line in report:
    print(line)
if failures:
    print("\n".join("FAIL: " + f for f in failures))
    sys.exit(1)
print("dem8 smoke: OK")
