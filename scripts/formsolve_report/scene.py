"""The scene to render: the part made whole by its symmetry (an
axisymmetric section revolved with a quarter left open, a plane-strain
section mirrored and extruded over its width, a 3-D quarter or half model
mirrored), the tools, the split column's marker, and the direction the
camera looks from."""
import math
import os

from .mesh import add_penetration, append, merged, surface_of
from .vtu import read_vtu

# The nodal fields the pictures show, the only ones read of a VTU file:
# the thinning, and the contact gap for the penetration (mesh.add_penetration).
FIELDS = ("thinning_percent", "contact_gap")


def column_position(grid, split, axisymmetric):
    """The current mid-surface position of the split's column: the nodes
    whose reference position (position minus displacement) is nearest its
    planform position, averaged through the thickness."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy as np
    x = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    ref = x - vtk_to_numpy(grid.GetPointData().GetArray("displacement"))[:, :3]
    a = math.radians(split["angle"])
    if axisymmetric:
        d = np.abs(ref[:, 0] - split["R0"])
    else:
        d = np.hypot(ref[:, 0] - split["R0"] * math.cos(a), ref[:, 1] - split["R0"] * math.sin(a))
    return x[d <= d.min() + 1e-3].mean(axis=0)  # float32 positions: a column's nodes ~1e-4 mm apart


def rotated(data, degrees, vtk, swap=False):
    """data turned about z; swap first maps the section's (r, z, 0) to (r, 0, z)."""
    t = vtk.vtkTransform()
    t.RotateZ(degrees)
    if swap:
        t.Concatenate([1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1])
    f = vtk.vtkTransformFilter()
    f.SetTransform(t)
    f.SetInputData(data)
    f.Update()
    return f.GetOutput()


def swept(lines, start, angle, vtk):
    """The r-z section's lines (polydata) swept about the axis from `start`
    degrees over `angle`."""
    sweep = vtk.vtkRotationalExtrusionFilter()
    sweep.SetInputData(rotated(lines, start, vtk, swap=True))
    sweep.SetAngle(angle)
    sweep.SetResolution(max(int(angle / 3), 4))
    sweep.CappingOff()
    sweep.Update()
    return sweep.GetOutput()


def outline_of(section, vtk):
    """The boundary edges of a 2-D section's surface (polydata lines)."""
    outline = vtk.vtkFeatureEdges()
    outline.SetInputData(section)
    outline.BoundaryEdgesOn()
    outline.FeatureEdgesOff()
    outline.NonManifoldEdgesOff()
    outline.ManifoldEdgesOff()
    outline.ColoringOff()
    outline.Update()
    return outline.GetOutput()


