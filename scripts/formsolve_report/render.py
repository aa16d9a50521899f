"""The rendered pictures, thickness-change.png and penetration.png: the
scene (scene.py) drawn offscreen with VTK, coloured by a field, with a
colour bar and a caption. They are made in a subprocess, the launcher run
again with the internal --render option: VTK needs an X server (xvfb-run
when there is no DISPLAY), and a crash there costs only these pictures.
vtk is imported in that subprocess only and handed to the functions."""
import math
import os
import shutil
import subprocess
import sys

from .mesh import add_penetration, merged
from .rundata import Run
from .scene import camera_direction, mirrored_scene, revolved_scene
from .split import split_event
from .vtu import read_vtu

WIDTH, HEIGHT = 1000, 720  # pixels of a rendered picture
PART = 0.8  # the part's share of the width; the colour bar has the rest


def render(args, report):
    """thickness-change.png and penetration.png with VTK, in a subprocess
    (VTK needs an X server: xvfb-run when there is no DISPLAY). None, or
    why there are no pictures."""
    try:
        import vtk  # noqa: F401
    except ImportError:
        return "python3-vtk9 is missing: no rendered pictures"
    # args.launcher: the formsolve-report this run was started as, so that
    # the subprocess finds this same package (source, build or install tree).
    cmd = [sys.executable, args.launcher, "--render", args.directory, "--output", report,
           "--view", args.view]
    if args.range:
        cmd += ["--range"] + [repr(v) for v in args.range]
    if args.no_tools:
        cmd.append("--no-tools")
    if args.travel is not None:
        cmd += ["--travel", repr(args.travel)]
    if not os.environ.get("DISPLAY"):
        if shutil.which("xvfb-run") is None:
            return "no X server and no xvfb-run (Debian package xvfb): no rendered pictures"
        cmd = ["xvfb-run", "-a"] + cmd
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        return "rendering failed: " + (done.stderr.strip().splitlines() or ["?"])[-1]
    return None


def render_pictures(args, report):
    """The --render subprocess: both pictures of the report's VTU output into report."""
    import vtk
    run = Run(args)
    if run.vtu is None:
        raise SystemExit("no VTU output at or before the report's travel")
    grid = merged(read_vtu(os.path.join(run.directory, run.vtu)), vtk)
    add_penetration(grid, vtk)
    tools = None
    if run.tools and not args.no_tools:
        tools = read_vtu(os.path.join(run.directory, run.tools))
    split = split_event(run)
    scene = (revolved_scene(run, grid, tools, split, vtk) if run.axisymmetric
             else mirrored_scene(run, grid, tools, split, args.view, vtk))
    caption = [f"punch travel {run.vtu_travel:.2f} mm (step {run.vtu_step}); view: {args.view}"]
    if scene["marker"]:
        caption.append(f"black ball: the split column ({split['measure']} at {split['travel']:.2f} mm)")
    for field, title, name, fixed in (
            ("thinning_percent", "thickness change (%)\nthinning +\nthickening −", "thickness-change.png", args.range),
            ("penetration_um", "contact\npenetration\n(micrometres)", "penetration.png", None)):
        picture(scene, field, title, fixed, caption, args.view, run.axisymmetric,
                os.path.join(report, name), vtk)


def nice_ticks(lo, hi, n=5):
    """Round tick values spanning [lo, hi] (1, 2, 2.5 or 5 times a power of 10)."""
    span = max(hi - lo, 1e-12)
    raw = span / n
    power = 10 ** math.floor(math.log10(raw))
    step = min((m * power for m in (1, 2, 2.5, 5, 10) if m * power >= raw), default=10 * power)
    first = math.floor(lo / step) * step
    ticks = [first + k * step for k in range(int(math.ceil((hi - first) / step - 1e-9)) + 1)]
    return [round(t, 10) for t in ticks]


def colour_scale(values, fixed, vtk):
    """(lookup table, ticks, lo, hi) of a field: the data's range widened
    to round ticks, or the --range chosen (fixed)."""
    lo, hi = fixed or values.GetRange()
    if hi - lo < 1e-9:  # a uniform field (the blank) in the middle of the scale
        lo, hi = lo - 1, hi + 1
    ticks = nice_ticks(lo, hi) if not fixed else nice_ticks(*fixed)
    if fixed:
        ticks = [t for t in ticks if fixed[0] - 1e-9 <= t <= fixed[1] + 1e-9]
    lo, hi = (fixed[0], fixed[1]) if fixed else (ticks[0], ticks[-1])
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)  # blue thick, red thin / deep
    lut.SetTableRange(lo, hi)
    if fixed:  # outside a chosen range: grey below, black above, not the end colours
        lut.SetBelowRangeColor(0.7, 0.7, 0.7, 1)
        lut.SetAboveRangeColor(0.1, 0.1, 0.1, 1)
        lut.UseBelowRangeColorOn()
        lut.UseAboveRangeColorOn()
    lut.Build()
    return lut, ticks, lo, hi


def colour_bar(renderer, lut, ticks, title, vtk):
    """A vertical bar with its title as separate text above it, both in the
    right-hand viewport, so that neither is clipped nor lies on the part."""
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetUseCustomLabels(True)
    labels = vtk.vtkDoubleArray()
    for t in ticks:
        labels.InsertNextValue(t)
    bar.SetCustomLabels(labels)
    bar.SetLabelFormat("%g")
    bar.SetPosition(0.08, 0.06)
    bar.SetWidth(0.6)
    bar.SetHeight(0.66)
    bar.SetUnconstrainedFontSize(True)
    bar.SetTextPositionToSucceedScalarBar()
    text = vtk.vtkTextActor()
    text.SetInput(title)
    text.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    text.SetPosition(0.08, 0.76)
    for prop, size in ((bar.GetLabelTextProperty(), 14), (text.GetTextProperty(), 15)):
        prop.SetColor(0, 0, 0)
        prop.SetFontSize(size)
        prop.ItalicOff()
        prop.BoldOff()
        prop.ShadowOff()
    text.GetTextProperty().SetVerticalJustificationToBottom()
    renderer.AddActor2D(bar)
    renderer.AddActor2D(text)


