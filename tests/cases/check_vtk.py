"""Read the written .pvd/.pvtu back with VTK's own reader: every expected field
present, with finite values, on both MPI ranks' pieces."""
import math, os, sys
import results
import xml.etree.ElementTree as ET
import vtk
from vtk.util.numpy_support import vtk_to_numpy
import numpy as np

out = sys.argv[1]
pvd = ET.parse(os.path.join(out, "solution.pvd")).getroot()
datasets = pvd.findall(".//DataSet")
assert len(datasets) >= 2, "expected the initial and later time steps in the .pvd"
point_fields = {"velocity": 3, "displacement": 3, "contact_gap": 1,
                "contact_pressure": 1, "penalty_factor": 1}
cell_fields = ["equivalent_strain", "equivalent_strain_rate", "flow_stress",
               "mean_stress", "thickness_strain", "mpi_rank"]
times = []
for ds in datasets:
    times.append(float(ds.get("timestep")))
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, ds.get("file")))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0
    for name, ncomp in point_fields.items():
        arr = grid.GetPointData().GetArray(name)
        assert arr is not None, f"{ds.get('file')}: point field {name} missing"
        assert arr.GetNumberOfComponents() == ncomp, f"{name}: components"
        assert np.all(np.isfinite(vtk_to_numpy(arr))), f"{name}: non-finite values"
    # deal.II writes cell data as piecewise-constant point data of each patch.
    for name in cell_fields:
        arr = grid.GetPointData().GetArray(name)
        assert arr is not None, f"{ds.get('file')}: cell field {name} missing"
        assert np.all(np.isfinite(vtk_to_numpy(arr))), f"{name}: non-finite values"
    ranks = set(vtk_to_numpy(grid.GetPointData().GetArray("mpi_rank")).astype(int))
    print(f"{ds.get('file')}: t={ds.get('timestep')}, {grid.GetNumberOfPoints()} points, ranks {sorted(ranks)}")
    assert ranks == {0, 1}, "expected pieces from 2 ranks"
assert times == sorted(times) and times[0] == 0.0
# The last file shows the sheet drawn down: displacement of order the travel.
disp = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
assert disp[:, 2].min() < -1.0, "the sheet did not move down with the punch"
print("all fields present and finite")

# The tools beside the sheet (tools.pvd, the same times): each tool's surface
# where the tool is at that time. drawing.prm: t0 = 0.78 mm, the punch face
# starts on the sheet and moves down by the travel, the die face stays at
# z = 0, the holder face at t0 + 0.05 mm (gap control).
import csv
history = {round(float(r["time"]), 9): r for r in results.read(out)}
tools = ET.parse(os.path.join(out, "tools.pvd")).getroot().findall(".//DataSet")
assert [float(ds.get("timestep")) for ds in tools] == times, "tools.pvd: not the times of solution.pvd"
for ds in tools:
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, ds.get("file")))
    reader.Update()
    grid = reader.GetOutput()
    z = vtk_to_numpy(grid.GetPoints().GetData())[:, 2]
    tool = vtk_to_numpy(grid.GetPointData().GetArray("tool")).astype(int)
    t = float(ds.get("timestep"))
    travel = float(history[round(t, 9)]["punch_travel"]) if t > 0 else 0.0
    expected = {0: ("lowest", 0.78 - travel), 1: ("highest", 0.0), 2: ("lowest", 0.83)}
    assert set(tool) == set(expected), f"{ds.get('file')}: tools {sorted(set(tool))}"
    for k, (which, face) in expected.items():
        zk = z[tool == k]
        got = zk.min() if which == "lowest" else zk.max()
        assert abs(got - face) < 1e-4, f"{ds.get('file')}: tool {k}'s face at z = {got}, expected {face}"
    print(f"{ds.get('file')}: {grid.GetNumberOfCells()} tool cells, punch face at z = {0.78 - travel:.3f} mm")
print("the tools' surfaces where the tools are")