def open_gap(data):
    """(from, to) in degrees: the largest angular gap of a revolved copy's
    points about the z axis, the quarter it leaves open."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy as np
    p = vtk_to_numpy(data.GetPoints().GetData())
    p = p[np.hypot(p[:, 0], p[:, 1]) > 1e-6]
    a = np.unique(np.round(np.mod(np.degrees(np.arctan2(p[:, 1], p[:, 0])), 360.0), 3) % 360.0)
    gaps = np.diff(np.append(a, a[0] + 360.0))
    k = int(np.argmax(gaps))
    return float(a[k]), float(a[k] + gaps[k])


def revolved_scene(run, grid, tools, split, vtk):
    """The axisymmetric part swept about z with a quarter open: the revolved
    copy when it was written, else the section's outline swept here with the
    section itself as the two cut faces. The tools as their profiles on the
    cut faces; the split column marked on a cut face."""
    d = run.directory
    if run.revolved:
        volume = merged(read_vtu(os.path.join(d, run.revolved), FIELDS), vtk)
        add_penetration(volume, vtk)
        gap = open_gap(volume)
        surface = surface_of(volume, vtk)
    else:
        gap = (270.0, 360.0)
        section = surface_of(grid, vtk)
        surface = append([swept(outline_of(section, vtk), 0.0, 270.0, vtk),
                          rotated(section, 0.0, vtk, swap=True), rotated(section, 270.0, vtk, swap=True)], vtk)
    scene = {"surface": surface, "gap": gap, "azimuth": (gap[0] + gap[1]) / 2, "marker": None,
             "tools": None, "tool_lines": None}
    if tools is not None:
        # The tools' profiles on both cut faces, where they meet the section.
        # Swept tool surfaces would lie on the sheet, their facets crossing
        # its faces in a saw-tooth pattern, and hide the inside of the cup.
        lines = vtk.vtkGeometryFilter()
        lines.SetInputData(tools)
        lines.Update()
        scene["tool_lines"] = append([rotated(lines.GetOutput(), a, vtk, swap=True) for a in gap], vtk)
    if split and split["R0"] is not None:  # a column to mark
        r, z = column_position(grid, split, True)[:2]
        a = math.radians(gap[0])  # the cut face the open quarter starts at
        scene["marker"] = (r * math.cos(a), r * math.sin(a), z)
    return scene


def extruded(data, width, vtk):
    """The x-z section's (polydata) points (x, z, 0) moved to (x, 0, z) and
    swept along y over width: faces from its lines, a ribbon from faces."""
    sweep = vtk.vtkLinearExtrusionFilter()
    sweep.SetInputData(rotated(data, 0.0, vtk, swap=True))
    sweep.SetExtrusionTypeToVectorExtrusion()
    sweep.SetVector(0.0, width, 0.0)
    sweep.CappingOff()
    sweep.Update()
    return sweep.GetOutput()


def extruded_scene(run, grid, tools, split, vtk):
    """The plane-strain part: the section mirrored at x = 0 (the whole
    channel) and swept over the width it stands for, the section itself as
    the two end faces; the tools as their profiles on the end faces; the
    split column marked on the front face (y = 0)."""
    width = float(run.summary.get("section_width", "1") or 1)
    section = surface_of(both_halves(grid, vtk), vtk)
    front = rotated(section, 0.0, vtk, swap=True)
    surface = append([extruded(outline_of(section, vtk), width, vtk), front, shifted(front, width, vtk)], vtk)
    # gap: the side view looks at the front face (y = 0) face-on.
    scene = {"surface": surface, "gap": (-180.0, -90.0), "azimuth": -60.0, "marker": None,
             "tools": None, "tool_lines": None}
    if tools is not None:
        lines = polydata(both_halves(tools, vtk), vtk)
        front_lines = rotated(lines, 0.0, vtk, swap=True)
        scene["tool_lines"] = append([front_lines, shifted(front_lines, width, vtk)], vtk)
    if split and split["R0"] is not None:  # a column to mark
        x, z = column_position(grid, split, True)[:2]
        scene["marker"] = (x, 0.0, z)
    return scene


def both_halves(data, vtk):
    """data and its mirror image at x = 0, as one grid."""
    a = vtk.vtkAppendFilter()
    a.AddInputData(data)
    a.AddInputData(reflected(data, ["x"], vtk))
    a.Update()
    return merged(a.GetOutput(), vtk)


def polydata(data, vtk):
    f = vtk.vtkGeometryFilter()
    f.SetInputData(data)
    f.Update()
    return f.GetOutput()


def shifted(data, dy, vtk):
    """data moved by dy along y."""
    t = vtk.vtkTransform()
    t.Translate(0.0, dy, 0.0)
    f = vtk.vtkTransformFilter()
    f.SetTransform(t)
    f.SetInputData(data)
    f.Update()
    return f.GetOutput()


def reflected(data, planes, vtk):
    """data mirrored at x = 0 and/or y = 0 (the input left out)."""
    out = data
    for plane in planes:
        f = vtk.vtkReflectionFilter()
        f.SetInputData(out)
        f.SetPlane({"x": f.USE_X, "y": f.USE_Y}[plane])
        f.SetCenter(0.0)
        f.CopyInputOff()
        f.Update()
        out = f.GetOutput()
    return out


def tool_profiles(tools, grid, vtk):
    """A slice's tools as their profiles across its middle (lines): the
    straight tools run along y, far beyond the slice, and seen face-on their
    surfaces would be edges."""
    lo, hi = grid.GetBounds()[2:4]
    plane = vtk.vtkPlane()
    plane.SetOrigin(0.0, 0.5 * (lo + hi), 0.0)
    plane.SetNormal(0.0, 1.0, 0.0)
    cut = vtk.vtkCutter()
    cut.SetInputData(tools)
    cut.SetCutFunction(plane)
    cut.Update()
    return cut.GetOutput()


def mirrored_scene(run, grid, tools, split, view, vtk):
    """A 3-D model completed by its symmetry: the whole part; for the
    section view a quarter model as three quarters (x >= 0, y >= 0 left
    open: the sections at x = 0 and y = 0 show) and a half model alone. A
    slice is mirrored at x = 0 and seen face-on at its face y = 0, with the
    tools' profiles in that face."""
    pieces = {"quarter": [[], ["x"], ["y"], ["x", "y"]], "half": [[], ["x"]],
              "slice": [[], ["x"]]}.get(run.model, [[]])
    profiles = None
    if run.model == "slice" and tools is not None:
        profiles, tools = tool_profiles(tools, grid, vtk), None
    if view == "section" and run.model in ("quarter", "half"):
        pieces = pieces[1:] if run.model == "quarter" else pieces[:1]

    def whole(data):
        a = vtk.vtkAppendFilter()
        for p in pieces:
            a.AddInputData(reflected(data, p, vtk))
        a.Update()
        return merged(a.GetOutput(), vtk)  # no seams at the symmetry planes
    scene = {"surface": surface_of(whole(grid), vtk), "tools": whole(tools) if tools is not None else None,
             "gap": None, "marker": None, "tool_lines": None}
    if split and split["R0"] is not None:  # a column to mark
        x, y, z = column_position(grid, split, False)
        if view == "section" and run.model == "quarter":  # its image opposite the open quarter,
            x, y = -x, -y                                   # seen from inside through the opening
        scene["marker"] = (x, y, z)
        scene["azimuth"] = math.degrees(math.atan2(y, x))
    else:  # the thinnest point
        at = [float(v) for v in run.summary.get("min_thickness_location", "1 0 0").split()]
        scene["azimuth"] = math.degrees(math.atan2(at[1], at[0])) if len(at) == 3 else 0.0
    if view == "section":
        scene["azimuth"] = {"quarter": 45.0, "half": 180.0}.get(run.model, scene["azimuth"])
    if run.model == "slice":
        scene["azimuth"] = -90.0  # the face y = 0, the section, towards the camera
        if profiles is not None and profiles.GetNumberOfCells() > 0:
            scene["tool_lines"] = polydata(whole(profiles), vtk)
    return scene


def camera_direction(scene, view, axisymmetric):
    """Unit vector from the part towards the camera. Axisymmetric: the views
    look into the open quarter, so the cut faces (the wall's section) face
    the camera; 3-D: at the split or the thinnest point."""
    phi = math.radians(scene["azimuth"])
    c, s = math.cos(phi), math.sin(phi)
    if view == "top":
        v = (0.0, -0.05, 1.0)
    elif view == "side" and axisymmetric:  # the cut face at gap[0] face-on
        a = math.radians(scene["gap"][0] + 90)
        v = (math.cos(a), math.sin(a), 0.12)
    elif view == "side":
        v = (c, s, 0.1)
    elif view == "section":
        v = (c, s, 0.25)
    else:  # iso: from above into the open quarter; 3-D from outside, a little below
        v = (c, s, 0.55) if axisymmetric else (c, s, -0.3)
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]

