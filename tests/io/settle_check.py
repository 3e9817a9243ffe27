"""Settle, then experiment: a polydisperse bed settled by one scene (settle_bed.toml) is reloaded
by a second scene from the state file the first wrote (`[[particles]] file = ".../state.csv"`),
with other walls (frictionless steel side walls and floor, a lid), another friction and other
outputs. Checked:
- state.csv holds the 200 beads with their different radii, ids and materials;
- the second scene's first frame is the saved state, bit for bit (ids, positions, radii,
  velocities written in shortest round-trip form, so equal text is equal bits);
- the force column is the contact force: its sum over the particles is minus the sum of the wall
  loads in walls.csv (pair forces cancel, Newton's third law), to round-off (1e-9 relative);
- the bed comes to rest in the second scene (released from the side walls' friction it slumps and
  rings for ~0.15 s; kinetic energy below 1e-9 J at t = 0.3 s, checked), and then, the side walls
  being frictionless, the floor carries the bed's weight: |F_floor,z - g sum m| < 0.1 % (the rest
  is sum m a_z of the remaining vibration, tiny at that energy); the mean coordination (particle
  contacts) is at least 3 (a stable frictional packing has about 4 or more; rattlers lower it);
- the times read exactly: t == 0.1 selects the frame at 10000 steps of 1e-5 s;
- a restart of the second scene from a checkpoint writes the same state.csv, byte for byte.

usage: /usr/bin/python3 settle_check.py VERIDEM SETTLE_SCENE OUT_DIR
"""
import csv
import os
import shutil
import subprocess
import sys

veridem, settle_scene, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(scene, directory, *extra):
    command = [veridem, "run", scene, "--quiet", "--out", os.path.join(out, directory), *extra]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    check(result.returncode == 0, f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip()}")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


run(settle_scene, "settle")
state = rows(os.path.join(out, "settle", "state.csv"))
check(len(state) == 200, f"state.csv has {len(state)} rows, expected 200")
radii = {r["radius"] for r in state}
check(len(radii) > 100, f"state.csv has {len(radii)} distinct radii: not polydisperse")
check({r["material"] for r in state} == {"glass"}, "state.csv: materials are not 'glass'")

experiment = """[simulation]
dt = 1e-5
duration = 0.3
output_interval = 0.1
checkpoint_interval = 0.1
[output]
particle_fields = ["velocity", "radius", "mass", "material", "force", "coordination"]
[[material]]
name = "glass"
density = 2500
kn = 2000
friction = 0.5
[[material]]
name = "steel"
density = 7800
kn = 2000
[[pair]]
first = "glass"
second = "steel"
friction = 0
""" + "".join(f"""[[wall]]
name = "{name}"
material = "steel"
point = {point}
normal = {normal}
""" for name, point, normal in [("floor", "[0, 0, 0]", "[0, 0, 1]"), ("left", "[0, 0, 0]", "[1, 0, 0]"),
                                ("right", "[0.02, 0, 0]", "[-1, 0, 0]"), ("front", "[0, 0, 0]", "[0, 1, 0]"),
                                ("back", "[0, 0.02, 0]", "[0, -1, 0]"), ("lid", "[0, 0, 0.05]", "[0, 0, -1]")]) + """
[[particles]]
file = "settle/state.csv"
"""
scene = os.path.join(out, "experiment.toml")
with open(scene, "w") as f:
    f.write(experiment)
run(scene, "experiment")
frames = rows(os.path.join(out, "experiment", "particles.csv"))
first = {r["id"]: r for r in frames if r["t"] == "0"}
check(len(first) == 200, f"the experiment's first frame has {len(first)} particles")
for r in state:
    f = first.get(r["id"], {})
    same = all(f.get(k) == r[k] for k in ("x", "y", "z", "vx", "vy", "vz", "radius", "material"))
    check(same, f"particle {r['id']}: the first frame differs from state.csv")
    if not same:
        break

g = 9.81  # [m/s^2], the default gravity
at = [r for r in frames if float(r["t"]) == 0.1]
check(len(at) == 200, f"t == 0.1 selects {len(at)} rows, expected 200 (times not exact?)")
last = [r for r in frames if r["t"] == "0.3"]
weight = g * sum(float(r["mass"]) for r in last)
walls = [w for w in rows(os.path.join(out, "experiment", "walls.csv")) if w["t"] == "0.3"]
for axis in "xyz":
    on_particles = sum(float(r["f" + axis]) for r in last)
    on_walls = sum(float(w["f" + axis]) for w in walls)
    check(abs(on_particles + on_walls) <= 1e-9 * weight,
          f"sum of f{axis} over the particles {on_particles} is not minus the walls' {on_walls}")
thermo = [r for r in rows(os.path.join(out, "experiment", "thermo.csv")) if r["t"] == "0.3"]
kinetic = float(thermo[0]["kinetic_translational"]) + float(thermo[0]["kinetic_rotational"]) if thermo else 1
check(kinetic < 1e-9, f"the bed is not at rest at t = 0.3 s: kinetic energy {kinetic:.3g} J")
floor = [w for w in walls if w["wall"] == "floor"]
check(len(floor) == 1, "walls.csv has no floor row at t = 0.3")
if floor:
    load = -float(floor[0]["fz"])  # (walls.csv: the force ON the wall; the floor is pushed down)
    check(abs(load - weight) < 1e-3 * weight, f"floor load {load:.6g} N vs the bed's weight {weight:.6g} N")
    print(f"floor load {load:.7g} N, weight {weight:.7g} N, ratio {load / weight:.7f}")
coordination = sum(int(r["coordination"]) for r in last) / max(1, len(last))
check(coordination >= 3, f"mean coordination {coordination:.3g} < 3: the bed is not a settled packing")
print(f"mean coordination {coordination:.3g}")

# Restart from a checkpoint at step 13000 (t = 0.13 s, between outputs): the same final state, byte for byte.
run(scene, "split", "--stop-at-step", "13000")
run(scene, "split", "--restart", os.path.join(out, "split", "checkpoint.bin"))
for name in ("state.csv", "particles.csv", "walls.csv", "thermo.csv"):
    a = open(os.path.join(out, "experiment", name), "rb").read()
    b = open(os.path.join(out, "split", name), "rb").read()
    check(a == b, f"restarted at step 13000: {name} differs from the straight run's")

print("settle then experiment: " + ("OK" if not failures else f"{len(failures)} FAILED"))
sys.exit(1 if failures else 0)
