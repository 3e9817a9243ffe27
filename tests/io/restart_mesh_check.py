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
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from restart_support import RestartCheck, nonzero_doubles, records  # noqa: E402

veridem, scene, out = sys.argv[1:4]
rc = RestartCheck(veridem, out)
check = rc.check


def run(directory, *extra):
    rc.run(scene, directory, *extra)


run("straight", "--threads", "1")
final = records(f"{out}/straight/checkpoint.bin")
springs, normals, turned = nonzero_doubles(final["wcTS"]), nonzero_doubles(final["wcMN"]), final["wTrn"]
print(f"mesh final state: non-zero wall springs {springs}, slot normals {normals}, "
      f"turned {struct.unpack('<d', turned)[0]:.6g} rad")
check(springs > 20 and normals > 20, "too little mesh contact history to test")
rc.stop_and_restart(scene, (3337, 6000), ("particles.csv", "thermo.csv", "walls.csv"))

sys.exit(rc.finish("restart with a mesh wall"))
