"""LDL^T against LU on a symmetric tangent (the frictionless cup): the same
converged steps (check_regression.py: physics at 1e-5, iteration totals
loosely), and the LDL^T factors have fewer entries than the LU factors
(run-summary.txt, factor_entries: one triangle against two), i.e. the
symmetric path ran.
Usage: check_symmetric_solver.py OUT_LDLT OUT_LU"""
import os, subprocess, sys

ldlt, lu = sys.argv[1:3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"),
                      ldlt, os.path.join(lu, "history.csv")]) == 0


def entries(out):
    s = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")) if " = " in l)
    return float(s["factor_entries"])


e_ldlt, e_lu = entries(ldlt), entries(lu)
print(f"factor entries: LDL^T {e_ldlt:g}, LU {e_lu:g}")
if not 0 < e_ldlt < 0.7 * e_lu:
    print("FAILED: LDL^T should store less than 0.7x the entries of LU")
    ok = False
sys.exit(0 if ok else 1)
