"""Unsymmetric tangent = symmetric part: history.csv matches the LU reference
(check_regression.py: physics at 1e-5), and the factors were those of the
symmetric part, not of the tangent: GMRES needed more than 4 linear iterations
per Newton iteration, where exact factors need one per solve (two per Newton
iteration with the holder's second solve).

Usage: check_symmetric_part.py OUT REFERENCE"""
import os
import subprocess
import sys

out, reference = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, linear = int(summary["newton_iterations"]), int(summary["linear_iterations"])
print(f"{linear} linear iterations in {newton} Newton iterations")
sys.exit(0 if ok and linear > 4 * newton else 1)
