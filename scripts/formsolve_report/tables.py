"""The report's two tables, (quantity, value) in words: the key numbers of
the formed part and the solver checks. No -1 sentinels of run-summary.txt
reach them: a travel never reached is said in words."""
import math

from .history import IRONING_WINDOW, drawn_through, peak_force, running_mean
from .readers import column, number, reached
from .split import SPLIT_MEASURES
from .zones import ZONES


def mm(x, digits=2):
    return f"{x:.{digits}f} mm"


def coordinate_names(model):
    """r, z in the axisymmetric section; x, z in the plane-strain one; x, y, z."""
    return {"axisymmetric": ("r", "z"), "plane strain": ("x", "z")}.get(model, ("x", "y", "z"))


def coordinates(values, model):
    """Coordinates with their names (coordinate_names)."""
    return ", ".join(f"{n} = {v:.2f} mm" for n, v in zip(coordinate_names(model), values))


def planform_label(model):
    """The name of a column's planform position: its distance X0 from the
    plane of symmetry in plane strain, else its radius R0."""
    return "X0" if model == "plane strain" else "R0"


def summary_value(summary, key, fmt="{:.2f}"):
    """A run-summary number as text; "?" when absent."""
    v = number(summary, key)
    return "?" if v is None else fmt.format(v)


def key_rows(run, split, column_at_split):
    """The key table: (quantity, value) in words, no -1 sentinels."""
    s, model = run.summary, run.model
    rows = run_rows(run, split)
    rows += part_rows(run)
    counts = run.zone_counts()
    if run.sheet:
        rows.append(("FLD zones (columns)", ", ".join(f"{n} {c}" for (n, _), c in zip(ZONES, counts))))
    if column_at_split:
        c = column_at_split
        rows.append((f"the split column{' at the end' if run.as_of is None else ''}",
                     f"{planform_label(model)} = {c['reference_radius']:.2f} mm" +
                     (f", {c['reference_angle']:.1f} degrees from x" if not run.section else "") +
                     (f", now at {coordinates((c['r'], c['z']), model)}" if run.section else
                      f", now at {coordinates((c['r'], c['z']), 'axisymmetric')} (r: from the axis)") + "; "
                     f"major strain {c['major_strain']:.3f}, minor {c['minor_strain']:.3f}: {ZONES[c['zone']][0]}"))
    flc0, source = run.flc0(), s.get("forming_limit", "?")
    if flc0 is not None and "(true strain" not in source:  # the source quotes it in engineering strain
        source += f"; FLC0 = {flc0:.3f} (true strain, {run.flc0_source()})"
    rows.append(("forming limit curve", source))
    rows += fracture_rows(run, model)
    release = reached(s, "holder_release_travel", run.as_of)
    rows.append(("blank holder", "not released" if release is None else f"released at punch travel {mm(release)}"))
    rows.append(("ironing (wall squeezed between punch and die)", ironing_text(run)))
    if not run.section and run.as_of is None and "ears" in s and drawn_through(run):
        rows.append(("earing", f"{s['ears']} ears, amplitude {summary_value(s, 'earing_amplitude')} mm "
                     f"around a mean cup height of {summary_value(s, 'cup_height_mean')} mm"))
    warnings = [s.get(f"warning_{k}", "?") for k in range(1, int(number(s, "warnings") or 0) + 1)]
    if warnings:
        rows.append(("warnings", "; ".join(warnings)))
    return rows


def run_rows(run, split):
    """The model, the split and each split measure, the end of the run."""
    s = run.summary
    dofs = number(s, "dofs")
    rows = [("model", f"{run.model} ({s.get('ranks', '?')} rank(s)" +
             (f", {dofs:.0f} DoFs)" if dofs else ")"))]
    if s.get("start_from"):
        rows.append(("next operation", f"the part of {s['start_from']} ({s.get('start_from_shape', '?')}); "
                     "strains, thickness and damage include the earlier operation's"))
    if split:
        rows.append(("split", f"yes: {split['measure']} at punch travel {mm(split['travel'])}, at {split['location']}"))
    else:
        rows.append(("split", "no" if run.as_of is None else f"not by {run.as_of:g} mm"))
    for key, words in SPLIT_MEASURES:
        if key in s.get("split_measures", "").split() or reached(s, key + "_travel") is not None:
            t = reached(s, key + "_travel", run.as_of)
            rows.append((f"split measure: {words}", "not reached" if t is None else
                         f"at punch travel {mm(t)}, at {s.get(key + '_location', '?')}"))
    rows.append(("end of run", s.get("end_reason", "?")))
    return rows


