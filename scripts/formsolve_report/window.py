"""A rendered picture of the scene (scene.py): the part coloured by a
field, smoothly shaded, the tools faint, the split column marked, a
caption, and the colour bar in its own viewport on the right; drawn
offscreen with VTK into a PNG. vtk (vtkclasses) is handed in: it is
imported only in the --render subprocess (render.py)."""
import math

from .scene import camera_direction

WIDTH, HEIGHT = 1000, 720  # pixels of a rendered picture
PART = 0.8  # the part's share of the width; the colour bar has the rest


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


def colour_bar(renderer, vtk):
    """A vertical bar with its title as separate text above it, both in the
    right-hand viewport, so that neither is clipped nor lies on the part.
    (bar, title); show_scale sets them for a field."""
    bar = vtk.vtkScalarBarActor()
    bar.SetUseCustomLabels(True)
    bar.SetLabelFormat("%g")
    bar.SetPosition(0.08, 0.06)
    bar.SetWidth(0.6)
    bar.SetHeight(0.66)
    bar.SetUnconstrainedFontSize(True)
    bar.SetTextPositionToSucceedScalarBar()
    text = vtk.vtkTextActor()
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
    return bar, text


def show_scale(bar, text, lut, ticks, title, vtk):
    """The colour bar of one field: its colours, round ticks, title."""
    bar.SetLookupTable(lut)
    labels = vtk.vtkDoubleArray()
    for t in ticks:
        labels.InsertNextValue(t)
    bar.SetCustomLabels(labels)
    text.SetInput(title)


def frame(renderer, surface, direction, view, aspect):
    """A parallel projection along direction that fills the viewport with
    the part (its points' extent across the view, not its bounding box)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
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


def part_actor(surface, vtk):
    """The part, smoothly shaded; colour_by colours it by a field."""
    normals = vtk.vtkPolyDataNormals()  # smooth shading: no facet lines on the part
    normals.SetInputData(surface)
    normals.SetFeatureAngle(60)
    normals.Update()
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputData(normals.GetOutput())
    mapper.SetScalarModeToUsePointFieldData()
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


def colour_by(mapper, field, lut, lo, hi):
    """The part's colours: field through lut over [lo, hi]."""
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(lo, hi)
    mapper.SetLookupTable(lut)


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
    """The window as rendered last: no second rendering for the image
    (vtkWindowToImageFilter renders again by default)."""
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.ShouldRerenderOff()
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


class PartWindow:
    """The scene in one offscreen window: the part, the tools, the split's
    marker, the caption and the camera set up once; draw() colours the part
    by a field, sets the colour bar and writes the PNG. Both pictures share
    the window: its OpenGL context and shaders, a third of a second of
    software rendering, are made once."""

    def __init__(self, scene, caption, view, axisymmetric, vtk):
        self.vtk, self.surface = vtk, scene["surface"]
        part = vtk.vtkRenderer()
        part.SetViewport(0, 0, PART, 1)
        self.actor = part_actor(self.surface, vtk)
        part.AddActor(self.actor)
        part.SetBackground(1, 1, 1)
        part.SetUseDepthPeeling(0)
        vtk.vtkLightKit().AddLightsToRenderer(part)
        bounds = self.surface.GetBounds()
        add_tools(part, scene, vtk)
        if scene["marker"]:
            add_marker(part, scene["marker"], math.dist(bounds[0::2], bounds[1::2]), vtk)
        add_caption(part, caption, vtk)
        legend = vtk.vtkRenderer()
        legend.SetViewport(PART, 0, 1, 1)
        legend.SetBackground(1, 1, 1)
        self.bar, self.title = colour_bar(legend, vtk)
        self.window = vtk.vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.AddRenderer(part)
        self.window.AddRenderer(legend)
        self.window.SetSize(WIDTH, HEIGHT)
        frame(part, self.surface, camera_direction(scene, view, axisymmetric), view, PART * WIDTH / HEIGHT)

    def draw(self, field, title, fixed, path):
        """The part coloured by field (fixed: the --range chosen, else the
        data's), its colour bar with title, written to path."""
        vtk = self.vtk
        lut, ticks, lo, hi = colour_scale(self.surface.GetPointData().GetArray(field), fixed, vtk)
        colour_by(self.actor.GetMapper(), field, lut, lo, hi)
        show_scale(self.bar, self.title, lut, ticks,
                   title + (f"\ngrey: below {lo:g}\nblack: above {hi:g}" if fixed else ""), vtk)
        self.window.Render()
        write_png(self.window, path, vtk)
