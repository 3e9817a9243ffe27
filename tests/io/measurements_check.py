"""The measurement outputs of a 3D run (docs/measurements.md) through the real program.

- thermo.csv has the ledger's columns and balances: |residual| below 1e-2 of the energy
  dissipated (the energy_ledger verification case bounds it tighter and checks its order);
- contacts_NNNNNN.vtp, read back by VTK's own reader when the vtk module is present: one line per
  touching contact (pair_contacts + wall_contacts of the same thermo row), its cell arrays present;
- region.csv has its columns and one row per output;
- a run stopped at a step and restarted gives thermo.csv and region.csv bit for bit equal to the
  straight run's (the ledger's accumulators are in the checkpoint);
- region_min without region_max is refused with one line naming the key, exit status 2.

usage: /usr/bin/python3 measurements_check.py VERIDEM SCENE WORK_DIR
"""
import csv
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

veridem, scene, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
work.mkdir(parents=True, exist_ok=True)


def run(*args):
    return subprocess.run([veridem, "run", *map(str, args), "--quiet"], capture_output=True, text=True)


straight = work / "straight"
result = run(scene, "--out", straight)
if result.returncode != 0:
    raise SystemExit(f"FAIL: run: {result.stderr}")
thermo = list(csv.DictReader(open(straight / "thermo.csv")))
last = thermo[-1]
dissipated = sum(float(last[k]) for k in ("dissipated_normal_damping", "dissipated_tangential_damping",
                                           "dissipated_friction", "dissipated_rolling", "dissipated_adhesion"))
if not dissipated > 0 or abs(float(last["energy_residual"])) > 1e-2 * dissipated:
    raise SystemExit(f"FAIL: ledger residual {last['energy_residual']} J, dissipated {dissipated} J")
region = list(csv.DictReader(open(straight / "region.csv")))
stress = ["sxx", "syy", "szz", "sxy", "sxz", "syz"]
if len(region) != len(thermo) or list(region[0].keys()) != (
        ["t", "particles", "contacts", "coordination", "packing_fraction"] + stress +
        ["kinetic_" + s for s in stress]):
    raise SystemExit("FAIL: region.csv columns or rows")

frames = [(float(d.get("timestep")), straight / d.get("file"))
          for d in ElementTree.parse(straight / "contacts.pvd").getroot().iter("DataSet")]
if len(frames) != len(thermo):
    raise SystemExit(f"FAIL: {len(frames)} contact frames for {len(thermo)} outputs")
try:
    import vtk
    for (t, path), row in zip(frames, thermo):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(path))
        reader.Update()
        data = reader.GetOutput()
        expected = int(row["pair_contacts"]) + int(row["wall_contacts"])
        if data.GetNumberOfLines() != expected:
            raise SystemExit(f"FAIL: {path.name}: {data.GetNumberOfLines()} lines, {expected} contacts")
        for name in ("ids", "wall", "contact_point", "normal", "normal_force", "tangential_force",
                     "force_magnitude"):
            if data.GetCellData().GetArray(name) is None:
                raise SystemExit(f"FAIL: {path.name}: no cell array {name}")
    read_back = "read back by VTK"
except ImportError:
    read_back = "not read back (no vtk module)"

interrupted = work / "interrupted"
first = run(scene, "--out", interrupted, "--stop-at-step", 2345)
second = run(scene, "--out", interrupted, "--restart", interrupted / "checkpoint.bin")
if first.returncode != 0 or second.returncode != 0:
    raise SystemExit(f"FAIL: restart: {first.stderr} {second.stderr}")
for name in ("thermo.csv", "region.csv"):
    if (straight / name).read_bytes() != (interrupted / name).read_bytes():
        raise SystemExit(f"FAIL: {name} differs after a restart")

bad = work / "bad.toml"
bad.write_text(scene.read_text().replace("region_max", "# region_max"))
result = run(bad, "--out", work / "bad")
if result.returncode != 2 or "region_min" not in result.stderr or result.stderr.count("\n") != 1:
    raise SystemExit(f"FAIL: region_min alone: status {result.returncode}, {result.stderr!r}")
print(f"measurements: OK (ledger residual {float(last['energy_residual']):.3g} J of {dissipated:.3g} J "
      f"dissipated; contacts {read_back}; restart bit-identical; bad region refused)")
