"""Approximate factors (block low-rank, single precision, or LDL^T of the
tangent's symmetric part) as GMRES's preconditioner: history.csv matches
the reference of the run with exact factors (check_regression.py: physics
at 1e-5, or RELATIVE); the solves took GMRES iterations, more than two per
Newton iteration (exact factors need one solve, two with the holder's second
right-hand side: more shows the approximate path ran); and not more than
MAX_RATIO per Newton iteration, about 3x what was measured, so that a
solver that gets much worse fails and one that gets better does not.
Measured (`ctest -R "cup_3d_(low_rank|symmetric|single|forcing)"`, run-summary
linear_iterations / newton_iterations): low-rank 336 in 10 (MAX_RATIO 100),
symmetric part 521 in 36 (45), single precision 358 in 36 (30, RELATIVE
3e-3).
--inexact-newton: inexact Newton (Nonlinear solver/Forcing) on exact factors
instead, where a solve may stop after one iteration: only the upper bound.
Measured on cup-fixed-short-forcing: 68 in 37 (MAX_RATIO 4; RELATIVE 1e-3:
8 runs on 2 ranks took 37-38 Newton iterations and moved step 1's strain by
up to 4.2e-5 against the reference, a CI run took 39 and moved it by
1.7e-4).

Usage: check_inexact_factors.py OUT REFERENCE MAX_RATIO [RELATIVE] [--inexact-newton]"""
import os
import subprocess
import sys

inexact_newton = "--inexact-newton" in sys.argv
args = [a for a in sys.argv if a != "--inexact-newton"]
out, reference, ratio = args[1], args[2], float(args[3])
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]
                     + args[4:5]) == 0
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, linear = int(summary["newton_iterations"]), int(summary["linear_iterations"])
checks = {f"at most {ratio:g} per Newton iteration": linear <= ratio * newton}
if not inexact_newton:
    checks["more than 2 per Newton iteration (the approximate factors were used)"] = linear > 2 * newton
print(f"{linear} linear iterations in {newton} Newton iterations ({linear / max(newton, 1):.1f} each)")
for what, good in checks.items():
    print(f"{'ok  ' if good else 'FAIL'} {what}")
sys.exit(0 if ok and all(checks.values()) else 1)
