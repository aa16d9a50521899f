"""Earing of the quarter cup (`doc/reference-scenes.md` (section 2)), read from
earing.csv (cup height against the angle to RD over 0-90 degrees) and
run-summary.txt:
- "ears": with r-based Hill and delta r = (r0 + r90 - 2 r45)/2 > 0, four ears,
  at 0 and 90 degrees (crests there, the highest within 5 degrees of one of
  them, and the summary's ear angles within 5 degrees) and the lowest height near 45
  (within 10 degrees), amplitude above 1 mm (measured 3.36 mm), and the
  summary's ears and ear_angles the same;
- "flat": planar isotropy, the rim flat within 0.3 mm and no ears in the
  summary. Measured 0.0945 mm: the quarter-disk mesh's own waviness (its
  cells are not symmetric about 45 degrees), which the limit must leave room
  for: 3x that, still a tenth of the 3.36 mm ears of "ears".
Usage: check_earing.py OUT ears|flat"""
import csv, os, sys

out, mode = sys.argv[1], sys.argv[2]
rows = [(float(r["angle_deg"]), float(r["cup_height_mm"]))
        for r in csv.DictReader(open(os.path.join(out, "earing.csv")))]
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")) if " = " in l)
heights = [h for _, h in rows]
amplitude = max(heights) - min(heights)
checks = {"profile from 0 to 90 degrees": rows[0][0] == 0 and abs(rows[-1][0] - 90) < 1e-9,
          "drawn through": summary["end_reason"].startswith("drawn through")}
if mode == "ears":
    low = min(rows, key=lambda r: r[1])[0]
    angles = [float(a) for a in summary["ear_angles"].split()]
    checks.update({
        "amplitude above 1 mm": amplitude > 1,
        "highest within 5 degrees of 0 or 90": min(abs(max(rows, key=lambda r: r[1])[0] - e)
                                                   for e in (0, 90)) <= 5,
        "crests at 0 and 90 degrees": heights[0] >= heights[1] and heights[-1] >= heights[-2]
        and min(heights[0], heights[-1]) > sum(heights) / len(heights) + amplitude / 4,
        "lowest near 45 degrees (within 10)": abs(low - 45) <= 10,
        "four ears in the summary": summary["ears"] == "4",
        "at 0, 90, 180, 270 degrees (within 5)": len(angles) == 4 and all(
            min(abs(a - e), 360 - abs(a - e)) <= 5 for a, e in zip(sorted(angles), (0, 90, 180, 270)))})
else:
    checks.update({"flat within 0.3 mm": amplitude <= 0.3, "no ears in the summary": summary["ears"] == "0"})
print(f"{len(rows)} angles, mean {sum(heights) / len(heights):.3f} mm, amplitude {amplitude:.4f} mm, "
      f"summary: ears {summary.get('ears')} at {summary.get('ear_angles')}")
for what, good in checks.items():
    print(f"{'ok  ' if good else 'FAIL'} {what}")
sys.exit(0 if all(checks.values()) else 1)
