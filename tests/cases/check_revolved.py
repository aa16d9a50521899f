"""The revolved 3-D copy of an axisymmetric run (Output/Revolved copy), read
back with VTK: one with the last section file (or one per section file with
Revolved every output); vector fields have 3 components, and its volume is the
section's volume swept through the revolved angle. A bilinear section cell
swept between two half-planes dtheta apart spans sin(dtheta) int r dA, so
with n segments the revolved mesh holds n sin(dtheta) / (2 pi) times the
history's volume (2 pi int r dA), to float32 precision."""
import csv, math, os, re, sys
import results
import xml.etree.ElementTree as ET
import vtk
from vtk.util.numpy_support import vtk_to_numpy
import numpy as np

out = sys.argv[1]
angle = float(re.search(r"set Revolved angle\s*=\s*([0-9.eE+-]+)",
                        open(os.path.join(out, "parameters.prm")).read()).group(1))
datasets = ET.parse(os.path.join(out, "revolved.pvd")).getroot().findall(".//DataSet")
solutions = ET.parse(os.path.join(out, "solution.pvd")).getroot().findall(".//DataSet")
every = re.search(r"set Revolved every output\s*=\s*true",
                  open(os.path.join(out, "parameters.prm")).read())
if every:
    assert len(datasets) == len(solutions) >= 2, "one revolved copy per section file"
else:
    # Written with the last section file only.
    assert len(solutions) >= 2 and len(datasets) == 1, "one revolved copy, with the last section file"
    step = lambda d: re.search(r"_(\d+)\.pvtu$", d.get("file")).group(1)
    assert step(datasets[0]) == step(solutions[-1]), "the revolved copy is of the last step"
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName(os.path.join(out, datasets[-1].get("file")))
reader.Update()
grid = reader.GetOutput()
for name in ("velocity", "displacement"):
    assert grid.GetPointData().GetArray(name).GetNumberOfComponents() == 3, name
for name in ("thickness_strain", "contact_pressure", "equivalent_strain"):
    assert np.all(np.isfinite(vtk_to_numpy(grid.GetPointData().GetArray(name)))), name
# Exact volume of the trilinear cells: det J has degree <= 2 in each
# variable, so 2 x 2 x 2 Gauss points integrate it exactly. Every cell must be
# right-handed (det J > 0).
points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 8)
X = points[cells[:, [0, 1, 3, 2, 4, 5, 7, 6]]]  # VTK order -> lexicographic
g = np.array([0.5 - 0.5 / math.sqrt(3), 0.5 + 0.5 / math.sqrt(3)])
volume, smallest = 0.0, np.inf
for a in g:
    for b in g:
        for c in g:
            w = [(1 - a, a), (1 - b, b), (1 - c, c)]
            d = [(-1, 1)] * 3
            J = np.zeros((len(X), 3, 3))
            for v in range(8):
                i, j, k = v & 1, (v >> 1) & 1, (v >> 2) & 1
                dN = np.array([d[0][i] * w[1][j] * w[2][k],
                               w[0][i] * d[1][j] * w[2][k],
                               w[0][i] * w[1][j] * d[2][k]])
                J += X[:, v, :, None] * dN[None, None, :]
            det = np.linalg.det(J)
            smallest = min(smallest, det.min())
            volume += det.sum() / 8
assert smallest > -1e-9, f"a revolved cell is left-handed (det J = {smallest})"
rows = list(results.read(out))
n = math.ceil(angle / 5)
expected = float(rows[-1]["volume"]) * n * math.sin(math.radians(angle / n)) / (2 * math.pi)
err = abs(volume / expected - 1)
print(f"{grid.GetNumberOfCells()} hexahedra over {angle} degrees: volume {volume:.3f} mm^3, "
      f"expected {expected:.3f} mm^3, relative error {err:.1e} (limit 1e-5)")
sys.exit(0 if err <= 1e-5 else 1)
