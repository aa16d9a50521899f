"""Which pictures the report has, in its order, with their headings and
captions: each made by plots.py or render.py, a failure of one named in
the report instead of costing the rest."""
import os
import traceback

from .history import IRONING_WINDOW
from .plots import damage_plot, fld_plot, force_plot, rim_plot, thickness_plot
from .render import render

PICTURES = ("force-travel.png", "thickness-change.png", "thickness.png", "fld.png", "damage.png",
            "earing.png", "draw-in.png", "penetration.png")


def attempt(notes, what, make):
    """make(); a failure is named in the report (and its traceback on
    stderr) instead of costing the rest of it."""
    try:
        return make()
    except Exception as e:  # noqa: BLE001 - any failure of one picture
        traceback.print_exc()
        notes.append(f"{what} failed: {type(e).__name__}: {e}")
        return None


def pictures_of(run, args, report, split, at_split, plt, notes):
    """The pictures, made in the report's order: [(heading, file, caption)]
    for the report, and the same for the solver checks."""
    pictures, checks = [], []
    for name in PICTURES:  # none left from an earlier report in this folder
        if os.path.exists(os.path.join(report, name)):
            os.remove(os.path.join(report, name))
    at = f" at punch travel {run.sheet_travel:.2f} mm" if run.sheet_travel is not None else ""
    dashed = " The dashed red line marks the split." if split else ""

    def add(heading, name, caption, make):
        attempt(notes, name, lambda: make(os.path.join(report, name)))
        if os.path.exists(os.path.join(report, name)):
            pictures.append((heading, name, caption))
    if run.history:
        ironed = any(float(r.get("ironing_pressure", 0)) > 0 for r in run.history)
        add("Forces", "force-travel.png", "Punch, blank-holder and die force (full part) against the punch travel "
            "they were solved at." + dashed + (
                " Below: the mean normal pressure with which punch and die squeeze the ironed wall, each step "
                f"and a {IRONING_WINDOW}-step running mean; a pressure on the wall, not a force to compare with "
                "the punch's." if ironed else ""),
            lambda p: force_plot(run, split, p, plt))
    else:
        notes.append("no converged step: no force-travel and no damage plot")
    if run.vtu is None:
        notes.append("no VTU output at or before the report's travel: no rendered pictures")
    else:
        problem = render(args, report)
        if problem:
            notes.append(problem)
        else:
            pictures.append(("The part", "thickness-change.png",
                             f"Thickness change at punch travel {run.vtu_travel:.2f} mm, thinning positive" +
                             (", the tools faint" if run.tools and not args.no_tools else "") +
                             (". Axisymmetric: revolved with a quarter left open, its cut faces show the "
                              "section" if run.axisymmetric else "") +
                             (". The black ball marks the split column." if split else ".")))
            checks.append(("Contact penetration", "penetration.png", "Contact penetration in micrometres (a solver "
                           "check: the allowed penetration is Contact/Allowed penetration)."))
    if run.sheet:
        add("Thickness", "thickness.png", f"Thickness along the section{at}.",
            lambda p: thickness_plot(run, at_split, p, plt))
        if run.flc is None:
            notes.append("no flc.csv: no forming limit diagram")
        else:
            add("Forming limit diagram", "fld.png",
                f"Each column's mid-surface strains{at}, coloured by formsolve's zone ({run.sheet_source}); "
                "the background shows the zones' rule from flc.csv and run-summary.txt's thresholds "
                "(fracture, which needs the damage, only as points); the legend gives the columns per zone.",
                lambda p: fld_plot(run, at_split, split, p, plt))
    else:
        notes.append(f"no sheet data ({run.sheet_source}): no thickness section and no FLD")
    if run.history:
        add("Damage", "damage.png", "The fracture criteria's largest values against punch travel." + dashed,
            lambda p: damage_plot(run, split, p, plt))
    if not run.axisymmetric and run.sheet:
        made = attempt(notes, "earing/draw-in plot", lambda: rim_plot(run, report, plt))
        if made:
            pictures.append(made)
    return pictures, checks

