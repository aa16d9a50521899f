"""A tool that can never touch the sheet (untouched-punch.prm): warned at the
start (the distance and the reach) and at the end (its force stayed 0), both
on screen and in run-summary.txt's warnings; the run itself ends normally."""
import os, sys

out = sys.argv[1]
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")) if " = " in l)
warnings = [summary[f"warning_{k}"] for k in range(1, int(summary["warnings"]) + 1)]
log = open(out + ".log").read()
start = "Tools/Punch: the tool is 10 mm from the sheet, farther than the run brings them together (5 mm"
end = "Tools/Punch: the tool never touched the sheet (its force stayed 0 over the run)"
checks = {
    "warned at the start, on screen": "warning: " + start in log,
    "warned at the end, on screen": "warning: " + end in log,
    "both in run-summary.txt": any(w.startswith(start) for w in warnings) and any(w.startswith(end) for w in warnings),
    "no other tool warned": not any("Tools/Die" in w or "Tools/Blank holder" in w for w in warnings),
    "the stroke was reached": summary["end_reason"] == "the punch stroke was reached",
}
for what, good in checks.items():
    print(f"{'ok  ' if good else 'FAIL'} {what}")
sys.exit(0 if all(checks.values()) else 1)
