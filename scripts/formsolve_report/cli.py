"""The command line of formsolve-report and the order of the work: read
the run, start the VTK subprocess, make the plots meanwhile, write the
page. The internal --render call is the VTK subprocess (render.py)."""
import argparse
import importlib.util
import os
import sys

from . import timing
from .outcome import outcome
from .page import write_report
from .pictures import clear_pictures, pictures_of
from .readers import fail
from .render import Rendering, part_outputs, render_pictures
from .rundata import Run
from .split import split_column, split_event
from .tables import key_rows, solver_rows, zone_check

VIEWS = ("iso", "section", "top", "side")


class Parser(argparse.ArgumentParser):
    """A wrong command line: one line saying what is wrong, exit status 2."""

    def error(self, message):
        print(f"formsolve-report: {message} (formsolve-report --help)", file=sys.stderr)
        sys.exit(2)


def parse_args(argv):
    p = Parser(prog="formsolve-report",
               description="The run report of a formsolve output folder: DIR/report/report.md, "
                           "report.html and the pictures.",
               epilog="formsolve runs it at the end of every run with Output/Report = true.")
    p.add_argument("directory", metavar="DIR", help="the run's output folder (Output/Output directory)")
    p.add_argument("--view", choices=VIEWS, default="iso",
                   help="camera of the rendered pictures: iso (default; axisymmetric: into the open "
                        "quarter from above; 3-D: the critical area from outside), section (level, into "
                        "the open quarter: the wall's section; a 3-D quarter model is shown as three "
                        "quarters), top, side (the section face-on)")
    p.add_argument("--range", nargs=2, type=float, metavar=("MIN", "MAX"),
                   help="colour range of thickness-change.png in %% (default: the data's, rounded)")
    p.add_argument("--no-tools", action="store_true", help="leave the tools out of the rendered pictures")
    p.add_argument("--travel", type=float, metavar="T",
                   help="the report as of punch travel T mm: history rows up to T, the part at the last "
                        "VTU output at or before T; written to DIR/report-<T>mm/")
    p.add_argument("--output", metavar="DIR2", help="write the report to DIR2 instead")
    p.add_argument("--render", action="store_true", help=argparse.SUPPRESS)  # the VTK subprocess
    args = p.parse_args(argv)
    if args.range and not args.range[0] < args.range[1]:
        p.error(f"--range {args.range[0]:g} {args.range[1]:g}: MIN must be below MAX")
    if args.travel is not None and args.travel < 0:
        p.error("--travel must be 0 or more (mm)")
    return args


def report_directory(args):
    if args.output:
        return args.output
    name = "report" if args.travel is None else f"report-{args.travel:g}mm"
    return os.path.join(args.directory, name)


def pyplot():
    """matplotlib.pyplot on the Agg backend: files only, no display."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        fail("python3-matplotlib is missing (apt-get install python3-matplotlib): no report")
    return plt


def main(argv, launcher=None):
    """The report of argv's folder. launcher: the formsolve-report script
    that started this (default sys.argv[0]); the --render subprocess runs
    it again, so that it finds this same package."""
    args = parse_args(argv)
    args.launcher = os.path.abspath(launcher or sys.argv[0])
    report = report_directory(args)
    timing.lap("render" if args.render else "report", "the report's modules")
    if args.render:
        render_pictures(args, report)
        return
    run = Run(args)
    if importlib.util.find_spec("matplotlib") is None:  # before the subprocess is started
        fail("python3-matplotlib is missing (apt-get install python3-matplotlib): no report")
    os.makedirs(report, exist_ok=True)
    clear_pictures(report)
    # The VTK subprocess first: it renders while this process makes the plots.
    rendering = Rendering(args, report) if run.vtu is not None or part_outputs(run) else None
    timing.lap("report", "read the run, start the rendering")
    plt = pyplot()
    timing.lap("report", "import matplotlib")
    split = split_event(run)
    at_split = split_column(run, split)
    pictures, checks, notes = pictures_of(run, args, report, split, at_split, plt, rendering)
    zone_check(run, notes)
    heading, text = outcome(run, split)
    write_report(report, os.path.abspath(run.directory), heading, text, key_rows(run, split, at_split),
                 pictures, solver_rows(run), checks, notes)
    timing.lap("report", "tables, report.md and report.html")
    for n in notes:
        print("formsolve-report: " + n, file=sys.stderr)
    print(os.path.join(report, "report.md"))
