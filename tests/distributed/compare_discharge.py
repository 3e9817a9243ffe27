"""Compares the discharge of the example hopper (examples/hopper_discharge.toml) run on several MPI
rank counts with one process (CTest mpi_hopper_discharge_rate, label slow).

    compare_discharge.py REFERENCE OTHER...

Each run's outlets.csv gives the beads discharged against time. Once the beads pile up, runs on
different rank counts are different realisations of the flow (their round-off differences grow
~20x every 0.01 s: tests/scenes/mpi_hopper.toml), so they are compared as a physical result:
  - every run discharges all 1,500 beads;
  - the mean rate over the steady window 0.5-1.1 s (the gate opens at 0.4 s) agrees with one
    process's within 8.5 %: if the ~1,250 beads of the window left independently, the count would
    fluctuate by 1/sqrt(1250) = 2.8 % (a dense flow is more regular, so this bounds it); the
    tolerance is three such standard deviations.
"""
import csv
import math
import sys

WINDOW = (0.5, 1.1)  # s


def counts(run):
    with open(f"{run}/outlets.csv", newline="") as f:
        return [(float(r["t"]), int(r["count"])) for r in csv.DictReader(f)]


def at(series, t):
    return min(series, key=lambda p: abs(p[0] - t))[1]


def rate(series):
    return (at(series, WINDOW[1]) - at(series, WINDOW[0])) / (WINDOW[1] - WINDOW[0])


reference = counts(sys.argv[1])
w0 = rate(reference)
beads = at(reference, WINDOW[1]) - at(reference, WINDOW[0])
tolerance = 3 / math.sqrt(beads)
failed = False
for run in sys.argv[1:]:
    c = counts(run)
    w = rate(c)
    print(f"{run}: {c[-1][1]} beads discharged, rate {w:.1f} beads/s over {WINDOW[0]}-{WINDOW[1]} s "
          f"({w / w0 - 1:+.2%} against one process; tolerance {tolerance:.1%})")
    if c[-1][1] != 1500 or abs(w / w0 - 1) > tolerance:
        failed = True
print("FAIL" if failed else "PASS")
sys.exit(1 if failed else 0)
