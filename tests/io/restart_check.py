"""Checkpoint and restart continue a run with the same bits (docs/scene-format.md, "Checkpoint and
restart").

3D (restart_bed.toml: ~3000 spheres, friction, EPSD rolling springs, an oscillating floor and a
moving wall): the straight run on 1 and on 2 threads; runs stopped at steps k1 = 337 (between
outputs) and k2 = 750 (an output step) and restarted, on 1 and 2 threads alternately, into the
same directory and into a fresh one; a run stopped by SIGINT at an unknown step and restarted
(and one stopped by SIGTERM: status 143). Every one must end in the same state: the final checkpoints are compared record by record (every
particle array, the neighbour list with its contact history, the wall contacts, time and step
count: all but the output counters) and, in the same directory, the output files byte for byte.
The springs are checked to be non-zero, so history is really carried; walls.csv (the wall loads)
must be byte-identical on 1 and 2 threads.
2D (restart_block_2d.toml: a block sliding with friction after a settling): the same with
k1 = 333, k2 = 1000.
Refusals: a checkpoint of another scene, of another format version, of the other engine, a
truncated and a corrupt one: a one-line error and exit status 2.

usage: /usr/bin/python3 restart_check.py VERIDEM SCENE3D SCENE2D OUT_DIR
"""
import os
import shutil
import signal
import struct
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from restart_support import RestartCheck, nonzero_doubles, records  # noqa: E402

veridem, scene3d, scene2d, out = sys.argv[1:5]
rc = RestartCheck(veridem, out)
check, run, same_state, same_files, failures = rc.check, rc.run, rc.same_state, rc.same_files, rc.failures


def signal_when_stepping(process, directory, sig):
    """Sends `sig` once the run is in its step loop (its thermo.csv has a row after t = 0), so the
    handler is installed whatever the machine's load."""
    thermo = f"{out}/{directory}/thermo.csv"
    deadline = time.time() + 120
    while time.time() < deadline and process.poll() is None:
        if os.path.exists(thermo) and len(open(thermo).read().splitlines()) >= 3:
            break
        time.sleep(0.02)
    process.send_signal(sig)


# ---- 3D ----
outputs3d = ["checkpoint.bin", "particles.csv", "thermo.csv", "walls.csv", "particles.pvd", "particles_000006.vtp"]
run(scene3d, "straight1", "--threads", "1")
run(scene3d, "straight2", "--threads", "2")
check(open(f"{out}/straight1/checkpoint.bin", "rb").read() == open(f"{out}/straight2/checkpoint.bin", "rb").read(),
      "3D: the straight runs on 1 and 2 threads differ")
# walls.csv (the loads, summed in slot order) has the same bits on any thread count, and the
# floor carries the bed.
same_files("straight1", "straight2", ["walls.csv"], "3D walls.csv on 1 and 2 threads")
check(any(float(line.split(",")[4]) != 0 for line in open(f"{out}/straight1/walls.csv").read().splitlines()[1:]),
      "3D: walls.csv has no load")
final = records(f"{out}/straight1/checkpoint.bin")
print("3D final state: non-zero pair springs", nonzero_doubles(final["acSp"]), "rolling springs",
      nonzero_doubles(final["acRo"]), "wall springs", nonzero_doubles(final["wcTS"]))
check(nonzero_doubles(final["acSp"]) > 100 and nonzero_doubles(final["acRo"]) > 100
      and nonzero_doubles(final["wcTS"]) > 10, "3D: the scene carries too little contact history")
for first, second in ((1, 2), (2, 1)):
    d = f"split{first}{second}"
    run(scene3d, d, "--threads", str(first), "--stop-at-step", "337")
    shutil.copy(f"{out}/{d}/checkpoint.bin", f"{out}/k337_{d}.bin")
    state = records(f"{out}/k337_{d}.bin")
    check(struct.unpack("<Q", state["step"])[0] == 337, f"3D {d}: checkpoint not at step 337")
    run(scene3d, d, "--threads", str(second), "--restart", f"{out}/{d}/checkpoint.bin", "--stop-at-step", "750")
    run(scene3d, d, "--threads", str(first), "--restart", f"{out}/{d}/checkpoint.bin")
    same_state(f"{out}/straight1/checkpoint.bin", f"{out}/{d}/checkpoint.bin", f"3D {d}")
    same_files("straight1", d, outputs3d, f"3D {d}")
    run(scene3d, f"fresh{first}{second}", "--threads", str(second), "--restart", f"{out}/k337_{d}.bin")
    same_state(f"{out}/straight1/checkpoint.bin", f"{out}/fresh{first}{second}/checkpoint.bin",
               f"3D fresh{first}{second}")

# SIGINT at whatever step a long run (the same scene lasting 1 s) has reached after its second
# output, then a restart to 300 steps later: the state must be that of a straight run stopped there.
long3d = f"{out}/long_scene.toml"
with open(long3d, "w") as f:
    f.write(open(scene3d).read().replace("duration = 0.03 ", "duration = 1.0  "))
command = [veridem, "run", long3d, "--quiet", "--threads", "2", "--out", f"{out}/sigint"]
process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
signal_when_stepping(process, "sigint", signal.SIGINT)
_, stderr = process.communicate()
check(process.returncode == 130, f"SIGINT: exit {process.returncode}, expected 130: {stderr.strip()}")
check("stopped by SIGINT" in stderr, f"SIGINT: message missing: {stderr.strip()}")
if process.returncode == 130:
    stopped = struct.unpack("<Q", records(f"{out}/sigint/checkpoint.bin")["step"])[0]
    print("SIGINT: checkpoint at step", stopped)
    target = str(stopped + 300)
    run(long3d, "sigint", "--threads", "1", "--restart", f"{out}/sigint/checkpoint.bin", "--stop-at-step", target)
    run(long3d, "sigint_straight", "--threads", "1", "--stop-at-step", target)
    same_state(f"{out}/sigint_straight/checkpoint.bin", f"{out}/sigint/checkpoint.bin", "3D after SIGINT")
    same_files("sigint_straight", "sigint", ["particles.csv", "thermo.csv", "walls.csv", "particles.pvd"], "3D after SIGINT")

