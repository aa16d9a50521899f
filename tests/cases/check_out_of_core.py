"""MUMPS's factors out of core (Linear solver/Out-of-core directory):
history.csv matches the reference of the in-core run (check_regression.py:
physics at 1e-5); MUMPS's memory (INFOG(22)) is below that of the same run
in core (IN_CORE_OUT) by at least half the factors' size (on this small case
the out-of-core buffers take the rest: 40 MB against 55 MB in core, factors
23 MB); and MUMPS removed its files from OUT.factors when the factors were
dropped.

Usage: check_out_of_core.py OUT REFERENCE IN_CORE_OUT"""
import os
import subprocess
import sys

out, reference, in_core_out = sys.argv[1], sys.argv[2], sys.argv[3]
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_regression.py"), out, reference]) == 0


def summary(run):
    return dict(line.rstrip("\n").split(" = ", 1) for line in open(os.path.join(run, "run-summary.txt")) if " = " in line)


s, reference_run = summary(out), summary(in_core_out)
mumps_mb = float(s["factorisation_memory_mb"])
in_core_mb = float(reference_run["factorisation_memory_mb"])
factors_mb = 8e-6 * float(s["factor_entries"])
print(f"MUMPS {mumps_mb:.1f} MB out of core, {in_core_mb:.1f} MB in core; factors {factors_mb:.1f} MB")
if not 0 < mumps_mb <= in_core_mb - 0.5 * factors_mb:
    print("FAIL: the factors were held in core")
    ok = False
left = os.listdir(out + ".factors")
if left:
    print(f"FAIL: files left in {out}.factors: {left}")
    ok = False
sys.exit(0 if ok else 1)
