"""A next operation against the same draw in one run (check_start_from.sh).

check_start_from.py ONE SECOND TRAVEL [STEPS TOLERANCE]: the second run
(started from the first's end, TRAVEL mm in) takes the steps the one run
takes from TRAVEL on (STEPS of them, 10 by default): its punch force,
strain, thickness, damage and holder position at each step are the one
run's at the same total travel within TOLERANCE (1e-4 by default), and its
sheet.csv at the end is the one run's.

check_start_from.py --sprung FIRST SECOND: the second run's first output
(step 0) is the first run's sprung part, point by point.
"""
import csv
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results  # noqa: E402

# Each step is converged to the Newton tolerance; the two runs start their
# steps from different guesses (the second from rest), so they agree to
# that tolerance and not to the last digit. A part that lost its strain or
# damage on the way would differ by percent (the flow stress at the first
# run's strain is 1.6 times the initial one).
TOLERANCE = 1e-4


def relative(a, b, scale):
    return abs(a - b) / max(abs(scale), 1e-30)


def continuity(one_dir, second_dir, travel, steps=10, tolerance=TOLERANCE):
    one = numbers(results.read(one_dir))
    second = numbers(results.read(second_dir))
    by_travel = {round(r["punch_travel"], 9): r for r in one}
    worst = {}
    for r in second:
        o = by_travel.get(round(r["punch_travel"] + travel, 9))
        if o is None:
            sys.exit(f"FAIL: the one run has no step at punch travel "
                     f"{r['punch_travel'] + travel} mm")
        pairs = {
            "punch_force": (r["punch_force"], o["punch_force"],
                            o["punch_force"]),
            "max_equivalent_strain": (r["max_equivalent_strain"],
                                      o["max_equivalent_strain"],
                                      o["max_equivalent_strain"]),
            "min_thickness": (r["min_thickness"], o["min_thickness"],
                              o["min_thickness"]),
            "max_oyane": (r["max_oyane"], o["max_oyane"], o["max_oyane"]),
            # The holder's own displacement: from where the first run left it.
            "holder_position": (r["holder_displacement"]
                                + one_holder_at(one, travel),
                                o["holder_displacement"], 0.78),
        }
        for k, (a, b, s) in pairs.items():
            worst[k] = max(worst.get(k, 0), relative(a, b, s))
    if len(second) != steps:
        sys.exit(f"FAIL: the second run took {len(second)} steps, not {steps}")
    for k, w in worst.items():
        print(f"{k}: largest relative difference {w:.2e}")
        if w > tolerance:
            sys.exit(f"FAIL: {k} differs from the one run by {w:.2e} "
                     f"(bound {tolerance})")
    a = list(csv.DictReader(open(os.path.join(one_dir, "sheet.csv"))))
    b = list(csv.DictReader(open(os.path.join(second_dir, "sheet.csv"))))
    if len(a) != len(b):
        sys.exit("FAIL: sheet.csv has other columns than the one run's")
    for key in ("thickness", "equivalent_strain"):
        if key not in a[0]:
            continue
        d = max(relative(float(x[key]), float(y[key]), float(x[key]))
                for x, y in zip(a, b))
        print(f"sheet.csv {key}: largest relative difference {d:.2e}")
        if d > tolerance:
            sys.exit(f"FAIL: sheet.csv {key} differs by {d:.2e}")
    print("ok: the second operation continues the one run")


def numbers(rows):
    out = []
    for r in rows:
        row = {}
        for k, v in r.items():
            try:
                row[k] = float(v)
            except (TypeError, ValueError):
                row[k] = v
        out.append(row)
    return out


def one_holder_at(rows, travel):
    for r in rows:
        if abs(r["punch_travel"] - travel) < 1e-9:
            return r["holder_displacement"]
    sys.exit(f"FAIL: the one run has no step at {travel} mm")


def points(pattern):
    import vtk
    files = sorted(glob.glob(pattern))
    if not files:
        sys.exit(f"FAIL: no {pattern}")
    r = vtk.vtkXMLPUnstructuredGridReader()
    r.SetFileName(files[-1])
    r.Update()
    p = r.GetOutput().GetPoints()
    return np.array([p.GetPoint(i) for i in range(p.GetNumberOfPoints())])


def sprung(first_dir, second_dir):
    released = points(os.path.join(first_dir, "springback_*.pvtu"))
    start = points(os.path.join(second_dir, "solution_00000.pvtu"))
    formed = points(os.path.join(first_dir, "solution_*.pvtu"))
    nearest = max(np.min(np.linalg.norm(released - x, axis=1)) for x in start)
    moved = max(np.min(np.linalg.norm(formed - x, axis=1)) for x in start)
    print(f"the second run's start lies {nearest:.2e} mm from the sprung "
          f"part's points, {moved:.2e} mm from the formed part's")
    if nearest > 1e-8:
        sys.exit("FAIL: the second run does not start from the sprung part")
    if moved < 1e-4:
        sys.exit("FAIL: the sprung part is the formed part: no springback "
                 "to tell them apart")


if __name__ == "__main__":
    if sys.argv[1] == "--sprung":
        sprung(sys.argv[2], sys.argv[3])
    else:
        continuity(sys.argv[1], sys.argv[2], float(sys.argv[3]),
                   *([int(sys.argv[4]), float(sys.argv[5])] if len(sys.argv) > 5 else []))
