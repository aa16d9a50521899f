"""Factorisation reuse: history.csv matches the reference of the run with a
fresh factorisation per matrix (check_regression.py: physics at 1e-5), and
the run factorised fewer matrices than it had Newton iterations (the reuse
happened; without it every iteration factorises once).

Usage: check_reuse.py OUT REFERENCE"""
import os, subprocess, sys

out, reference = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, factorised = int(summary["newton_iterations"]), int(summary["factorisations"])
print(f"{factorised} factorisations in {newton} Newton iterations")
sys.exit(0 if ok and 0 < factorised < newton else 1)
