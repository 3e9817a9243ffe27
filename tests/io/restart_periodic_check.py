"""Checkpoint and restart with periodic boundaries (restart_periodic.toml: beads flowing down a
chute periodic in x and y, with friction and EPSD rolling springs): runs stopped at step 3337
(between outputs) and at step 6000 (an output and checkpoint step) and restarted on 2 threads,
where the straight run had 1, must end in the same state as the straight run (the final
checkpoints compared record by record: particles, the pairs through a periodic face with their
shifts and springs) and write the same particles.csv, thermo.csv and walls.csv, byte for byte.
The run is checked to carry history on pairs through a periodic face.

usage: /usr/bin/python3 restart_periodic_check.py VERIDEM SCENE OUT_DIR
"""
import os
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
springs, rolling = nonzero_doubles(final["pbSp"]), nonzero_doubles(final["pbRo"])
print(f"periodic final state: non-zero springs of pairs through a face {springs}, rolling {rolling}")
check(springs > 20 and rolling > 20, "too little history through the periodic faces to test")
rc.stop_and_restart(scene, (3337, 6000), ("particles.csv", "thermo.csv", "walls.csv"))

sys.exit(rc.finish("restart with periodic boundaries"))
