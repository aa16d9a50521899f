"""An adaptive draw whose adaptations must invent nothing (issue 48,
section 1), from history.csv, refinement.csv and run-summary.txt:
- no fracture is reported (critical_stroke < 0);
- the largest Oyane integral rises across an adaptation by no more than 1.5
  times the larger of the two steps' increments before it, plus 1e-4: the
  transfer makes no new maximum;
- the punch force changes across an adaptation (the step after it against
  the step before) by no more than the larger change of the neighbouring
  steps, plus 0.5 % of the force;
- every adaptation keeps the sheet's volume within 1e-6 (relative).
The run must have adapted after straining started, coarsening included."""
import csv, os, sys
import results

out = sys.argv[1]
rows = list(results.read(out))
adaptations = list(csv.DictReader(open(os.path.join(out, "refinement.csv"))))
summary = dict(line.split(" = ", 1) for line in
               open(os.path.join(out, "run-summary.txt")).read().splitlines()
               if " = " in line)
F = {int(r["step"]): float(r["punch_force"]) for r in rows}
I = {int(r["step"]): float(r["max_oyane"]) for r in rows}
ok = True

critical = float(summary["critical_stroke"])
print(f"critical stroke {critical} (largest I {max(I.values()):.4f})")
ok &= critical < 0

worst_force, worst_damage, worst_volume, coarsened = 0.0, 0.0, 0.0, 0
for a in adaptations:
    s = int(float(a["step"]))
    dv = abs(float(a["volume_after"]) / float(a["volume_before"]) - 1)
    worst_volume = max(worst_volume, dv)
    coarsened += float(a["flagged_coarsen"]) > 0 and s > 0
    if not all(k in F for k in (s - 2, s - 1, s, s + 1, s + 2)):
        continue
    jump = abs(F[s + 1] - F[s])
    limit = max(abs(F[s] - F[s - 1]), abs(F[s + 2] - F[s + 1])) + 0.005 * abs(F[s])
    rise = I[s + 1] - I[s]
    damage_limit = 1.5 * max(abs(I[s] - I[s - 1]), abs(I[s - 1] - I[s - 2])) + 1e-4
    worst_force = max(worst_force, (jump - limit) / abs(F[s]))
    worst_damage = max(worst_damage, rise - damage_limit)
    if jump > limit or rise > damage_limit or dv > 1e-6:
        ok = False
        print(f"FAIL adaptation at step {s}: force {F[s]:.0f} -> {F[s + 1]:.0f} N "
              f"(limit {limit:.0f}), I {I[s]:.5f} -> {I[s + 1]:.5f} (limit "
              f"{I[s] + damage_limit:.5f}), volume change {dv:.2e}")
print(f"{len(adaptations)} adaptations, {coarsened} with coarsening; force jump "
      f"beyond its limit at most {100 * worst_force:.3f} % of the force (<= 0); "
      f"I beyond its limit at most {worst_damage:.2e} (<= 0); volume change at "
      f"most {worst_volume:.2e}")
ok &= coarsened > 0 and len(adaptations) > 10
sys.exit(0 if ok else 1)