# SIGTERM: the same stop, status 143.
process = subprocess.Popen([veridem, "run", long3d, "--quiet", "--threads", "1", "--out", f"{out}/sigterm"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
signal_when_stepping(process, "sigterm", signal.SIGTERM)
_, stderr = process.communicate()
check(process.returncode == 143 and "stopped by SIGTERM" in stderr,
      f"SIGTERM: exit {process.returncode}, expected 143: {stderr.strip()}")
check(os.path.exists(f"{out}/sigterm/checkpoint.bin"), "SIGTERM: no checkpoint")

# ---- 2D ----
outputs2d = ["checkpoint.bin", "bodies.csv", "energy.csv", "thermo.csv", "series.pvd", "frame_00004.vtu"]
run(scene2d, "straight2d")
final2d = records(f"{out}/straight2d/checkpoint.bin")
check(any(v != 0 for (v,) in struct.iter_unpack("<d", b"".join(
    final2d["cpls"][k + 8:k + 56] for k in range(0, len(final2d["cpls"]), 104)))), "2D: no friction spring")
# 2D thermo.csv: its columns, and at t = 0 (right after the settling, the block's nodes all set to
# v = 1 m/s) kinetic = rho A v^2 / 2 = 2650 * 0.05 * 0.05 / 2 J/m: the lumped masses sum to rho A
# up to rounding (64 + 16 terms of ~1e-16 relative error each: tolerance 1e-13).
thermo2d = open(f"{out}/straight2d/thermo.csv").read().splitlines()
check(thermo2d[0] == "t,bodies,nodes,triangles,couples,contacts,sliding,kinetic", f"2D thermo header {thermo2d[0]}")
first = thermo2d[1].split(",")
check(first[:4] == ["0", "2", "59", "64"] and abs(float(first[7]) - 2650 * 0.05 * 0.05 / 2) < 1e-13 * 3.3125,
      f"2D thermo first row {thermo2d[1]}")
check(len(thermo2d) == 6 and all(int(r.split(",")[5]) > 0 for r in thermo2d[2:]),
      "2D thermo: expected 5 rows with touching contacts after t = 0")
run(scene2d, "split2d", "--stop-at-step", "333")
shutil.copy(f"{out}/split2d/checkpoint.bin", f"{out}/k333_2d.bin")
run(scene2d, "split2d", "--restart", f"{out}/split2d/checkpoint.bin", "--stop-at-step", "1000")
run(scene2d, "split2d", "--restart", f"{out}/split2d/checkpoint.bin")
same_state(f"{out}/straight2d/checkpoint.bin", f"{out}/split2d/checkpoint.bin", "2D split")
same_files("straight2d", "split2d", outputs2d, "2D split")
run(scene2d, "fresh2d", "--restart", f"{out}/k333_2d.bin")
same_state(f"{out}/straight2d/checkpoint.bin", f"{out}/fresh2d/checkpoint.bin", "2D fresh")

# ---- refusals ----
other = f"{out}/other_scene.toml"
with open(other, "w") as f:  # the same scene with another duration
    f.write(open(scene3d).read().replace("duration = 0.03 ", "duration = 0.04 "))


def refused(scene, checkpoint, message, what):
    result = run(scene, "refused", "--restart", checkpoint, expect=2)
    lines = [l for l in result.stderr.splitlines() if l.startswith("veridem: error")]
    check(len(lines) == 1 and message in lines[0], f"{what}: expected one error line with '{message}': "
          f"{result.stderr.strip()}")


good = open(f"{out}/k337_split12.bin", "rb").read()
refused(other, f"{out}/k337_split12.bin", "belongs to another scene", "other scene")
# Comments and layout are not the scene: a copy with one more comment line restarts.
commented = f"{out}/commented_scene.toml"
with open(commented, "w") as f:
    f.write("# a comment that was not there\n" + open(scene3d).read() + "\n# nor this one\n")
run(commented, "commented", "--restart", f"{out}/k337_split12.bin")
same_state(f"{out}/straight1/checkpoint.bin", f"{out}/commented/checkpoint.bin", "3D commented scene")
refused(scene2d, f"{out}/k337_split12.bin", "is a checkpoint of a 3D DEM scene", "other engine")
with open(f"{out}/version.bin", "wb") as f:
    f.write(good[:12] + struct.pack("<I", 99) + good[16:])
refused(scene3d, f"{out}/version.bin", "has format version 99, this veridem reads version 6", "version")
with open(f"{out}/truncated.bin", "wb") as f:
    f.write(good[:len(good) // 2])
refused(scene3d, f"{out}/truncated.bin", "is truncated", "truncated")
with open(f"{out}/short.bin", "wb") as f:
    f.write(good[:40])
refused(scene3d, f"{out}/short.bin", "is truncated", "truncated to 40 bytes")
corrupt = bytearray(good)
corrupt[len(good) // 2] ^= 0x10
with open(f"{out}/corrupt.bin", "wb") as f:
    f.write(corrupt)
refused(scene3d, f"{out}/corrupt.bin", "is corrupt", "corrupt")
refused(scene3d, f"{out}/no_such.bin", "does not exist", "missing")
refused(scene3d, out, "is not a regular file", "a directory")

if failures:
    raise SystemExit(f"restart: {len(failures)} failure(s)")
print("restart: OK")
