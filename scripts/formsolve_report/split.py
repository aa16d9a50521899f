"""The split as run-summary.txt records it: which measure, at what punch
travel, where (in words and as the column's planform position), and which
of the split measures were met by the report's travel."""
import math
import re

from .readers import number, reached

SPLIT_MEASURES = [("forming_limit", "forming limit"), ("neck", "neck"),
                  ("fracture_criterion", "fracture criterion")]


def split_event(run):
    """The split, if it happened by the report's travel: measure, travel,
    location, and the column's planform position (R0, angle) to find it in
    sheet.csv and the VTU."""
    s = run.summary
    travel = reached(s, "split_travel", run.as_of) if s.get("split") == "yes" else None
    if travel is None:
        return None
    where = s.get("split_location", "")
    r0, angle = split_position(s, where)
    return {"measure": s.get("split_measure", "?"), "travel": travel, "location": where,
            "R0": r0, "angle": angle}


def split_position(summary, where):
    """(R0 mm or None, degrees from x): run-summary.txt's split_R0 and
    split_angle; older folders have only the location text, parsed then."""
    def finite(key):
        value = number(summary, key)
        return value if value is not None and math.isfinite(value) else None
    r0 = finite("split_R0")
    if r0 is not None:
        angle = finite("split_angle")
        return r0, 0.0 if angle is None else angle
    m = re.search(r"R0 = ([-0-9.eE+]+) mm(?:, ([-0-9.eE+]+) degrees from x)?", where)
    return (float(m.group(1)) if m else None), (float(m.group(2)) if m and m.group(2) else 0.0)


def split_column(run, split):
    """The sheet.csv row nearest the split's planform position."""
    if not split or split["R0"] is None or not run.sheet:
        return None
    a = math.radians(split["angle"])
    target = (split["R0"] * math.cos(a), split["R0"] * math.sin(a))

    def planform(r):
        b = math.radians(r["reference_angle"])
        return (r["reference_radius"] * math.cos(b), r["reference_radius"] * math.sin(b))
    return min(run.sheet, key=lambda r: math.dist(planform(r), target))


def measures_met(run):
    """[(words, travel, location)] of each split measure met by the report's travel."""
    out = []
    for key, words in SPLIT_MEASURES:
        t = reached(run.summary, key + "_travel", run.as_of)
        if t is not None:
            out.append((words, t, run.summary.get(key + "_location", "")))
    return out
