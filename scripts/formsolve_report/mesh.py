"""deal.II's VTU output as a clean VTK surface to render: coincident
points merged, the inner faces at hanging nodes dropped, and the contact
penetration as a field. vtk is handed in (vtkclasses, imported only in the
--render subprocess); numpy and vtk's numpy support are imported where used."""


def merged(grid, vtk):
    """The grid with coincident points merged. deal.II writes every cell
    with its own vertices, so every face of every cell would count as
    boundary: the part would be drawn with all its inner faces, which show
    through as dark hatching."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
    import numpy as np
    points = vtk_to_numpy(grid.GetPoints().GetData())
    bounds = np.ptp(points, axis=0).max() if len(points) else 1.0
    first, inverse = distinct_rows(np.round(points / (1e-7 * bounds)).astype(np.int64))
    out = vtk.vtkUnstructuredGrid()
    merged_points = vtk.vtkPoints()
    merged_points.SetData(numpy_to_vtk(np.ascontiguousarray(points[first]), deep=1))
    out.SetPoints(merged_points)
    cells = grid.GetCells()
    connectivity = inverse[vtk_to_numpy(cells.GetConnectivityArray())]
    array = vtk.vtkCellArray()
    array.SetData(numpy_to_vtkIdTypeArray(vtk_to_numpy(cells.GetOffsetsArray()).astype(np.int64), deep=1),
                  numpy_to_vtkIdTypeArray(connectivity.astype(np.int64), deep=1))
    out.SetCells(grid.GetCellTypesArray(), array)
    data = grid.GetPointData()
    for k in range(data.GetNumberOfArrays()):
        values = numpy_to_vtk(np.ascontiguousarray(vtk_to_numpy(data.GetArray(k))[first]), deep=1)
        values.SetName(data.GetArrayName(k))
        out.GetPointData().AddArray(values)
    return out


def distinct_rows(key):
    """(first, inverse) as np.unique(key, axis=0, return_index=True,
    return_inverse=True) gives them, by a lexicographic sort of the integer
    rows: 3 times faster (unique sorts the rows as opaque records)."""
    import numpy as np
    order = np.lexsort(key.T[::-1])
    ordered = key[order]
    new = np.ones(len(key), bool)
    new[1:] = np.any(ordered[1:] != ordered[:-1], axis=1)
    inverse = np.empty(len(key), np.int64)
    inverse[order] = np.cumsum(new) - 1
    return order[new], inverse  # lexsort is stable: order[new] is each row's first occurrence


def add_penetration(data, vtk):
    """penetration_um: how deep a node sits in a tool (contact_gap < 0), in micrometres."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy as np
    gap = vtk_to_numpy(data.GetPointData().GetArray("contact_gap"))
    values = numpy_to_vtk(np.maximum(-gap, 0.0) * 1000.0, deep=1)
    values.SetName("penetration_um")
    data.GetPointData().AddArray(values)


def surface_of(data, vtk):
    s = vtk.vtkDataSetSurfaceFilter()
    s.SetInputData(data)
    s.Update()
    return without_hanging_faces(s.GetOutput(), vtk)


def without_hanging_faces(surface, vtk):
    """The surface without the inner faces at hanging nodes. Where a cell
    meets refined neighbours, its face and their four faces share no
    points, so the surface filter keeps them all, inside the sheet; they
    show through as bright dashes. Such a coarse face has a vertex at its
    centroid (the hanging node), and the fine faces have it as a corner."""
    from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy
    import numpy as np
    polys = surface.GetPolys()
    if surface.GetNumberOfPolys() == 0 or surface.GetNumberOfPolys() != surface.GetNumberOfCells():
        return surface
    points = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    conn = vtk_to_numpy(polys.GetConnectivityArray())
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    sizes = np.diff(offsets)
    owner = np.repeat(np.arange(len(sizes)), sizes)
    centroids = np.zeros((len(sizes), 3))
    np.add.at(centroids, owner, points[conn])
    centroids /= sizes[:, None]
    tol = 1e-6 * max(np.ptp(points, axis=0).max(), 1e-12)
    index = {tuple(k): i for i, k in enumerate(np.round(points / tol).astype(np.int64))}
    hanging = [index.get(tuple(k)) for k in np.round(centroids / tol).astype(np.int64)]
    coarse = np.array([h is not None for h in hanging])
    if not coarse.any():
        return surface
    marks = np.zeros(len(points), bool)
    marks[[h for h in hanging if h is not None]] = True
    fine = np.zeros(len(sizes), bool)
    np.logical_or.at(fine, owner, marks[conn])
    keep = ~(coarse | fine)
    kept = keep[owner]
    array = vtk.vtkCellArray()
    array.SetData(numpy_to_vtkIdTypeArray(np.concatenate([[0], np.cumsum(sizes[keep])]).astype(np.int64), deep=1),
                  numpy_to_vtkIdTypeArray(conn[kept].astype(np.int64), deep=1))
    out = vtk.vtkPolyData()
    out.SetPoints(surface.GetPoints())
    out.GetPointData().ShallowCopy(surface.GetPointData())
    out.SetPolys(array)
    return out


def append(pieces, vtk):
    a = vtk.vtkAppendPolyData()
    for p in pieces:
        a.AddInputData(p)
    a.Update()
    return a.GetOutput()