def frame(renderer, surface, direction, view, aspect):
    """A parallel projection along direction that fills the viewport with
    the part (its points' extent across the view, not its bounding box)."""
    from vtk.util.numpy_support import vtk_to_numpy
    import numpy as np
    points = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    d = np.array(direction)
    up = np.array((0.0, 1.0, 0.0) if view == "top" else (0.0, 0.0, 1.0))
    up -= d * (up @ d)
    up /= np.linalg.norm(up)
    right = np.cross(up, d)
    across, along = points @ right, points @ up
    centre = (right * (across.min() + across.max()) / 2 + up * (along.min() + along.max()) / 2
              + d * (points @ d).mean())
    depth = np.ptp(points @ d) + np.ptp(across) + np.ptp(along)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + depth * d))
    camera.SetViewUp(*up)
    camera.SetParallelScale(1.1 * max(np.ptp(along) / 2, np.ptp(across) / (2 * aspect)))
    renderer.ResetCameraClippingRange()


def part_actor(surface, field, lut, lo, hi, vtk):
    """The part, smoothly shaded and coloured by field."""
    normals = vtk.vtkPolyDataNormals()  # smooth shading: no facet lines on the part
    normals.SetInputData(surface)
    normals.SetFeatureAngle(60)
    normals.Update()
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputData(normals.GetOutput())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(lo, hi)
    mapper.SetLookupTable(lut)
    mapper.InterpolateScalarsBeforeMappingOn()  # colour bands follow the field, not the cells
    # The sheet lies on the tools (micrometres apart): drawn a little towards
    # the camera, it is not speckled by the tools' faces.
    mapper.SetResolveCoincidentTopologyToPolygonOffset()
    mapper.SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -20)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    # A headlight, and ambient light so that no face turned away is dark.
    actor.GetProperty().SetAmbient(0.45)
    actor.GetProperty().SetDiffuse(0.65)
    return actor


def add_tools(renderer, scene, vtk):
    """The tools faint (3-D), or their profiles on the cut faces (axisymmetric)."""
    def plain(data, mapper, colour):
        mapper.SetInputData(data)
        mapper.ScalarVisibilityOff()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*colour)
        renderer.AddActor(actor)
        return actor.GetProperty()
    if scene["tools"] is not None:
        plain(scene["tools"], vtk.vtkDataSetMapper(), (0.55, 0.55, 0.6)).SetOpacity(0.2)
    if scene["tool_lines"] is not None:
        plain(scene["tool_lines"], vtk.vtkPolyDataMapper(), (0.3, 0.3, 0.35)).SetLineWidth(2)


def add_marker(renderer, centre, size, vtk):
    """The split column as a black ball, sized to the part."""
    ball = vtk.vtkSphereSource()
    ball.SetCenter(*centre)
    ball.SetRadius(0.012 * size)
    ball.SetThetaResolution(24)
    ball.SetPhiResolution(24)
    bm = vtk.vtkPolyDataMapper()
    bm.SetInputConnection(ball.GetOutputPort())
    ba = vtk.vtkActor()
    ba.SetMapper(bm)
    ba.GetProperty().SetColor(0, 0, 0)
    renderer.AddActor(ba)


def add_caption(renderer, caption, vtk):
    note = vtk.vtkTextActor()
    note.SetInput("\n".join(caption))
    note.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    note.SetPosition(0.02, 0.02)
    note.GetTextProperty().SetColor(0.2, 0.2, 0.2)
    note.GetTextProperty().SetFontSize(13)
    renderer.AddActor2D(note)


def write_png(window, path, vtk):
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


def picture(scene, field, title, fixed, caption, view, axisymmetric, path, vtk):
    """The part coloured by field, the tools faint, the split marked; the
    colour bar in its own viewport on the right."""
    surface = scene["surface"]
    lut, ticks, lo, hi = colour_scale(surface.GetPointData().GetArray(field), fixed, vtk)
    part = vtk.vtkRenderer()
    part.SetViewport(0, 0, PART, 1)
    part.AddActor(part_actor(surface, field, lut, lo, hi, vtk))
    part.SetBackground(1, 1, 1)
    part.SetUseDepthPeeling(0)
    vtk.vtkLightKit().AddLightsToRenderer(part)
    bounds = surface.GetBounds()
    add_tools(part, scene, vtk)
    if scene["marker"]:
        add_marker(part, scene["marker"], math.dist(bounds[0::2], bounds[1::2]), vtk)
    add_caption(part, caption, vtk)
    legend = vtk.vtkRenderer()
    legend.SetViewport(PART, 0, 1, 1)
    legend.SetBackground(1, 1, 1)
    colour_bar(legend, lut, ticks, title + (f"\ngrey: below {lo:g}\nblack: above {hi:g}" if fixed else ""), vtk)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(part)
    window.AddRenderer(legend)
    window.SetSize(WIDTH, HEIGHT)
    frame(part, surface, camera_direction(scene, view, axisymmetric), view, PART * WIDTH / HEIGHT)
    window.Render()
    write_png(window, path, vtk)
