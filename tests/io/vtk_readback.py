"""Reads the VTK XML output of both engines back with VTK's own readers, in ASCII and in binary
(appended, zlib-compressed), and checks it value for value against the round-trip CSV output
(DEM) and across the two formats (FEM/DEM). Equality is exact: both formats carry every double
bit for bit (the ASCII form is the shortest round-trip decimal).

usage: /usr/bin/python3 vtk_readback.py VERIDEM SOURCE_DIR WORK_DIR
"""
import csv
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("vtk read-back: SKIPPED: the Python module vtk is missing (Debian python3-vtk9, scripts/setup)")
    sys.exit(0)

veridem, source, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
work.mkdir(parents=True, exist_ok=True)


def run(scene, fmt, out):
    text = scene.read_text().replace("[simulation]\n", f'[simulation]\nvtk_format = "{fmt}"\n', 1)
    copy = work / f"{scene.stem}_{fmt}.toml"
    copy.write_text(text)
    subprocess.run([veridem, "run", str(copy), "--quiet", "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def series(pvd):
    root = ElementTree.parse(pvd).getroot()
    return [(float(d.get("timestep")), pvd.parent / d.get("file")) for d in root.iter("DataSet")]


def read(path, reader_class):
    reader = reader_class()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        raise SystemExit(f"FAIL: VTK read no points from {path}")
    arrays = {"points": vtk_to_numpy(data.GetPoints().GetData())}
    for attributes in (data.GetPointData(), data.GetCellData()):
        for i in range(attributes.GetNumberOfArrays()):
            arrays[attributes.GetArrayName(i)] = vtk_to_numpy(attributes.GetArray(i))
    if hasattr(data, "GetCells") and isinstance(data, vtk.vtkUnstructuredGrid):
        arrays["connectivity"] = vtk_to_numpy(data.GetCells().GetConnectivityArray())
    return arrays


checked = 0
# DEM: every frame of both formats equals the CSV rows of its time, bit for bit.
dem = source / "tests/io/data/falling_lattice.toml"
for fmt in ("ascii", "binary"):
    out = work / f"dem_{fmt}"
    run(dem, fmt, out)
    header = open(out / "particles_000000.vtp", "rb").read(400)
    if (b'format="appended"' in header) != (fmt == "binary"):
        raise SystemExit(f"FAIL: {fmt} output is not in the {fmt} form")
    rows = {}
    with open(out / "particles.csv") as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["t"], []).append(r)
    frames = series(out / "particles.pvd")
    if len(frames) != len(rows):
        raise SystemExit(f"FAIL: {len(frames)} frames in the .pvd, {len(rows)} times in the CSV")
    for (t, path), (time, table) in zip(frames, rows.items()):
        if t != float(time):
            raise SystemExit(f"FAIL: .pvd time {t!r} != CSV time {time}")
        a = read(path, vtk.vtkXMLPolyDataReader)
        for i, r in enumerate(table):
            expected = {"points": (r["x"], r["y"], r["z"]), "velocity": (r["vx"], r["vy"], r["vz"]),
                        "angular_velocity": (r["wx"], r["wy"], r["wz"])}
            for name, values in expected.items():
                if tuple(a[name][i]) != tuple(float(v) for v in values):
                    raise SystemExit(f"FAIL: {path.name} {name} of sphere {i}: {a[name][i]} != {values}")
            if int(a["id"][i]) != int(r["id"]):
                raise SystemExit(f"FAIL: {path.name} id {a['id'][i]} != {r['id']}")
            checked += 1

# FEM/DEM: the binary frames equal the ASCII ones array for array.
fdem = source / "tests/io/data/fdem_block.toml"
outputs = {}
for fmt in ("ascii", "binary"):
    run(fdem, fmt, work / f"fdem_{fmt}")
    outputs[fmt] = series(work / f"fdem_{fmt}" / "series.pvd")
if len(outputs["ascii"]) < 2 or len(outputs["ascii"]) != len(outputs["binary"]):
    raise SystemExit("FAIL: the FEM/DEM series differ in length or are empty")
for (ta, pa), (tb, pb) in zip(outputs["ascii"], outputs["binary"]):
    a, b = read(pa, vtk.vtkXMLUnstructuredGridReader), read(pb, vtk.vtkXMLUnstructuredGridReader)
    if ta != tb or a.keys() != b.keys() or not {"stress", "velocity", "displacement", "body"} <= a.keys():
        raise SystemExit(f"FAIL: {pa.name}: arrays {sorted(a.keys())} / {sorted(b.keys())}")
    for name in a:
        if a[name].shape != b[name].shape or (a[name] != b[name]).any():
            raise SystemExit(f"FAIL: {pa.name}: array {name} differs between ascii and binary")
    checked += 1
print(f"vtk read-back: OK ({checked} spheres and meshes compared bit for bit)")
