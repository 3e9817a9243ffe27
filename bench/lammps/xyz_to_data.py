#!/usr/bin/env python3
"""Writes a LAMMPS data file (atom_style sphere) from an .xyz file of sphere centres.

    xyz_to_data.py IN.xyz OUT.data [ZHI]

Spheres of diameter 2 mm and density 2500 kg/m^3, box 0.1 x 0.1 m (SI units), z from 0 to ZHI
(default: 0.02 m above the highest centre). Used by bench/run_reference.sh (docs/performance.md).
"""
import sys

centres = [tuple(map(float, line.split()[:3])) for line in open(sys.argv[1]) if line.strip()]
zhi = float(sys.argv[3]) if len(sys.argv) > 3 else max(c[2] for c in centres) + 0.02
with open(sys.argv[2], "w") as out:
    out.write(f"veridem reference bed ({len(centres)} spheres), from {sys.argv[1]}\n\n")
    out.write(f"{len(centres)} atoms\n1 atom types\n\n")
    out.write(f"0.0 0.1 xlo xhi\n0.0 0.1 ylo yhi\n0.0 {zhi:.6f} zlo zhi\n\nAtoms # sphere\n\n")
    for n, (x, y, z) in enumerate(centres, start=1):
        out.write(f"{n} 1 0.002 2500 {x:.10f} {y:.10f} {z:.10f}\n")
