"""How the run ended, in sentences at the top of the report: a split
first (it decides about the part), then how the run stopped."""
import re

from .readers import reached
from .split import SPLIT_MEASURES, measures_met


def outcome(run, split):
    """(heading, sentences): a split first, then how the run ended, in words."""
    s = run.summary
    end = s.get("end_reason") or "not recorded (run-summary.txt has no end_reason)"
    text = []
    if split:
        text.append(f"**The part splits: {split['measure']} at punch travel {split['travel']:.2f} mm, "
                    f"at {split['location']}.**")
        others = [f"{w} at {t:.2f} mm, at {where}" for w, t, where in measures_met(run)
                  if w != split["measure"]]
        if others:
            text.append("Also met: " + "; ".join(others) + ".")
    if run.as_of is not None:
        return ("Split" if split else "Outcome"), text + as_of_text(run, split, end)
    failed = re.search(r"step (\d+) \(punch travel ([-0-9.eE+]+) mm\)", end)
    results = (f"results up to punch travel {run.travel:.2f} mm ({len(run.history)} converged steps)"
               if run.history else "no step converged: the results show the blank as it started")
    if failed and ("did not converge" in end or "minimum time step" in end):
        text.append(f"The solver {'then ' if split else ''}failed in step {failed.group(1)} at punch travel "
                    f"{float(failed.group(2)):.2f} mm; {results}.")
    elif failed and end.startswith("error"):
        text.append(f"The run stopped with an error in step {failed.group(1)} at punch travel "
                    f"{float(failed.group(2)):.2f} mm; {results}.")
    elif not split:
        watched = [w for k, w in SPLIT_MEASURES if k in s.get("split_measures", "").split()]
        text.append("The part does not split" + (f" (watched: {', '.join(watched)})." if watched else "."))
        others = [f"{w} at {t:.2f} mm (not a split by Split/Measures)" for w, t, _ in measures_met(run)]
        if others:
            text.append("Met: " + "; ".join(others) + ".")
    text.append(f"How the run ended: {end}.")
    return ("Split" if split else "Outcome"), text


def as_of_text(run, split, end):
    """A report at --travel: what it shows, a split still to come, and how
    the whole run went on and ended (so that it is not read as the end)."""
    s, text = run.summary, []
    text.append(f"This report is as of punch travel {run.as_of:g} mm (history.csv up to "
                f"{run.travel:.2f} mm; the part and the FLD at the output of "
                f"{run.sheet_travel if run.sheet_travel is not None else float('nan'):.2f} mm).")
    later = reached(s, "split_travel") if s.get("split") == "yes" else None
    if not split and later is not None:
        text.append(f"The part has not split yet: it splits at {later:.2f} mm "
                    f"({s.get('split_measure')}, at {s.get('split_location')}).")
    text.append(f"The run went on to {run.final_travel:.2f} mm and ended: {end}.")
    return text
