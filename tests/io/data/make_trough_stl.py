"""Writes trough.stl (ASCII): a V-shaped trough, two faces sloping at 30 degrees down to a ridge
along x at z = 0, 60 mm long and 2 x 30 mm wide across, each face cut into an irregular grid of
triangles (jittered interior vertices from a fixed formula), so that spheres in the trough cross
shared edges and vertices and sit in the concave corner. The mesh of restart_mesh.toml.

usage: python3 make_trough_stl.py [OUT]   (standard library only)
"""
import math
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "trough.stl"
slope = math.tan(math.radians(30))
nx, ny = 5, 3
xs = [-0.03 + 0.06 * i / nx for i in range(nx + 1)]


def point(i, j, side):
    """Vertex i (along x), j (0: ridge .. ny: rim) of a face; side +1 or -1 in y."""
    x, y = xs[i], 0.03 * j / ny
    if 0 < i < nx and 0 < j < ny:  # interior: a fixed jitter, different per vertex
        x += 0.002 * math.sin(7.3 * i + 3.1 * j)
        y += 0.002 * math.cos(5.7 * i + 1.9 * j)
    return (x, side * y, slope * y)


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    s = math.sqrt(sum(t * t for t in n))
    return [t / s for t in n]


triangles = []
for side in (1, -1):
    for i in range(nx):
        for j in range(ny):
            a, b = point(i, j, side), point(i + 1, j, side)
            c, d = point(i + 1, j + 1, side), point(i, j + 1, side)
            quad = [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
            for t in quad:  # upward normals (the particles' side)
                triangles.append(t if normal(*t)[2] > 0 else (t[0], t[2], t[1]))
with open(out, "w") as f:
    f.write("solid trough\n")
    for t in triangles:
        n = normal(*t)
        f.write(f"  facet normal {n[0]:.9g} {n[1]:.9g} {n[2]:.9g}\n    outer loop\n")
        for v in t:
            f.write(f"      vertex {v[0]:.9g} {v[1]:.9g} {v[2]:.9g}\n")
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid trough\n")
