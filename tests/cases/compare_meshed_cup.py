"""The cup drawn 5 mm (quarter, or axisymmetric with r-z profiles) with
meshed copies of its analytic tools (check_meshed_case.sh): the punch force
of the meshed tools at facets of 2, 1
and 0.5 mm against the analytic tools' at every step from 2 mm of travel on
(once the sheet wraps the nose): within LIMIT % at 0.5 mm (about 3x what
was measured: 0.005 % for the quarter cup's surfaces, 0.064 % for the
axisymmetric cup's r-z profiles, `ctest -R "meshed_cup|profile_cup" -V`),
the deviation falling with the facet size, and the penetration within the
allowed 1e-3 mm (adaptive-strict) with every tool set.
Usage: compare_meshed_cup.py OUTDIR LIMIT"""
import os
import sys

import results

out, limit = sys.argv[1], float(sys.argv[2])
analytic = results.read(os.path.join(out, "analytic"))
failures = 0


def check(what, ok):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok


deviation = {}
for size in ["2", "1", "0.5"]:
    rows = results.read(os.path.join(out, "meshed-" + size))
    check(f"{size} mm: as many steps", len(rows) == len(analytic))
    worst = 0
    for a, m in zip(analytic, rows):
        if float(a["punch_travel"]) >= 2:
            fa, fm = float(a["punch_force"]), float(m["punch_force"])
            worst = max(worst, abs(fm - fa) / fa)
    pen = max(float(m["max_penetration"]) for m in rows)
    deviation[size] = worst
    print(f"facets {size} mm: punch force off by at most {100 * worst:.3f} %, "
          f"largest penetration {pen:.3e} mm")
    check(f"{size} mm: penetration within 1e-3 mm (2 % tolerance)", pen <= 1.02e-3)
check(f"0.5 mm: punch force within {limit:g} %", deviation["0.5"] <= limit / 100)
check("deviation falls from 2 to 1 mm", deviation["1"] < deviation["2"])
check("deviation falls from 1 to 0.5 mm", deviation["0.5"] < deviation["1"])
sys.exit(1 if failures else 0)
