"""A split by the fracture criterion (Split/Measures = fracture criterion,
Travel past the split = 0): the run ends in the step in which the deciding
criterion (Oyane, read by Material/Fracture measure: history column COLUMN)
first reaches 1, before the stroke, with that reason, that critical stroke
and that split in run-summary.txt: every earlier step's largest I is below
1, the last step's at or above it, and the critical stroke lies within the
last step's travel; the other measure's critical stroke is reported as well
(-1 if not reached).
Usage: check_stop_at_fracture.py OUT COLUMN"""
import csv, sys
import results

out = sys.argv[1]
rows = list(results.read(out))
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(out + "/run-summary.txt") if " = " in l)
column = sys.argv[2]
oyane = [float(r[column]) for r in rows]
travel = [float(r["punch_travel"]) for r in rows]
stroke = float(summary["critical_stroke"])
checks = {
    "earlier steps below 1": all(i < 1 for i in oyane[:-1]),
    "last step at or above 1": oyane[-1] >= 1,
    "ended before the 5 mm stroke": travel[-1] < 5 - 1e-9,
    "critical stroke within the last step": travel[-2] < stroke <= travel[-1] + 1e-12,
    "both measures' strokes reported": "critical_stroke_local" in summary
    and "critical_stroke_through_thickness" in summary,
    "end reason": summary["end_reason"].startswith("the sheet split: Oyane's integral reaches 1"),
    "the split is the fracture": summary["split"] == "yes"
    and summary["split_measure"] == "fracture criterion"
    and abs(float(summary["split_travel"]) - stroke) < 1e-4,
}
print(f"{len(rows)} steps, I {oyane[-2]:.3f} -> {oyane[-1]:.3f}, critical stroke {stroke} mm, "
      f"last travel {travel[-1]} mm: {summary['end_reason']}")
for what, good in checks.items():
    print(f"{'ok  ' if good else 'FAIL'} {what}")
sys.exit(0 if all(checks.values()) else 1)
