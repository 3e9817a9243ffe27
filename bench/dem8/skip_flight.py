#!/usr/bin/python3
"""Writes a DEM8 impact scene that starts the ball on its free-flight parabola just above the bed,
as the peers' decks start it (bench/dem8/peers/run_impact.sh --skip-flight), and converts the run's
tracked.csv to the benchmark's clock.

    skip_flight.py scene BED END OUT_SCENE     BED: 25k or 50k; END: simulated end time [s]
    skip_flight.py curve T0 TRACKED_CSV OUT_CSV

`scene` reads bench/dem8/impact_BED.toml, finds the bed top (max z + r of the bed file's beads),
and sets the ball's centre and velocity to those of the free-flight parabola z(t) = 0.06 - 5 t -
g t^2 / 2 (g = 9.8 m/s^2, exact for a ball that touches nothing) at the time t0 when its lowest
point is 1 mm above the bed top, rounded down to the 0.5 ms output grid (run_impact.sh's rule, so
both start at the same t0), and the duration to END - t0. The data paths are made absolute
(VERIDEM_SHARED_DEM8_DIR, default ../shared/dem8 beside the repository). It prints t0 [s]. The bed
does not settle under gravity during the skipped flight (~20 ms on the 25k bed, 14 ms on the 50k).

`curve` writes t,z with t0 [s] added to the run's times: the ball's height on the benchmark's clock.
"""
import csv
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
G, Z0, V0, RADIUS, DT, EVERY = 9.8, 0.06, 5.0, 0.01, 5e-7, 1000  # m/s^2, m, m/s, m, s, steps


def bed_top(path, rows):
    """max(z + r) [m] of the first `rows` beads of a packing file (header, then `radius x y z`)."""
    top = -math.inf
    with open(path) as stream:
        next(stream)
        for no, line in enumerate(stream, start=2):
            if no - 1 > rows:
                break
            fields = line.split()
            if len(fields) != 4:
                sys.exit(f"skip_flight.py: {path}:{no}: expected 4 columns (radius x y z), found {len(fields)}")
            top = max(top, float(fields[3]) + float(fields[0]))
    return top


def scene(bed, end, out):
    shared = os.path.abspath(os.environ.get("VERIDEM_SHARED_DEM8_DIR",
                                            os.path.join(HERE, "..", "..", "..", "shared", "dem8")))
    with open(os.path.join(HERE, f"impact_{bed}.toml")) as stream:
        text = stream.read().replace("../../../shared/dem8", shared)
    rows = int(re.search(r"^rows = (\d+)", text, re.M).group(1))
    top = bed_top(os.path.join(shared, "impact", f"particles_{bed}.txt"), rows)
    drop = Z0 - (top + RADIUS + 1e-3)  # m the ball falls freely
    t0 = (-V0 + math.sqrt(V0 * V0 + 2 * G * drop)) / G
    t0 = round(math.floor(t0 / (EVERY * DT)) * EVERY * DT, 9)
    z, vz = Z0 - V0 * t0 - 0.5 * G * t0 * t0, -(V0 + G * t0)
    if end <= t0:
        sys.exit(f"skip_flight.py: END {end} s is not after the start {t0} s")
    for key, value in (("position", f"[0, 0, {z!r}]"), ("velocity", f"[0, 0, {vz!r}]")):
        text, count = re.subn(rf"^{key} = \[0, 0, [-0-9.]+\]", f"{key} = {value}", text, flags=re.M)
        if count != 1:
            sys.exit(f"skip_flight.py: impact_{bed}.toml: expected one ball `{key} = [0, 0, ...]`")
    text = re.sub(r"^duration = [0-9.e-]+", f"duration = {round(end - t0, 9)!r}", text, flags=re.M)
    with open(out, "w") as stream:
        stream.write(f"# impact_{bed}.toml from t0 = {t0} s (skip_flight.py; bed top {top} m)\n" + text)
    print(f"{t0:.6g}")


def curve(t0, tracked, out):
    with open(tracked) as source, open(out, "w") as sink:
        sink.write("t,z\n")
        for row in csv.DictReader(source):
            sink.write(f"{float(row['t']) + t0:.6g},{row['z']}\n")


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "scene":
        scene(sys.argv[2], float(sys.argv[3]), sys.argv[4])
    elif len(sys.argv) == 5 and sys.argv[1] == "curve":
        curve(float(sys.argv[2]), sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)
