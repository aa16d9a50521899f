"""Quantities of history.csv that both the key table and the plots show,
computed once here so that the two always agree."""
from .readers import column

IRONING_WINDOW = 5  # steps in the running mean of the wall pressure


def peak_force(run):
    """The punch force (full part): (peak N, its travel mm, whether the peak
    is the last row, i.e. the force still rises, the last row's N)."""
    key = "punch_force" if run.history and "punch_force" in run.history[0] else "force_punch"
    force = column(run.history, key)
    travel = column(run.history, "force_travel")
    k = max(range(len(force)), key=lambda i: force[i])
    return force[k], travel[k], k == len(force) - 1, force[-1]


def running_mean(values, window):
    """Centred running mean over `window` steps, the zeros of steps where
    the wall lost contact included (they smooth the flicker); NaN outside
    the first and last non-zero step, so that it never starts early."""
    half = window // 2
    hits = [i for i, v in enumerate(values) if v > 0]
    out = []
    for i in range(len(values)):
        part = values[max(0, i - half):i + half + 1]
        out.append(sum(part) / len(part) if hits and hits[0] <= i <= hits[-1] else float("nan"))
    return out


def drawn_through(run):
    """Earing is measured only once the cup is drawn through (before, the
    rim's shape is the flange's draw-in)."""
    return run.summary.get("end_reason", "").startswith("drawn through")
