#!/usr/bin/env python3
"""Triangle meshes (binary STL, metres) of the walls the examples and benchmarks use.

    python3 scripts/make_meshes.py                 # writes examples/meshes/*.stl
    python3 scripts/make_meshes.py drum OUT.stl [--radius R] [--length L] [--segments N]
    python3 scripts/make_meshes.py hopper OUT.stl [--orifice-radius R0] [--radius R]
                                   [--cone-height HC] [--height H] [--segments N]

drum: a closed circular cylinder (side and both end disks) whose axis runs from the origin along
  +y for L; the side has N segments around and rings about as long as a segment is wide, each end
  disk is a fan of N triangles about its centre. Default R = 0.05 m, L = 0.03 m, N = 96 (a chord
  sags R (1 - cos(pi/N)) = 27 um from the circle).
hopper: an open conical hopper on the +z axis: a cone from the orifice (radius R0 at z = 0) to
  radius R at z = HC, then a vertical cylinder to z = H; open at the orifice and at the top (the
  reader warns of an open boundary: expected). Default R0 = 6 mm, R = 30 mm, HC = 30 mm,
  H = 90 mm, N = 64.

Only the standard library (no numpy), so any python3 runs it. The same arguments always give the
same bytes. The files in examples/meshes are made by this script: change the script, not them.
"""
import argparse
import math
import os
import struct
import sys


def write_stl(path, triangles, name):
    """Binary STL: an 80-byte header, a count, then normal and three corners per triangle."""
    header = ("veridem make_meshes.py: " + name).encode()[:80].ljust(80, b" ")
    with open(path, "wb") as f:
        f.write(header)
        f.write(struct.pack("<I", len(triangles)))
        for a, b, c in triangles:
            u = [b[k] - a[k] for k in range(3)]
            v = [c[k] - a[k] for k in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            s = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write(struct.pack("<12fH", *(x / s for x in n), *a, *b, *c, 0))


def ring(radius, segments, place):
    """Points at `segments` equal angles on a circle; place(x, y) maps the circle's (cos, sin) into 3D."""
    return [place(radius * math.cos(2 * math.pi * q / segments), radius * math.sin(2 * math.pi * q / segments))
            for q in range(segments)]


def band(lower, upper):
    """Triangles between two rings of the same point count (each quad split along one diagonal)."""
    n = len(lower)
    out = []
    for q in range(n):
        q1 = (q + 1) % n
        out.append((lower[q], lower[q1], upper[q1]))
        out.append((lower[q], upper[q1], upper[q]))
    return out


def drum(radius=0.05, length=0.03, segments=96):
    """Closed cylinder about +y from y = 0 to y = length."""
    width = 2 * math.pi * radius / segments
    rings = max(1, round(length / width))
    at = lambda y: ring(radius, segments, lambda c, s: (c, y, s))
    tris = []
    for k in range(rings):
        tris += band(at(length * k / rings), at(length * (k + 1) / rings))
    for y in (0.0, length):
        rim = at(y)
        tris += [((0.0, y, 0.0), rim[q], rim[(q + 1) % segments]) for q in range(segments)]
    return tris


def hopper(orifice_radius=0.006, radius=0.03, cone_height=0.03, height=0.09, segments=64):
    """Open cone from the orifice at z = 0 widening to `radius` at z = cone_height, then a cylinder."""
    width = 2 * math.pi * radius / segments
    at = lambda r, z: ring(r, segments, lambda c, s: (c, s, z))
    slant = math.hypot(radius - orifice_radius, cone_height)
    cone_rings = max(1, round(slant / width))
    tris = []
    for k in range(cone_rings):
        f0, f1 = k / cone_rings, (k + 1) / cone_rings
        tris += band(at(orifice_radius + (radius - orifice_radius) * f0, cone_height * f0),
                     at(orifice_radius + (radius - orifice_radius) * f1, cone_height * f1))
    side_rings = max(1, round((height - cone_height) / width))
    for k in range(side_rings):
        z0 = cone_height + (height - cone_height) * k / side_rings
        z1 = cone_height + (height - cone_height) * (k + 1) / side_rings
        tris += band(at(radius, z0), at(radius, z1))
    return tris


def positive(text):
    value = float(text)
    if not value > 0 or not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a positive number, got '{text}'")
    return value


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="shape")
    d = sub.add_parser("drum", help="closed cylinder about +y")
    d.add_argument("out")
    d.add_argument("--radius", type=positive, default=0.05, help="m")
    d.add_argument("--length", type=positive, default=0.03, help="m")
    d.add_argument("--segments", type=int, default=96)
    h = sub.add_parser("hopper", help="open conical hopper on +z")
    h.add_argument("out")
    h.add_argument("--orifice-radius", type=positive, default=0.006, help="m")
    h.add_argument("--radius", type=positive, default=0.03, help="m")
    h.add_argument("--cone-height", type=positive, default=0.03, help="m")
    h.add_argument("--height", type=positive, default=0.09, help="m")
    h.add_argument("--segments", type=int, default=64)
    args = parser.parse_args()
    if args.shape is None:
        here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "meshes")
        os.makedirs(here, exist_ok=True)
        write_stl(os.path.join(here, "drum.stl"), drum(), "drum R 0.05 L 0.03 N 96")
        write_stl(os.path.join(here, "hopper.stl"), hopper(), "hopper R0 0.006 R 0.03 HC 0.03 H 0.09 N 64")
        return 0
    if args.segments < 3:
        parser.error("--segments: expected at least 3")
    if args.shape == "drum":
        tris = drum(args.radius, args.length, args.segments)
    else:
        if not (args.orifice_radius < args.radius and args.cone_height < args.height):
            parser.error("hopper: expected orifice-radius < radius and cone-height < height")
        tris = hopper(args.orifice_radius, args.radius, args.cone_height, args.height, args.segments)
    write_stl(args.out, tris, args.shape)
    print(f"{args.out}: {len(tris)} triangles")
    return 0


if __name__ == "__main__":
    sys.exit(main())
