#!/usr/bin/python3
"""Converts the DEM8 drum case's shared input (../shared/dem8/drum/) for LIGGGHTS.

    convert_drum.py PARTICLES WALLS OUTDIR

PARTICLES: the organisers' settled bed, a header line then `radius x y z` [m] per line; a radius
           below 1.5 mm is an M1 bead (type 1, 2500 kg/m^3), above it an M2 bead (type 2,
           2000 kg/m^3), as veridem's scene tells them apart (bench/dem8/drum.toml).
WALLS:     the drum, a header line then one triangle a line, nine columns [m]; type 3 (steel).

Writes into OUTDIR:
  drum.data   LIGGGHTS read_data file, atom_style granular (id type diameter density x y z); the
              simulation box encloses the walls with a 5 mm margin (boundary f f f)
  walls.stl   ASCII STL of the triangles (fix mesh/surface)
  drum.txt    key = value: particle count, M1 and M2 counts, triangles

A malformed line stops the converter with the file, the line number and what was expected
(convert_impact.py's readers).
"""
import os
import sys

from convert_impact import fail, numbers, read_triangles, write_data, write_stl

SPLIT_RADIUS = 0.0015  # m: M1 below, M2 above (r = 1 mm and 2 mm)
DENSITY = {1: 2500.0, 2: 2000.0}  # kg/m^3: M1, M2


def read_beads(path):
    rows = []
    with open(path) as stream:
        for no, text in enumerate(stream, start=1):
            if no == 1 or not text.strip():
                continue  # header
            radius, x, y, z = numbers(path, no, text, 4)
            if radius <= 0.0:
                fail(path, no, f"expected a positive radius [m], found {radius}")
            rows.append((x, y, z, radius, 1 if radius < SPLIT_RADIUS else 2))
    if not rows:
        fail(path, 1, "expected a header then `radius x y z` lines")
    return rows


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: convert_drum.py PARTICLES WALLS OUTDIR")
    beads_path, walls_path, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    beads = read_beads(beads_path)
    triangles = read_triangles(walls_path)
    title = f"DEM8 drum: {len(beads)} M1 and M2 spheres from {beads_path}"
    write_data(os.path.join(out, "drum.data"), title, beads, 3, DENSITY, triangles)
    write_stl(os.path.join(out, "walls.stl"), "dem8_drum", triangles)
    with open(os.path.join(out, "drum.txt"), "w") as info:
        m1 = sum(1 for b in beads if b[4] == 1)
        info.write(f"particles = {len(beads)}\nm1 = {m1}\nm2 = {len(beads) - m1}\ntriangles = {len(triangles)}\n")


if __name__ == "__main__":
    main()
