"""The iterative path: history.csv matches the reference of the direct solves
(check_regression.py: physics at 1e-5), no solve fell back to the direct
solver (no factorisation), and the solves were iterative (more than one
linear iteration per Newton iteration).

Usage: check_iterative.py OUT REFERENCE"""
import os, subprocess, sys

out, reference = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, linear = int(summary["newton_iterations"]), int(summary["linear_iterations"])
factorised = int(summary["factorisations"])
print(f"{linear} linear iterations and {factorised} factorisations in {newton} Newton iterations")
sys.exit(0 if ok and factorised == 0 and linear > 2 * newton else 1)