def part_rows(run):
    """The formed part from history.csv's last row: force, thickness, height, margin."""
    h = run.history
    if not h:
        return [("formed part", "none: no step converged (the values below are the blank's)")]
    last = h[-1]
    at_end = "at the end of the run" if run.as_of is None else f"at {run.as_of:g} mm"
    peak, at, rising, final = peak_force(run)
    return [
        ("peak punch force", f"{peak:.0f} N at {at:.2f} mm" +
         (f": still rising {at_end} (no maximum reached)" if rising else
          f" (then {final:.0f} N {at_end}, {100 * (final / peak - 1):+.1f} %)")),
        ("minimum thickness", min_thickness(last, run.model)),
        ("largest thickening", f"{float(last['max_thickening_percent']):.1f} %"),
        ("part height" if run.plane_strain else "cup height", f"{float(last['cup_height']):.2f} mm"),
        ("margin to the forming limit", f"{float(last['flc_margin_percent']):.1f} % "
         "(100 (1 − largest major strain / the FLC's at its minor strain); negative: past the curve)")]


def min_thickness(row, model):
    names = coordinate_names(model)
    at = [float(row.get(f"min_thickness_{n}", "nan")) for n in names]
    where = coordinates(at, model)
    if len(names) == 3:
        where += f" ({math.degrees(math.atan2(at[1], at[0])):.1f} degrees from x)"
    return (f"{float(row['min_thickness']):.4f} mm (thinning {float(row['max_thinning_percent']):.1f} %) "
            f"at {planform_label(model)} = {float(row['min_thickness_R0']):.2f} mm, now at {where}")


def fracture_rows(run, model):
    s = run.summary
    criterion = s.get("fracture_criterion", "?")
    if criterion == "none":
        return [("fracture criterion", "none chosen (Material/Fracture criterion = none): no critical stroke")]

    def where(key):
        try:
            return coordinates([float(v) for v in s.get(key, "").split()], model)
        except ValueError:
            return s.get(key, "?")
    critical = reached(s, "critical_stroke", run.as_of)
    rows = [("critical stroke", f"{mm(critical, 3)} ({criterion}, {s.get('fracture_measure', '?')}; at "
             f"{where('fracture_location')})" if critical is not None else
             f"not reached: no fracture predicted ({criterion}, {s.get('fracture_measure', '?')})")]
    each = []
    for key, words in (("through_thickness", "through-thickness average"), ("local", "local maximum")):
        t = reached(s, "critical_stroke_" + key, run.as_of)
        each.append(f"{words} " + ("not reached" if t is None else mm(t, 3)))
    rows.append(("critical stroke by each measure", ", ".join(each) + f" ({s.get('fracture_measure', '?')} decides)"))
    return rows


def ironing_text(run):
    s = run.summary
    start = reached(s, "ironing_travel", run.as_of)
    if start is None or not run.history or "ironing_pressure" not in run.history[0]:
        return "none"
    pressure = column(run.history, "ironing_pressure")
    if max(pressure) <= 0:
        return f"from punch travel {mm(start)}, with no wall pressure recorded (history.csv: ironing_pressure)"
    mean = [m for m in running_mean(pressure, IRONING_WINDOW) if not math.isnan(m)]
    return (f"from punch travel {mm(start)}: wall pressure at most {max(pressure):.0f} MPa in a step, "
            f"{max(mean):.0f} MPa as a {IRONING_WINDOW}-step running mean (the mean normal pressure on the "
            "ironed wall: the smaller of the punch's and the die's wall force per contact area)")


def solver_rows(run):
    s, rows = run.summary, run.solver
    pen = column(rows, "max_penetration") if rows else []
    newton = sum(int(r["newton_iterations"]) for r in rows)
    cuts = sum(int(r["cutbacks"]) for r in rows)
    steps = f"{len(rows)}, {newton}, {cuts}"
    if run.as_of is None:
        extra_n = int(number(s, "newton_iterations") or newton) - newton
        extra_c = int(number(s, "cutbacks") or cuts) - cuts
        if extra_n > 0 or extra_c > 0:
            steps += f" (and {extra_n} iterations, {extra_c} cuts in the step that failed)"
    volume = column(rows, "volume") if rows and "volume" in rows[0] else []
    wall = float(rows[-1]["wall_time"]) if run.as_of is not None and rows else number(s, "wall_time")
    return [
        ("max penetration over the run", f"{max(pen):.3g} mm" if pen else "none: no step converged"),
        ("steps, Newton iterations, time-step cuts", steps),
        ("volume change over the run", f"{100 * (volume[-1] / volume[0] - 1):+.3f} % (from the first step)"
         if len(volume) > 1 else "not measured: fewer than two steps"),
        ("wall time", f"{wall:.1f} s" if wall is not None else "?"),
    ]


def zone_check(run, notes):
    """The report's zone counts are the sheet's; say so if the program's
    own counts for the same sheet differ."""
    source, expected = run.expected_zone_counts()
    got = run.zone_counts()
    if run.sheet and expected is not None and expected != got:
        notes.append(f"the zone counts of {run.sheet_source} ({got}) differ from {source}'s ({expected})")
