"""Factorisation reuse: history.csv matches the reference of the run with a
fresh factorisation per matrix (check_regression.py: physics at 1e-5), and
the run factorised fewer matrices than it had Newton iterations (the reuse
happened; without it every iteration factorises once).
--per-solve (Reuse velocity change > 0, Log iterations = true): no factors
are carried from one Newton solve to the next. The first iteration of every
solve factorises its matrix and is solved by substitution alone: at most 2
linear iterations (the body, and the holder's second right-hand side) in the
log's "it  1" lines, where a reuse attempt takes GMRES iterations.

Usage: check_reuse.py OUT REFERENCE [--per-solve]"""
import csv, os, re, subprocess, sys
import results

out, reference = sys.argv[1:3]
per_solve = "--per-solve" in sys.argv[3:]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, factorised = int(summary["newton_iterations"]), int(summary["factorisations"])
print(f"{factorised} factorisations in {newton} Newton iterations")
if per_solve:
    rows = list(results.read(out))
    solves = sum(1 + int(r["strict_passes"]) for r in rows)
    first = [int(m.group(1)) for m in (re.match(r"\s+it\s+1 .*\blinear=(\d+)", line) for line in open(out + ".log")) if m]
    print(f"{solves} Newton solves; linear iterations of their first iterations: {first}")
    ok = ok and len(first) == solves and max(first) <= 2
sys.exit(0 if ok and 0 < factorised < newton else 1)
