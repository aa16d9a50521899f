"""Which pictures the report has, in its order, with their headings and
captions: each made by plots.py or rendered by the --render subprocess
(render.py), a failure of one named in the report instead of costing the
rest. The rendered ones are collected last, the plots made meanwhile."""
import os
import traceback

from . import timing
from .history import IRONING_WINDOW
from .plots import damage_plot, fld_plot, force_plot, rim_plot, thickness_plot
from .springback import springback_plot

PICTURES = ("force-travel.png", "thickness-change.png", "thickness.png", "fld.png", "damage.png",
            "earing.png", "draw-in.png", "penetration.png", "springback.png", "springback-part.png",
            "trimmed-part.png")


def clear_pictures(report):
    """None left from an earlier report in this folder: done before the
    --render subprocess starts writing its own."""
    for name in PICTURES:
        if os.path.exists(os.path.join(report, name)):
            os.remove(os.path.join(report, name))


def attempt(notes, what, make):
    """make(); a failure is named in the report (and its traceback on
    stderr) instead of costing the rest of it."""
    try:
        return make()
    except Exception as e:  # noqa: BLE001 - any failure of one picture
        traceback.print_exc()
        notes.append(f"{what} failed: {type(e).__name__}: {e}")
        return None


class Section:
    """One part of the report's pictures: its pictures and solver checks as
    (heading, file, caption), and its notes, in the report's order."""

    def __init__(self, report):
        self.report, self.pictures, self.checks, self.notes = report, [], [], []

    def add(self, heading, name, caption, make):
        """make(path) a plot; listed if its file was written."""
        attempt(self.notes, name, lambda: make(os.path.join(self.report, name)))
        timing.lap("report", name)
        if os.path.exists(os.path.join(self.report, name)):
            self.pictures.append((heading, name, caption))


def pictures_of(run, args, report, split, at_split, plt, rendering):
    """The pictures in the report's order: [(heading, file, caption)] for
    the report, the same for the solver checks, and the notes. rendering:
    the --render subprocess (render.Rendering), None without VTU output."""
    force, part, sheet, damage, rim = (Section(report) for _ in range(5))
    force_plots(run, split, force, plt)
    sheet_plots(run, split, at_split, sheet, plt)
    damage_plots(run, split, damage, plt)
    rim_plots(run, rim, plt)
    springback_plots(run, rim, plt)
    rendered(run, args, split, rendering, part)  # last: the subprocess has run beside the plots
    sections = (force, part, sheet, damage, rim)
    return ([p for s in sections for p in s.pictures], [c for s in sections for c in s.checks],
            [n for s in sections for n in s.notes])


def springback_plots(run, section, plt):
    """The section's springback (Springback/Enabled, 2-D models)."""
    if run.as_of is not None or not os.path.exists(os.path.join(run.directory, "springback-profile.csv")):
        return
    section.add("Springback", "springback.png", "The sheet's mid-surface at the end of forming (grey) and after "
                "the release (dots, coloured by the springback displacement; held by "
                f"{run.summary.get('springback_supports', '?')}), and the displacement along the section "
                "(springback-profile.csv, springback_*.pvtu).", lambda p: springback_plot(run, p, plt))


def force_plots(run, split, section, plt):
    if not run.history:
        section.notes.append("no converged step: no force-travel and no damage plot")
        return
    ironed = any(float(r.get("ironing_pressure", 0)) > 0 for r in run.history)
    dashed = " The dashed red line marks the split." if split else ""
    section.add("Forces", "force-travel.png", "Punch, blank-holder and die force (full part) against the punch "
                "travel they were solved at." + dashed + (
                    " Below: the mean normal pressure with which punch and die squeeze the ironed wall, each "
                    f"step and a {IRONING_WINDOW}-step running mean; a pressure on the wall, not a force to "
                    "compare with the punch's." if ironed else ""),
                lambda p: force_plot(run, split, p, plt))


def rendered(run, args, split, rendering, section):
    """The part and the penetration, once the --render subprocess is done."""
    if rendering is None:
        section.notes.append("no VTU output at or before the report's travel: no rendered pictures")
        return
    problem = rendering.wait()
    timing.lap("report", "wait for the rendered pictures")
    if problem:
        section.notes.append(problem)
        return
    if run.vtu is None:
        section.notes.append("no VTU output of the forming at or before the report's travel: only the "
                             "trimmed or sprung part is rendered")
    else:
        part_picture(run, args, split, section)
    part_after_pictures(run, section)


def part_picture(run, args, split, section):
    """The formed part and the penetration (rendered by the --render subprocess)."""
    section.pictures.append(("The part", "thickness-change.png",
                             f"Thickness change at punch travel {run.vtu_travel:.2f} mm, thinning positive" +
                             (", the tools faint" if run.tools and not args.no_tools else "") +
                             (". Axisymmetric: revolved with a quarter left open, its cut faces show the "
                              "section" if run.axisymmetric else "") +
                             (". Plane strain: the section mirrored at x = 0 and swept over the width it "
                              "stands for; its end faces show the section" if run.plane_strain else "") +
                             (". The black ball marks the split column."
                              if split and split["R0"] is not None else ".")))
    section.checks.append(("Contact penetration", "penetration.png", "Contact penetration in micrometres (a "
                           "solver check: the allowed penetration is Contact/Allowed penetration)."))


def part_after_pictures(run, section):
    """The trimmed and the sprung part, where the run wrote them."""
    if os.path.exists(os.path.join(section.report, "trimmed-part.png")):
        section.pictures.append(("The trimmed part", "trimmed-part.png",
                                 "The part after the Trimming subsection's cuts (trimmed_*.pvtu), its thickness "
                                 "change from the thickness strain, thinning positive; the outline is "
                                 "trim-outline.csv."))
    if os.path.exists(os.path.join(section.report, "springback-part.png")):
        section.pictures.append(("The part after springback", "springback-part.png",
                                 "The part taken out of the tools and released (springback_*.pvtu), coloured "
                                 "by the springback displacement; held by "
                                 f"{run.summary.get('springback_supports', '?')}."))


def sheet_plots(run, split, at_split, section, plt):
    if not run.sheet:
        section.notes.append(f"no sheet data ({run.sheet_source}): no thickness section and no FLD")
        return
    at = f" at punch travel {run.sheet_travel:.2f} mm" if run.sheet_travel is not None else ""
    section.add("Thickness", "thickness.png", f"Thickness along the section{at}.",
                lambda p: thickness_plot(run, at_split, p, plt))
    if run.flc is None:
        section.notes.append("no flc.csv: no forming limit diagram")
        return
    section.add("Forming limit diagram", "fld.png",
                f"Each column's mid-surface strains{at}, coloured by formsolve's zone ({run.sheet_source}); "
                "the background shows the zones' rule from flc.csv and run-summary.txt's thresholds "
                "(fracture, which needs the damage, only as points); the legend gives the columns per zone.",
                lambda p: fld_plot(run, at_split, split, p, plt))


def damage_plots(run, split, section, plt):
    if run.history:
        dashed = " The dashed red line marks the split." if split else ""
        section.add("Damage", "damage.png", "The fracture criteria's largest values against punch travel." + dashed,
                    lambda p: damage_plot(run, split, p, plt))


def rim_plots(run, section, plt):
    """3-D: earing once drawn through, else the flange's draw-in."""
    if not run.section and run.sheet:
        made = attempt(section.notes, "earing/draw-in plot", lambda: rim_plot(run, section.report, plt))
        timing.lap("report", "earing/draw-in plot")
        if made:
            section.pictures.append(made)
