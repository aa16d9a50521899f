"""Penetration of every node pressed on the die, read from the last VTU:
adaptive within [0.8, 1.1] delta (measured 0.89..1.03); strict: adaptive-strict
<= delta and not far below it (the deepest judged node >= 0.5 delta, measured
0.73); bound: <= delta only (augmented Lagrangian). Nodes carrying less
than 5 % of the peak contact pressure (the rim of the contact zone, where the
lower bound of the factor may act) are listed but not judged."""
import os, sys
import xml.etree.ElementTree as ET
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

out, mode = sys.argv[1], sys.argv[2]
delta = 1e-3
last = ET.parse(os.path.join(out, "solution.pvd")).getroot().findall(".//DataSet")[-1]
reader = vtk.vtkXMLPUnstructuredGridReader()
reader.SetFileName(os.path.join(out, last.get("file")))
reader.Update()
grid = reader.GetOutput()
z = vtk_to_numpy(grid.GetPoints().GetData())[:, 2]
gap = vtk_to_numpy(grid.GetPointData().GetArray("contact_gap"))
p = vtk_to_numpy(grid.GetPointData().GetArray("contact_pressure"))
die = (z < 0.5) & (p > 0)  # bottom face in contact with the die
pen = -gap[die]
judged = p[die] >= 0.05 * p[die].max()
print(f"{die.sum()} die-contact points, {judged.sum()} judged; pressure {p[die].min():.3g}..{p[die].max():.3g} MPa")
print(f"penetration / delta: judged {pen[judged].min() / delta:.3f}..{pen[judged].max() / delta:.3f}, "
      f"all {pen.min() / delta:.3f}..{pen.max() / delta:.3f}")
if mode == "strict":
    ok = pen.max() <= delta * (1 + 1e-9) and pen[judged].max() >= 0.5 * delta
elif mode == "bound":
    ok = pen.max() <= delta * (1 + 1e-9)
else:
    ok = pen[judged].min() >= 0.8 * delta and pen[judged].max() <= 1.1 * delta
sys.exit(0 if ok else 1)
