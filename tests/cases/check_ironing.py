"""Deliberate ironing (ironing.prm: clearance 0.6 mm per side, t0 0.78 mm):
- no squeezing force before the wall reaches the gap, then ironing_force > 0
  in every later step, reported once (run-summary ironing_travel);
- the ironed wall (columns in the gap, 2 mm and more below the die radius'
  end and above the punch nose's end, 25 - 8 mm down; the thickness of a
  column averages its cells', one element each side) is as thick as the clearance, up to the two penetrations the contact
  allows: 0.6 - 2 delta <= t <= 0.6 (delta = 1e-3 mm), within 2e-4 mm."""
import csv, os, sys
import results

out = sys.argv[1]
clearance, delta = 0.6, 1e-3
rows = list(results.read(out))
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")) if " = " in l)
start = float(summary["ironing_travel"])
fail = []
if not 5 < start < 25:
    fail.append(f"ironing_travel = {start}, expected between 5 and 25 mm")
early = [r for r in rows if float(r["force_travel"]) < start - 1e-9]
late = [r for r in rows if float(r["force_travel"]) >= start]
if any(float(r["ironing_force"]) > 0.005 * float(r["punch_force"]) for r in early):
    fail.append("an ironing force above 0.5 % of the punch force before ironing_travel")
if not late or min(float(r["ironing_force"]) for r in late) <= 0:
    fail.append("ironing_force not positive in every step from ironing_travel on")
wall = [float(c["thickness"]) for c in csv.DictReader(open(os.path.join(out, "sheet.csv")))
        if float(c["r"]) > 20 and -(25 - 8 - 2) < float(c["z"]) < -(8 + 2)]
if len(wall) < 3:
    fail.append(f"only {len(wall)} columns in the gap")
elif not all(clearance - 2 * delta - 2e-4 <= t <= clearance + 2e-4 for t in wall):
    fail.append(f"wall thickness {min(wall):.5f}-{max(wall):.5f} mm, expected the clearance {clearance} mm less up to 2 delta")
print(f"ironing from {start} mm; ironed wall {min(wall, default=0):.5f}-{max(wall, default=0):.5f} mm over {len(wall)} columns; "
      f"largest squeezing force {summary.get('max_ironing_force')} N")
for f in fail:
    print("FAIL", f)
sys.exit(1 if fail else 0)
