#!/usr/bin/env python3
"""Writes a LAMMPS data file (atom_style sphere) from an .xyz file of sphere centres.

    xyz_to_data.py IN.xyz OUT.data [ZHI]
    xyz_to_data.py IN.xyz OUT.data --box XLO XHI YLO YHI ZLO ZHI
    xyz_to_data.py IN.xyz OUT.data [ZHI] --tile N

--tile N repeats the centres N x N times side by side in x and y (box N * 0.1 m wide), as
veridem_bench --tile N does (bed.in: -var side N*0.1).

Spheres of diameter 2 mm and density 2500 kg/m^3 (SI units). The box: 0.1 x 0.1 m, z from 0 to
ZHI (default: 0.02 m above the highest centre), or the one given by --box [m] (the drum of
drum_liggghts.in). Used by bench/run_reference.sh (docs/performance.md).
"""
import sys

args = sys.argv[1:]
box = None
if "--box" in args:
    at = args.index("--box")
    box = [float(v) for v in args[at + 1:at + 7]]
    if len(box) != 6:
        sys.exit("xyz_to_data.py: --box expects six numbers XLO XHI YLO YHI ZLO ZHI [m]")
    del args[at:at + 7]
tile = 1
if "--tile" in args:
    at = args.index("--tile")
    tile = int(args[at + 1])
    if tile < 1:
        sys.exit("xyz_to_data.py: --tile expects a whole number >= 1")
    del args[at:at + 2]
base = [tuple(map(float, line.split()[:3])) for line in open(args[0]) if line.strip()]
centres = [(x + 0.1 * tx, y + 0.1 * ty, z) for ty in range(tile) for tx in range(tile) for (x, y, z) in base]
if box is None:
    zhi = float(args[2]) if len(args) > 2 else max(c[2] for c in centres) + 0.02
    box = [0.0, 0.1 * tile, 0.0, 0.1 * tile, 0.0, zhi]
with open(args[1], "w") as out:
    out.write(f"veridem reference bed ({len(centres)} spheres), from {args[0]}\n\n")
    out.write(f"{len(centres)} atoms\n1 atom types\n\n")
    out.write(f"{box[0]:.6f} {box[1]:.6f} xlo xhi\n{box[2]:.6f} {box[3]:.6f} ylo yhi\n"
              f"{box[4]:.6f} {box[5]:.6f} zlo zhi\n\nAtoms # sphere\n\n")
    for n, (x, y, z) in enumerate(centres, start=1):
        out.write(f"{n} 1 0.002 2500 {x:.10f} {y:.10f} {z:.10f}\n")
