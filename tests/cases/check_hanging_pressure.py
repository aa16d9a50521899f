"""Contact pressure under the flat face of the punch (r < 2.8 mm; the nose
starts at r = 3) from the last VTU, on a mesh whose refinement boundary
crosses that face: the pressure is smooth there, min/max >= 0.5 over the
face's nodes (hanging ones included), and the face has refined nodes (a
coordinate at an odd multiple of the fine spacing 0.625 mm) and coarse ones.

Usage: check_hanging_pressure.py OUT"""
import os, sys
import xml.etree.ElementTree as ET
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

out = sys.argv[1]
last = ET.parse(os.path.join(out, "solution.pvd")).getroot().findall(".//DataSet")[-1]
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName(os.path.join(out, last.get("file")))
reader.Update()
grid = reader.GetOutput()
x = vtk_to_numpy(grid.GetPoints().GetData())
p = vtk_to_numpy(grid.GetPointData().GetArray("contact_pressure"))
face = (x[:, 2] > 4.5) & (np.hypot(x[:, 0], x[:, 1]) < 2.8) & (p > 0)
nodes, first = np.unique(np.round(x[face], 4), axis=0, return_index=True)
pressure = p[face][first]
odd = lambda c: abs(c / 0.625 - round(c / 0.625)) < 0.05 and round(c / 0.625) % 2 == 1
n_odd = sum(odd(a) or odd(b) for a, b, _ in nodes)
ratio = pressure.min() / pressure.max()
for (a, b, c), q in zip(nodes, pressure):
    print(f"  x={a:6.3f} y={b:6.3f}  p={q:7.1f} MPa")
print(f"{len(nodes)} nodes on the punch face, {n_odd} refined; "
      f"pressure min/max {ratio:.3f} (limit 0.5)")
sys.exit(0 if 0 < n_odd < len(nodes) and ratio >= 0.5 else 1)
