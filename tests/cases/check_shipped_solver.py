"""The solver settings of the shipped 3-D case (prm/cup-drawing-3d.prm:
single-precision factors reused as GMRES's preconditioner within a Newton
solve, inexact Newton with Forcing) against the reference of exact solves
(cup-adaptive-short.history.csv, cup-adaptive-short.prm):
- the physics per step at relative 3e-3 (check_regression.py). The
  penetrations match within 5e-5 mm, 5 % of the allowed 1e-3 mm: an inexact
  Newton solve stops elsewhere within Newton's tolerance, which moved a
  penetration by 2.3e-5 to 2.7e-5 mm (punch, step 1; 1 and 2 ranks, 7
  runs); forces moved by 3e-5 (relative). The thinning, 0.05 % in step 1,
  within 2e-3 percentage points (2.4e-4 on 1 rank, up to 8.9e-4 on 2).
  The through-thickness averages of the damage integrals within 2e-5: the
  average of a signed integrand over a bent sheet, whose tensile and
  compressive fibres nearly cancel in the first steps (I about 5e-4 at step
  1; moved by up to 5.8e-6 on 2 ranks, 1 % of it). The
  locations of maxima and minima are left out: in the first steps the
  extremes tie between nodes;
- the bound the strategy keeps: no penetration above Allowed penetration
  (1e-3 mm, read from the run's parameters.prm);
- the factors were reused: fewer factorisations than Newton iterations.

Usage: check_shipped_solver.py OUT REFERENCE"""
import csv
import results
import os
import re
import subprocess
import sys

out, reference = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference,
                      "3e-3", "--absolute", "penetration=5e-5,thinning_percent=2e-3,through_thickness=2e-5",
                      "--no-locations"]) == 0
allowed = float(re.search(r"set Allowed penetration\s*=\s*(\S+)",
                          open(os.path.join(out, "parameters.prm")).read()).group(1))
deepest = max(float(r["max_penetration"]) for r in results.read(out))
print(f"deepest penetration {deepest:.4e} mm (allowed {allowed:g})")
ok = ok and deepest <= allowed
summary = dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(out, "run-summary.txt")) if " = " in line)
newton, factorised = int(summary["newton_iterations"]), int(summary["factorisations"])
print(f"{factorised} factorisations in {newton} Newton iterations")
sys.exit(0 if ok and 0 < factorised < newton else 1)
