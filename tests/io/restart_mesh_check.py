"""Checkpoint and restart with a moving mesh wall (restart_mesh.toml: beads falling into a rocking
trough of irregular triangles, with friction and EPSD rolling springs): runs stopped at step 3337
(between outputs) and at step 6000 (an output and checkpoint step) and restarted on 2 threads,
where the straight run had 1, must end in the same state as the straight run (the final
checkpoints compared record by record: particles, the mesh's frame and turned angle, the wall
contacts with their springs and their slots' contact normals) and write the same particles.csv,
thermo.csv and walls.csv, byte for byte. The run is checked to carry mesh contact history.

usage: /usr/bin/python3 restart_mesh_check.py VERIDEM SCENE OUT_DIR
"""
import os
import shutil
import struct
import subprocess
import sys

veridem, scene, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(directory, *extra):
    command = [veridem, "run", scene, "--quiet", "--out", f"{out}/{directory}", *extra]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    check(result.returncode == 0, f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip()}")


def records(path):
    """The checkpoint's records, {tag: bytes} (container framing as in restart_check.py)."""
    data = open(path, "rb").read()
    result, k = {}, 32
    while k < len(data) - 24:
        tag = data[k:k + 4].decode()
        size, count = struct.unpack_from("<IQ", data, k + 4)
        result[tag] = data[k + 16:k + 16 + size * count]
        k += 16 + size * count
    return result


def nonzero_doubles(blob):
    return sum(1 for (v,) in struct.iter_unpack("<d", blob) if v != 0)


run("straight", "--threads", "1")
final = records(f"{out}/straight/checkpoint.bin")
springs, normals, turned = nonzero_doubles(final["wcTS"]), nonzero_doubles(final["wcMN"]), final["wTrn"]
print(f"mesh final state: non-zero wall springs {springs}, slot normals {normals}, "
      f"turned {struct.unpack('<d', turned)[0]:.6g} rad")
check(springs > 20 and normals > 20, "too little mesh contact history to test")
for stop in (3337, 6000):
    run(f"split{stop}", "--threads", "1", "--stop-at-step", str(stop))
    run(f"split{stop}", "--threads", "2", "--restart", f"{out}/split{stop}/checkpoint.bin")
    other = records(f"{out}/split{stop}/checkpoint.bin")
    differ = [t for t in final if t != "csvB" and final[t] != other.get(t)]
    check(not differ, f"stopped at {stop}: final checkpoint records differ: {differ}")
    for name in ("particles.csv", "thermo.csv", "walls.csv"):
        a = open(f"{out}/straight/{name}", "rb").read()
        b = open(f"{out}/split{stop}/{name}", "rb").read()
        check(a == b, f"stopped at {stop}: {name} differs from the straight run's")

print("restart with a mesh wall: " + ("OK" if not failures else f"{len(failures)} failure(s)"))
sys.exit(1 if failures else 0)
