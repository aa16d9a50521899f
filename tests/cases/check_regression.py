"""history.csv and solver.csv (merged, tests/cases/results.py) against the stored reference: the physics (forces, gaps,
penetration, volume, thickness, damage, ...) tightly, per row, with the
numdiff tolerances of the suite (relative 1e-5 or absolute 1e-7); the solver
cost (Newton/linear/Picard iterations, strict passes, locked pairs,
condition estimate, wall time) only loosely, as totals: a better solver must
not break a reference, a much worse one does (more than 1.5x + 5 Newton
iterations of the reference in total).

A location column (name ending in _x or _y) also matches when the row's
(x, y) pair is the reference's mirrored about the diagonal x = y: a maximum
that ties between two mirror points of a quarter or full round blank may be
found at either, depending on round-off.

Two kinds of column are differences of nearly equal numbers, so a relative
tolerance on them would be far tighter than on what they are made of:
max_thinning_percent = 100 (1 - t_min/t0) matches within 100 RELATIVE
(percent points: t_min's own tolerance), and draw_in_<angle> = R0 - rim
within RELATIVE * rim_radius_<angle> (mm). E.g. at step 1 thinning is
0.053 %, and t_min to 1e-4 moves it by up to 0.01 percent points.

Usage: check_regression.py OUTDIR REFERENCE [RELATIVE] [--absolute KEY=VALUE,...]
                           [--no-locations]
  RELATIVE: the relative tolerance of the physics (default 1e-5), for
  solvers that converge a different way (e.g. single-precision factors).
  --absolute: columns whose name contains KEY match within VALUE (in the
  column's unit) as well, e.g. penetration=5e-5 for solves that stop at a
  Newton tolerance.
  --no-locations: the locations of maxima and minima (_x, _y, _z) are not
  compared: with nearly tied nodes they follow round-off."""
import csv
import results
import sys

options = [a for a in sys.argv[1:] if a.startswith("--")]
args = [a for a in sys.argv[1:] if not a.startswith("--")]
absolute = {}
if "--absolute" in sys.argv:
    for item in sys.argv[sys.argv.index("--absolute") + 1].split(","):
        key, value = item.split("=")
        absolute[key] = float(value)
    args.remove(sys.argv[sys.argv.index("--absolute") + 1])
no_locations = "--no-locations" in options
out, reference = args[0:2]
relative = float(args[2]) if len(args) > 2 else 1e-5
COST = {"newton_iterations", "linear_iterations", "picard_iterations",
        "strict_passes", "max_linear_iterations", "locked_pairs",
        "condition_estimate", "wall_time"}
ref = results.read(reference)
got = list(results.read(out))
failures = []
if len(ref) != len(got):
    failures.append(f"{len(got)} steps, the reference has {len(ref)}")
# The sheet's equilibrium residual along z is round-off and Newton's
# tolerance, not a number to store; check_additional_tools.py bounds it.
RESIDUALS = {"force_imbalance_z"}
for row in got + ref:
    for k in RESIDUALS:
        row.pop(k, None)
if ref and got and list(ref[0]) != list(got[0]):
    failures.append("the columns differ from the reference's")


def inherited(k, row):
    """The absolute tolerance that column k takes from the column it is a
    difference of (0 for a column that is not such a difference)."""
    if k == "max_thinning_percent":
        return 100 * relative
    if k.startswith("draw_in_") and f"rim_radius_{k[8:]}" in row:
        return relative * abs(float(row[f"rim_radius_{k[8:]}"]))
    return 0


def close(x, y, k="", row=None):
    floor = max([1e-7, inherited(k, row or {})]
                + [v for key, v in absolute.items() if key in k])
    return abs(x - y) <= max(relative * abs(x), floor)


def mirrored(a, b, k):
    """The location column k of row b matches row a's mirror (x <-> y)."""
    stem, axis = k[:-2], k[-1]
    other = {"x": "y", "y": "x"}.get(axis) if k[-2:] in ("_x", "_y") else None
    return (other is not None and f"{stem}_{other}" in a and f"{stem}_{other}" in b
            and close(float(a[k]), float(b[f"{stem}_{other}"]))
            and close(float(a[f"{stem}_{other}"]), float(b[k])))


for a, b in zip(ref, got):
    for k in a:
        if k in COST or k not in b or (no_locations and k[-2:] in ("_x", "_y", "_z")):
            continue
        x, y = float(a[k]), float(b[k])
        if not close(x, y, k, a) and not mirrored(a, b, k):
            failures.append(f"step {a['step']}, {k}: {y!r}, reference {x!r}")
total = {t: sum(int(r["newton_iterations"]) for r in rows)
         for t, rows in (("ref", ref), ("got", got))}
if total["got"] > 1.5 * total["ref"] + 5:
    failures.append(f"{total['got']} Newton iterations, reference "
                    f"{total['ref']} (> 1.5x + 5)")
for f in failures[:30]:
    print("FAIL", f)
if failures:
    sys.exit(1)
print(f"history.csv matches {reference} ({len(got)} steps; Newton iterations "
      f"{total['got']}, reference {total['ref']})")
