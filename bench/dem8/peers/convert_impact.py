#!/usr/bin/python3
"""Converts the DEM8 impact case's shared input (../shared/dem8/impact/) for LIGGGHTS and Yade.

    convert_impact.py PARTICLES WALLS OUTDIR

PARTICLES: the organisers' bed file, a header line then `radius x y z` [m] per line; its last
           non-blank line is the organisers' projectile row (six columns), which is dropped.
WALLS:     the box, a header line then one triangle a line, nine columns [m] (x y z of three
           vertices).

The ball is added after the bed, as the last particle: steel, radius 0.01 m, centre (0, 0, 0.06) m
(its velocity, (0, 0, -5) m/s, is set by each deck). Materials: type 1 = M1 (bed, 2500 kg/m^3),
type 2 = steel (ball and walls, 7200 kg/m^3).

Writes into OUTDIR:
  impact.data     LIGGGHTS read_data file, atom_style granular (id type diameter density x y z);
                  the simulation box encloses the walls with a 5 mm margin (boundary f f f)
  walls.stl       ASCII STL of the triangles (fix mesh/surface), outward normals not needed
  spheres.txt     `x y z radius type` per line for the Yade deck (ball last)
  triangles.txt   nine columns per line, no header, for the Yade deck
  bed.txt         key = value: particle count, bed top (max z + r) [m], ball start [m]

A malformed line stops the converter with the file, the line number and what was expected.
"""
import math
import os
import sys

BALL_RADIUS = 0.01  # m
BALL_CENTRE = (0.0, 0.0, 0.06)  # m
DENSITY = {1: 2500.0, 2: 7200.0}  # kg/m^3: M1, steel
BOX_MARGIN = 0.005  # m, simulation box beyond the walls


def fail(path, line_no, what):
    sys.exit(f"convert_impact.py: {path}:{line_no}: {what}")


def numbers(path, line_no, text, count):
    fields = text.split()
    if len(fields) != count:
        fail(path, line_no, f"expected {count} numbers, found {len(fields)} fields")
    try:
        values = [float(f) for f in fields]
    except ValueError:
        fail(path, line_no, f"expected {count} numbers, found '{text.strip()}'")
    if not all(math.isfinite(v) for v in values):
        fail(path, line_no, "expected finite numbers, found NaN or infinity")
    return values


def read_bed(path):
    rows = []
    with open(path) as stream:
        lines = [(no, text) for no, text in enumerate(stream, start=1) if text.strip()]
    body = lines[1:]  # header
    if not body:
        fail(path, 1, "expected a header then `radius x y z` lines")
    last_no, last = body[-1]
    if len(last.split()) == 4:
        fail(path, last_no, "expected the organisers' projectile row (six columns) as the last line")
    for no, text in body[:-1]:
        radius, x, y, z = numbers(path, no, text, 4)
        if radius <= 0.0:
            fail(path, no, f"expected a positive radius [m], found {radius}")
        rows.append((x, y, z, radius, 1))
    return rows


def read_triangles(path):
    triangles = []
    with open(path) as stream:
        for no, text in enumerate(stream, start=1):
            if no == 1 or not text.strip():
                continue  # header
            v = numbers(path, no, text, 9)
            a, b, c = v[0:3], v[3:6], v[6:9]
            ab = [b[i] - a[i] for i in range(3)]
            ac = [c[i] - a[i] for i in range(3)]
            n = [ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]]
            if math.sqrt(sum(x * x for x in n)) == 0.0:
                fail(path, no, "expected a triangle with three distinct, non-collinear vertices")
            triangles.append((a, b, c, n))
    return triangles


def write_data(path, title, spheres, types, density, triangles):
    """LIGGGHTS read_data file, atom_style granular (id type diameter density x y z) of spheres
    (x, y, z, r, type) [m], density[type] [kg/m^3]; the box encloses the triangles with BOX_MARGIN."""
    lo = [min(min(t[k][i] for k in range(3)) for t in triangles) - BOX_MARGIN for i in range(3)]
    hi = [max(max(t[k][i] for k in range(3)) for t in triangles) + BOX_MARGIN for i in range(3)]
    with open(path, "w") as data:
        data.write(f"{title}\n\n{len(spheres)} atoms\n{types} atom types\n\n")
        for i, name in enumerate("xyz"):
            data.write(f"{lo[i]:.9g} {hi[i]:.9g} {name}lo {name}hi\n")
        data.write("\nAtoms\n\n")
        for atom_id, (x, y, z, r, kind) in enumerate(spheres, start=1):
            data.write(f"{atom_id} {kind} {2 * r:.9g} {density[kind]:.9g} {x:.12g} {y:.12g} {z:.12g}\n")


def write_stl(path, name, triangles):
    """ASCII STL of read_triangles()' triangles (unit normals from the vertex order)."""
    with open(path, "w") as stl:
        stl.write(f"solid {name}\n")
        for a, b, c, n in triangles:
            length = math.sqrt(sum(x * x for x in n))
            stl.write(f"facet normal {n[0] / length:.9g} {n[1] / length:.9g} {n[2] / length:.9g}\n outer loop\n")
            for v in (a, b, c):
                stl.write(f"  vertex {v[0]:.12g} {v[1]:.12g} {v[2]:.12g}\n")
            stl.write(" endloop\nendfacet\n")
        stl.write(f"endsolid {name}\n")


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: convert_impact.py PARTICLES WALLS OUTDIR")
    bed_path, walls_path, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    spheres = read_bed(bed_path)
    bed_top = max(z + r for (_, _, z, r, _) in spheres)
    spheres.append((*BALL_CENTRE, BALL_RADIUS, 2))
    triangles = read_triangles(walls_path)

    title = f"DEM8 impact: {len(spheres) - 1} M1 spheres from {bed_path} and the steel ball"
    write_data(os.path.join(out, "impact.data"), title, spheres, 2, DENSITY, triangles)
    write_stl(os.path.join(out, "walls.stl"), "dem8_impact_box", triangles)
    with open(os.path.join(out, "spheres.txt"), "w") as text:
        for x, y, z, r, kind in spheres:
            text.write(f"{x:.12g} {y:.12g} {z:.12g} {r:.9g} {kind}\n")
    with open(os.path.join(out, "triangles.txt"), "w") as text:
        for a, b, c, _ in triangles:
            text.write(" ".join(f"{v:.12g}" for v in (*a, *b, *c)) + "\n")
    with open(os.path.join(out, "bed.txt"), "w") as info:
        info.write(f"particles = {len(spheres)}\nbed_particles = {len(spheres) - 1}\n")
        info.write(f"bed_top = {bed_top:.9g}\nball_z0 = {BALL_CENTRE[2]}\nball_radius = {BALL_RADIUS}\n")
        info.write(f"triangles = {len(triangles)}\n")


if __name__ == "__main__":
    main()
