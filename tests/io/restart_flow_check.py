"""Checkpoint and restart with particles inserted and removed (restart_pour.toml: inserted at a
rate from a radius table and two materials, removed by an outlet, on a floor of frozen beads):
a run stopped at step 1337 (between outputs, between insertion steps) and at step 1500 (an
insertion step) and restarted into the same directory, on 2 threads where the straight run had
1, must write the same particles.csv, thermo.csv and outlets.csv, byte for byte, as the straight
run (the inserter's generator, counts and ids, the outlet counts and the frozen flags are in the
checkpoint, format version 4). The run is checked to insert and remove particles after each stop,
and its output to hold no retired particle (each frame's rows are thermo.csv's count). The same
scene with outputs twice as often writes the same rows at the straight run's output times: the
outputs skip retired particles and change nothing in the run.

usage: /usr/bin/python3 restart_flow_check.py VERIDEM SCENE OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from restart_support import RestartCheck  # noqa: E402

veridem, scene, out = sys.argv[1:4]
rc = RestartCheck(veridem, out)
check = rc.check


def run(directory, *extra):
    rc.run(scene, directory, *extra)


run("straight", "--threads", "1")
for stop in (1337, 1500):
    run(f"split{stop}", "--threads", "1", "--stop-at-step", str(stop))
    run(f"split{stop}", "--threads", "2", "--restart", f"{out}/split{stop}/checkpoint.bin")
    for name in ("particles.csv", "thermo.csv", "outlets.csv"):
        a = open(f"{out}/straight/{name}", "rb").read()
        b = open(f"{out}/split{stop}/{name}", "rb").read()
        check(a == b, f"stopped at {stop}: {name} differs from the straight run's")

# Outputs twice as often (a copy of the scene with half the output_interval): the same bits.
text = open(scene).read()
check("output_interval = 0.005\n" in text, "the scene's output_interval is not 0.005 s")
denser = os.path.join(out, "denser.toml")
with open(denser, "w") as f:
    f.write(text.replace("output_interval = 0.005\n", "output_interval = 0.0025\n"))
rc.run(denser, "denser", "--threads", "2")


def frames(directory):
    rows = {}
    for line in open(f"{out}/{directory}/particles.csv").read().splitlines()[1:]:
        rows.setdefault(line.split(",")[0], []).append(line)
    return rows


straight_frames, denser_frames = frames("straight"), frames("denser")
check(len(denser_frames) == 2 * len(straight_frames) - 1,
      f"{len(denser_frames)} frames with outputs twice as often, {len(straight_frames)} without")
for t, rows in straight_frames.items():
    check(denser_frames.get(t) == rows, f"t = {t}: outputs twice as often changed the particles")

# Particles came and went after the stops (t = 0.027 s and 0.03 s of 0.08 s).
rows = [line.split(",") for line in open(f"{out}/straight/outlets.csv").read().splitlines()[1:]]
removed = {float(r[0]): int(r[2]) for r in rows}
check(removed[max(removed)] > removed[min(removed, key=lambda t: abs(t - 0.03))] > 0,
      f"the outlet removed nothing after the stops: {removed}")
ids = set()
rows_at = {}
for line in open(f"{out}/straight/particles.csv").read().splitlines()[1:]:
    f = line.split(",")
    ids.add(int(f[1]))
    rows_at[f[0]] = rows_at.get(f[0], 0) + 1
    # An outlet's particles are parked at 1e30 m until they leave the store: never in the output.
    check(all(abs(float(v)) < 1e3 for v in f[2:5]), f"a parked particle in particles.csv: {line}")
check(len(ids) > 600, f"only {len(ids)} ids over the run: too few insertions")
for line in open(f"{out}/straight/thermo.csv").read().splitlines()[1:]:
    t, count = line.split(",")[:2]
    check(rows_at.get(t, 0) == int(count), f"t = {t}: thermo counts {count} particles, particles.csv {rows_at.get(t, 0)}")

sys.exit(rc.finish("restart with insertion"))
