"""The square cup's table in doc/tools.md: one column per run folder (each
with its log beside it as <folder>.log), rows as in section 2 there.
    /usr/bin/python3 benchmarks/square_cup_table.py NAME=RUN_DIR ...
The draw-in and thickness rows are read at the steps that end on
Output/Profile travels (15 and 40 mm); forces where they are solved, at the
start of a step (force_travel): at 15 mm the next step's, at 40 mm the last
step's (its travel given). Below the table: the second run against the
first over the whole draw (the second interpolated to the first's travels):
largest draw-in difference; punch force from 2 mm to the first's peak
(median and largest, with where) and at the end; then both every 5 mm from
15 mm (the mesh-convergence table of doc/tools.md)."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_tables import section, steps, summary  # noqa: E402


def minutes(seconds):
    return f"{int(seconds // 60)} min {seconds % 60:.0f} s"


def at(rows, travel):
    row = min(rows, key=lambda r: abs(float(r["punch_travel"]) - travel))
    if abs(float(row["punch_travel"]) - travel) > 1e-6:
        raise SystemExit(f"FAIL: no step ends at {travel} mm (Output/Profile travels)")
    return row


def column(run_dir):
    rows = steps(run_dir)
    s = summary(run_dir)
    log = open(run_dir.rstrip("/") + ".log").read()
    total = float(re.search(r"Total wallclock time elapsed since start +\| +([0-9.e+-]+)s", log).group(1))
    first = int(re.search(r"adapted mesh: \d+ cells, (\d+) DoFs", log).group(1))
    peak = max(rows, key=lambda r: float(r["punch_force"]))
    out = {
        f"wall time, {s['ranks']} ranks": f"{minutes(total)} ({len(rows)} steps)",
        "contact search, share of the run": f"{100 * section(log, 'contact')[1] / total:.2f} %",
        "DoFs (after adaptation)": f"{first} → {s['dofs']}",
        "Newton iterations per step (mean)": f"{int(s['newton_iterations']) / len(rows):.2f}",
    }
    for travel in (15, 40):
        r = at(rows, travel)
        out[f"draw_in_x / draw_in_y at {travel} mm"] = f"{float(r['draw_in_x']):.3f} / {float(r['draw_in_y']):.3f} mm"
        out[f"draw_in_diagonal at {travel} mm"] = f"{float(r['draw_in_diagonal']):.3f} mm"
        f = min(rows, key=lambda r: abs(float(r["force_travel"]) - travel))
        where = float(f["force_travel"])
        out[f"punch force at {travel} mm"] = f"{float(f['punch_force']) / 1000:.1f} kN" + (
            "" if abs(where - travel) < 1e-6 else f" (at {where:.2f} mm)")
    out["peak punch force"] = f"{float(peak['punch_force']) / 1000:.1f} kN at {float(peak['force_travel']):.1f} mm"
    last = rows[-1]
    out["minimum thickness at 40 mm"] = (
        f"{float(last['min_thickness']):.3f} mm ({float(last['max_thinning_percent']):.1f} %) at "
        f"x, y = {float(last['min_thickness_x']):.1f}, {float(last['min_thickness_y']):.1f} mm")
    return out


def interpolate(rows, key, travel, along="punch_travel"):
    xs = [float(r[along]) for r in rows]
    for k in range(1, len(rows)):
        if xs[k] >= travel:
            w = (travel - xs[k - 1]) / (xs[k] - xs[k - 1])
            return (1 - w) * float(rows[k - 1][key]) + w * float(rows[k][key])
    return float(rows[-1][key])


def compare(first, second):
    a, b = steps(first), steps(second)
    draw_in = max(abs(float(r[k]) - interpolate(b, k, float(r["punch_travel"])))
                  for r in a for k in ("draw_in_x", "draw_in_y", "draw_in_diagonal"))
    peak = max(float(r["punch_force"]) for r in a)
    upto = next(float(r["force_travel"]) for r in a if float(r["punch_force"]) == peak)

    def force(r):
        other = interpolate(b, "punch_force", float(r["force_travel"]), "force_travel")
        return abs(other / float(r["punch_force"]) - 1)
    before = sorted((force(r), float(r["force_travel"])) for r in a
                    if 2 <= float(r["force_travel"]) <= upto)
    median = before[len(before) // 2][0]
    print(f"\nsecond against first: draw-in within {draw_in:.3f} mm over the draw; punch force from 2 mm "
          f"to the peak ({upto:.1f} mm): median {100 * median:.2f} %, largest {100 * before[-1][0]:.2f} % "
          f"at {before[-1][1]:.2f} mm; {100 * force(a[-1]):.2f} % at the end")


def by_travel(first, second):
    """The second run against the first every 5 mm from 15 mm: draw-in on the
    x axis and the diagonal, punch force and minimum thickness (both runs
    interpolated to the travel)."""
    a, b = steps(first), steps(second)
    end = min(float(a[-1]["punch_travel"]), float(b[-1]["punch_travel"]))
    print("\n| travel | draw_in_x, first / second | draw_in_diagonal, first / second "
          "| punch force | minimum thickness |")
    print("|---|---|---|---|---|")
    travel = 15.
    while travel <= end + 1e-9:
        cells = []
        for key in ("draw_in_x", "draw_in_diagonal"):
            x, y = interpolate(a, key, travel), interpolate(b, key, travel)
            cells.append(f"{x:.3f} / {y:.3f} ({y - x:+.3f}) mm")
        fa = interpolate(a, "punch_force", travel, "force_travel")
        fb = interpolate(b, "punch_force", travel, "force_travel")
        cells.append(f"{100 * (fb / fa - 1):+.1f} %")
        ta, tb = (interpolate(r, "min_thickness", travel) for r in (a, b))
        cells.append(f"{ta:.3f} / {tb:.3f} mm")
        print(f"| {travel:.0f} mm | " + " | ".join(cells) + " |")
        travel += 5


def main():
    names, cols = [], []
    for arg in sys.argv[1:]:
        name, run_dir = arg.split("=", 1)
        names.append(name)
        cols.append(column(run_dir))
    print("| | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 1) + "|")
    for key in cols[0]:
        print(f"| {key} | " + " | ".join(c[key] for c in cols) + " |")
    if len(names) > 1:
        compare(sys.argv[1].split("=", 1)[1], sys.argv[2].split("=", 1)[1])
        by_travel(sys.argv[1].split("=", 1)[1], sys.argv[2].split("=", 1)[1])


main()
