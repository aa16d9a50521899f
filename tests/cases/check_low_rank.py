"""Block low-rank factors: history.csv matches the reference of the full-rank
run (check_regression.py: physics at 1e-5), and the solves needed GMRES
iterations: more than 5 linear iterations per Newton iteration, where
full-rank factors need one per solve (41 in 21 Newton iterations here, with
the holder's second solve) and these low-rank ones 496; the factors were
inexact and GMRES corrected them.

Usage: check_low_rank.py OUT REFERENCE"""
import os, subprocess, sys

out, reference = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, linear = int(summary["newton_iterations"]), int(summary["linear_iterations"])
print(f"{linear} linear iterations in {newton} Newton iterations")
sys.exit(0 if ok and linear > 5 * newton else 1)
