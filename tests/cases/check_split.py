"""Whether a run split, as run-summary.txt, history.csv and the screen say:
check_split.py OUT split LOW HIGH [MEASURE]: the sheet split between LOW and
HIGH mm of punch travel by MEASURE (default: forming limit); the run stopped
by Split/Travel past the split after it (end_reason), at the column past the
curve (flc_margin_percent < 0 from the split on, >= 0 before), said once on
screen. check_split.py OUT none: no split, the run drew through, every
step's margin >= 0 and no neck. check_split.py OUT continued LOW HIGH: the
split by the forming limit, then a neck between LOW and HIGH mm, then the
solver's failure, which the end reason puts down to the split. With a report (report/report.md), the report
says the same (check_report.py is run on it)."""
import os, subprocess, sys
import results

out, expect = sys.argv[1], sys.argv[2]
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")) if " = " in l)
rows = list(results.read(out))
travel = [float(r["punch_travel"]) for r in rows]
margin = [float(r["flc_margin_percent"]) for r in rows]
log = open(out + ".log").read()
checks = {}
if expect == "split":
    lo, hi = float(sys.argv[3]), float(sys.argv[4])
    measure = sys.argv[5] if len(sys.argv) > 5 else "forming limit"
    at = float(summary["split_travel"])
    checks["split said in run-summary.txt"] = summary["split"] == "yes" and summary["split_measure"] == measure
    checks[f"split between {lo} and {hi} mm ({at:.3f})"] = lo <= at <= hi
    checks["the split has a location"] = summary["split_location"].startswith("R0 = ")
    checks["end reason: the sheet split"] = summary["end_reason"].startswith("the sheet split: ")
    past = travel[-1] - at
    checks[f"stopped 1 mm past it ({past:.3f})"] = abs(past - 1) < 1e-6
    if measure == "forming limit":
        first = next(i for i, m in enumerate(margin) if m < 0)
        checks["the margin crosses 0 in the split's step"] = travel[first - 1] <= at <= travel[first] + 1e-9
    checks["said once on screen"] = log.count("\nsplit: ") == 2  # when found, and at the end
elif expect == "continued":
    lo, hi = float(sys.argv[3]), float(sys.argv[4])
    neck = float(summary["neck_travel"])
    checks["split by the forming limit"] = summary["split_measure"] == "forming limit"
    checks[f"a neck between {lo} and {hi} mm ({neck:.3f})"] = lo <= neck <= hi
    checks["the neck after the split"] = neck > float(summary["split_travel"])
    checks["neck said on screen"] = "\nnote: a neck forms" in log
    checks["end reason: the solver after the split"] = summary["end_reason"].startswith(
        "the solver stopped converging") and "after the sheet split" in summary["end_reason"]
else:
    checks["no split in run-summary.txt"] = summary["split"] == "no" and float(summary["split_travel"]) < 0
    checks["no neck"] = float(summary["neck_travel"]) < 0
    checks["drawn through"] = summary["end_reason"].startswith("drawn through")
    checks[f"margin >= 0 at every step (min {min(margin):.1f} %)"] = min(margin) >= 0
    checks["no split on screen"] = "\nsplit: " not in log and "\nno split" in log
for what, good in checks.items():
    print(f"{'ok  ' if good else 'FAIL'} {what}")
ok = all(checks.values())
if os.path.exists(os.path.join(out, "report", "report.md")):
    ok = subprocess.call([sys.executable, os.path.join(os.path.dirname(__file__), "check_report.py"), out]) == 0 and ok
elif "CASE_REPORT" in os.environ:
    print("FAIL no report")
    ok = False
sys.exit(0 if ok else 1)
