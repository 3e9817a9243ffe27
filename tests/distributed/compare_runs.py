"""Compares the output of runs of one scene on different MPI rank counts (mpi_run_restart.cmake).

    compare_runs.py REFERENCE OTHER...

Each OTHER must have the reference's files with the same rows and columns: thermo.csv and
walls.csv (the same times, walls and particle and contact counts), particles.csv (the same times
and ids), outlets.csv if there is one (the same counts). The kinetic energies and the outlets'
masses must agree within 1e-9 relative, the energy ledger's terms (with `[output] energy`) within
1e-9 of the initial energy, and the positions within 1e-12 m: another
rank count sums each particle's contacts in another order (tests/distributed/mpi_step_check.cpp gives the
bound). Exit 1 on the first difference, naming the file, row and column.
"""
import csv
import os
import sys

KINETIC = 1e-9   # relative
POSITION = 1e-12  # m


def rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def compare(reference, other):
    for name in ("thermo.csv", "walls.csv", "particles.csv", "outlets.csv"):
        if not os.path.exists(f"{reference}/{name}"):
            continue
        a, b = rows(f"{reference}/{name}"), rows(f"{other}/{name}")
        if len(a) != len(b) or a[0] != b[0]:
            fail(f"{other}/{name}: {len(b)} rows with header {b[0]}, expected {len(a)} with {a[0]}")
        header = a[0]
        ledger = "energy_initial" in header
        if name == "particles.csv":  # (rows by time and id: one process keeps its store's order)
            a[1:] = sorted(a[1:], key=lambda r: (float(r[0]), int(r[1])))
            b[1:] = sorted(b[1:], key=lambda r: (float(r[0]), int(r[1])))
        for line, (x, y) in enumerate(zip(a[1:], b[1:]), start=2):
            for column, (u, v) in enumerate(zip(x, y)):
                key = header[column]
                if key in ("t", "id", "particles", "wall", "pair_contacts", "wall_contacts", "outlet", "count",
                           "bonds_intact", "bonds_broken"):
                    if key == "t" and abs(float(u) - float(v)) > 1e-12:
                        fail(f"{other}/{name} line {line}: t = {v}, expected {u}")
                    if key != "t" and u != v:
                        fail(f"{other}/{name} line {line}: {key} = {v}, expected {u}")
                elif ledger and (key == "elastic" or key.split("_")[0] in ("work", "dissipated", "energy")):
                    scale = max(abs(float(u)), abs(float(x[header.index("energy_initial")])))
                    if abs(float(v) - float(u)) > KINETIC * scale:
                        fail(f"{other}/{name} line {line}: {key} = {v}, expected {u} within {KINETIC} of {scale} J")
                elif key.startswith("kinetic") or key == "mass":
                    if abs(float(v) - float(u)) > KINETIC * abs(float(u)):
                        fail(f"{other}/{name} line {line}: {key} = {v}, expected {u} within {KINETIC} relative")
                elif key in ("x", "y", "z"):
                    if abs(float(v) - float(u)) > POSITION:
                        fail(f"{other}/{name} line {line}: {key} = {v} m, expected {u} within {POSITION} m")
    print(f"{other}: the same rows as {reference}; kinetic energies within {KINETIC}, positions within {POSITION} m")


for run in sys.argv[2:]:
    compare(sys.argv[1], run)
