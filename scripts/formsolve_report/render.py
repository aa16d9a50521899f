"""The rendered pictures, thickness-change.png and penetration.png, made in
a subprocess: the launcher run again with the internal --render option.
VTK needs an X server (xvfb-run when there is no DISPLAY), and a crash
there costs only these pictures. The subprocess is started before the
matplotlib plots and runs beside them (Rendering): on 2 cores the report
takes about as long as the longer of the two. vtk (vtkclasses) is imported
in that subprocess only and handed to the functions."""
import copy
import glob
import importlib.util
import os
import shutil
import subprocess
import sys

from . import timing
from .mesh import add_penetration, merged
from .window import PartWindow
from .rundata import Run
from .scene import FIELDS, extruded_scene, mirrored_scene, revolved_scene
from .split import split_event
from .vtu import read_vtu


class Rendering:
    """The --render subprocess under way: started at once, wait() for its
    outcome. problem: why there are no rendered pictures, or None."""

    def __init__(self, args, report):
        self.process = None
        self.problem = problem_of(args)
        if self.problem is None:
            self.process = subprocess.Popen(render_command(args, report), stdout=subprocess.PIPE,
                                            stderr=subprocess.PIPE, text=True)

    def wait(self):
        """None once both pictures are written, else why there are none."""
        if self.process is not None:
            _, err = self.process.communicate()
            if self.process.returncode != 0:
                self.problem = "rendering failed: " + (err.strip().splitlines() or ["?"])[-1]
            self.process = None
        return self.problem


def problem_of(args):
    """Why no subprocess can render (VTK or an X server missing), or None.
    VTK is looked up, not imported: importing it here would cost what the
    subprocess pays again."""
    if importlib.util.find_spec("vtkmodules") is None:
        return "python3-vtk9 is missing: no rendered pictures"
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run") is None:
        return "no X server and no xvfb-run (Debian package xvfb): no rendered pictures"
    return None


def render_command(args, report):
    """The subprocess's command line: args.launcher is the formsolve-report
    this run was started as, so that it finds this same package (source,
    build or install tree); under xvfb-run when there is no DISPLAY."""
    cmd = [sys.executable, args.launcher, "--render", args.directory, "--output", report,
           "--view", args.view]
    if args.range:
        cmd += ["--range"] + [repr(v) for v in args.range]
    if args.no_tools:
        cmd.append("--no-tools")
    if args.travel is not None:
        cmd += ["--travel", repr(args.travel)]
    return cmd if os.environ.get("DISPLAY") else ["xvfb-run", "-a"] + cmd


def render_pictures(args, report):
    """The --render subprocess: both pictures of the report's VTU output into report."""
    from . import vtkclasses as vtk
    timing.lap("render", "import the VTK classes")
    run = Run(args)
    if run.vtu is None:
        # Only the trimmed or the sprung part (Output interval = 0).
        trimmed_picture(run, args, report, vtk)
        springback_picture(run, args, report, vtk)
        return
    # displacement: to find the split's column in the grid (scene.column_position)
    grid = merged(read_vtu(os.path.join(run.directory, run.vtu), FIELDS + ("displacement",)), vtk)
    add_penetration(grid, vtk)
    tools = None
    if run.tools and not args.no_tools:
        tools = read_vtu(os.path.join(run.directory, run.tools), ())
    split = split_event(run)
    scene = (revolved_scene(run, grid, tools, split, vtk) if run.axisymmetric
             else extruded_scene(run, grid, tools, split, vtk) if run.plane_strain
             else mirrored_scene(run, grid, tools, split, args.view, vtk))
    timing.lap("render", "read the VTU output, make the scene")
    caption = [f"punch travel {run.vtu_travel:.2f} mm (step {run.vtu_step}); view: {args.view}"]
    if scene["marker"]:
        caption.append(f"black ball: the split column ({split['measure']} at {split['travel']:.2f} mm)")
    window = PartWindow(scene, caption, args.view, run.section, vtk)
    for field, title, name, fixed in (
            ("thinning_percent", "thickness change (%)\nthinning +\nthickening −", "thickness-change.png", args.range),
            ("penetration_um", "contact\npenetration\n(micrometres)", "penetration.png", None)):
        window.draw(field, title, fixed, os.path.join(report, name))
        timing.lap("render", name)
    trimmed_picture(run, args, report, vtk)
    springback_picture(run, args, report, vtk)


def part_outputs(run):
    """Whether the run wrote the trimmed or the sprung part (VTU files the
    rendering draws even without the forming's output)."""
    return run.as_of is None and any(glob.glob(os.path.join(run.directory, pattern))
                                     for pattern in ("trimmed_*.pvtu", "springback_*.pvtu"))


def trimmed_picture(run, args, report, vtk):
    """trimmed-part.png: the trimmed part (trimmed_*.pvtu, the Trimming
    subsection) coloured by the thickness change from its thickness strain,
    completed like the part, without tools."""
    files = sorted(glob.glob(os.path.join(run.directory, "trimmed_*.pvtu")))
    if not files or run.as_of is not None:
        return
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy as np
    grid = merged(read_vtu(files[-1], ("thickness_strain",)), vtk)
    strain = vtk_to_numpy(grid.GetPointData().GetArray("thickness_strain"))
    change = numpy_to_vtk(100 * (1 - np.exp(strain)), deep=1)
    change.SetName("thinning_percent")
    grid.GetPointData().AddArray(change)
    section = copy.copy(run)
    section.revolved = None  # the revolved copy is the untrimmed part's
    scene = (revolved_scene(section, grid, None, None, vtk) if run.axisymmetric
             else extruded_scene(section, grid, None, None, vtk) if run.plane_strain
             else mirrored_scene(section, grid, None, None, args.view, vtk))
    window = PartWindow(scene, ["trimmed; view: " + args.view], args.view, run.section, vtk)
    window.draw("thinning_percent", "thickness change (%)\nthinning +\nthickening −", args.range,
                os.path.join(report, "trimmed-part.png"))
    timing.lap("render", "trimmed-part.png")


def springback_picture(run, args, report, vtk):
    """springback-part.png: the sprung part (springback_*.pvtu, Springback/
    Enabled) coloured by the springback displacement, completed like the
    part (the section swept, the symmetric model mirrored), without tools."""
    files = sorted(glob.glob(os.path.join(run.directory, "springback_*.pvtu")))
    if not files or run.as_of is not None:
        return
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy as np
    grid = merged(read_vtu(files[-1], ("springback_displacement",)), vtk)
    u = vtk_to_numpy(grid.GetPointData().GetArray("springback_displacement"))
    magnitude = numpy_to_vtk(np.linalg.norm(u, axis=1), deep=1)
    magnitude.SetName("springback_mm")
    grid.GetPointData().AddArray(magnitude)
    section = copy.copy(run)
    section.revolved = None  # the revolved copy is the forming's, not the sprung part
    scene = (revolved_scene(section, grid, None, None, vtk) if run.axisymmetric
             else extruded_scene(section, grid, None, None, vtk) if run.plane_strain
             else mirrored_scene(section, grid, None, None, args.view, vtk))
    window = PartWindow(scene, ["after the release; view: " + args.view], args.view, run.section, vtk)
    window.draw("springback_mm", "springback\ndisplacement\n(mm)", None,
                os.path.join(report, "springback-part.png"))
    timing.lap("render", "springback-part.png")
