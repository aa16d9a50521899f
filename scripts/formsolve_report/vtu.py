"""formsolve's VTU output read with VTK: the grid, and sheet.csv's rows
rebuilt from its nodal fields (for --travel without a sheet_<T>mm.csv).
numpy and vtk are imported where used: without python3-vtk9 only what
needs them is left out."""

SHEET_FIELDS = ("thickness", "thinning_percent", "major_strain", "minor_strain", "safety_zone")


def read_vtu(path, fields=None):
    """The grid of a .vtu or .pvtu file with the nodal fields named (all if
    None): the others are not even decompressed (a revolved copy carries
    20 fields, the pictures need 2)."""
    from . import vtkclasses as vtk
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    if fields is not None:
        reader.UpdateInformation()  # the file's fields: a selection made before has none to act on
        selection = reader.GetPointDataArraySelection()
        selection.DisableAllArrays()
        for name in fields:
            selection.EnableArray(name)
        reader.GetCellDataArraySelection().DisableAllArrays()
    reader.Update()
    return reader.GetOutput()


def sheet_from_vtu(path, section):
    """sheet.csv's rows rebuilt from a VTU's nodal fields: every node of a
    column carries the column's values; columns are the nodes' in-plane
    reference positions (current position minus displacement)."""
    import numpy as np
    grid = read_vtu(path, ("displacement",) + SHEET_FIELDS)
    from vtkmodules.util.numpy_support import vtk_to_numpy
    pd = grid.GetPointData()
    x = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    ref = x - vtk_to_numpy(pd.GetArray("displacement"))[:, :3]
    fields = {n: vtk_to_numpy(pd.GetArray(n)) for n in SHEET_FIELDS}
    planar = ref[:, :1] if section else ref[:, :2]
    labels = columns_of(planar, 1e-3)
    order = np.argsort(labels, kind="stable")
    starts = np.flatnonzero(np.r_[True, np.diff(labels[order]) != 0])
    rows = []
    for nodes in np.split(order, starts[1:]):
        first = nodes[0]
        if fields["thickness"][first] <= 0:
            continue  # a node of no column (its field was never set)
        mid = x[nodes].mean(axis=0)
        p = planar[first]
        rows.append({
            "reference_radius": float(np.hypot(*p)) if len(p) == 2 else float(p[0]),
            "reference_angle": float(np.degrees(np.arctan2(p[1], p[0]))) if len(p) == 2 else 0.0,
            "r": float(mid[0]) if section else float(np.hypot(mid[0], mid[1])),
            "z": float(mid[1] if section else mid[2]),
            "thickness": float(fields["thickness"][first]),
            "thinning_percent": float(fields["thinning_percent"][first]),
            "major_strain": float(fields["major_strain"][first]),
            "minor_strain": float(fields["minor_strain"][first]),
            "damage": float("nan"),
            "zone": int(round(float(fields["safety_zone"][first]))),
            "rim": 0.0})
    outer = max((r["reference_radius"] for r in rows), default=0)
    for r in rows:  # the blank's edge: no rim flag in the VTU
        r["rim"] = float(r["reference_radius"] >= 0.99 * outer)
    return rows


def columns_of(planar, tol):
    """A label per node: nodes whose planform positions lie within about
    tol share it. The VTU's float32 positions minus displacements put the
    nodes of one column up to ~1e-4 mm apart, so rounding alone would split
    columns; neighbouring cells of a tol grid are joined instead (columns
    lie much further apart than tol)."""
    import itertools
    import numpy as np
    cells, inverse = np.unique(np.floor(planar / tol).astype(np.int64), axis=0, return_inverse=True)
    index = {tuple(c): i for i, c in enumerate(cells)}
    parent = list(range(len(cells)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for i, c in enumerate(cells):
        for step in itertools.product((-1, 0, 1), repeat=len(c)):
            j = index.get(tuple(c + np.array(step)))
            if j is not None:
                parent[root(i)] = root(j)
    return np.array([root(i) for i in range(len(cells))])[inverse.ravel()]
