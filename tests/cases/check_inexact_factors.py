"""Approximate factors (block low-rank, single precision, or LDL^T of the
tangent's symmetric part) as GMRES's preconditioner: history.csv matches
the reference of the run with exact factors (check_regression.py: physics
at 1e-5, or RELATIVE), and the solves needed GMRES iterations: more than
RATIO linear iterations per Newton iteration, where exact factors need one
per solve (two per Newton iteration with the holder's second solve).
Measured: 473 low-rank iterations in 20 Newton iterations (cup_3d_low_rank,
RATIO 5), 792 with the symmetric part in 51 (cup_3d_symmetric_part_2ranks,
RATIO 4), 510 with single-precision factors in 45
(cup_3d_single_precision_2ranks, RATIO 2.5, RELATIVE 3e-3).
--at-most: inexact Newton (Nonlinear solver/Forcing) instead; at most RATIO
linear iterations per Newton iteration. Measured on cup-fixed-short-forcing:
93 in 40 with Forcing = 1, 409 in 40 with Forcing = 0 (cup_3d_forcing_2ranks,
RATIO 4, RELATIVE 1e-3: 8 runs on 2 ranks took 37-38 Newton iterations
and moved step 1's strain by up to 4.2e-5 against the reference, a CI run
took 39 and moved it by 1.7e-4).

Usage: check_inexact_factors.py OUT REFERENCE RATIO [RELATIVE] [--at-most]"""
import os
import subprocess
import sys

at_most = "--at-most" in sys.argv
args = [a for a in sys.argv if a != "--at-most"]
out, reference, ratio = args[1], args[2], float(args[3])
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]
                     + args[4:5]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, linear = int(summary["newton_iterations"]), int(summary["linear_iterations"])
print(f"{linear} linear iterations in {newton} Newton iterations")
sys.exit(0 if ok and (linear <= ratio * newton if at_most else linear > ratio * newton) else 1)
