"""Two runs of one process agree at their last step: punch force, largest
equivalent strain and largest Oyane integral within a relative tolerance.
Usage: check_same_peaks.py OUTDIR OTHER_OUTDIR TOLERANCE"""
import csv, os, sys
import results

out, other, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
last = [list(results.read(d))[-1]
        for d in (out, other)]
ok = last[0]["punch_travel"] == last[1]["punch_travel"]
for key in ("punch_force", "max_equivalent_strain", "max_oyane"):
    a, b = float(last[0][key]), float(last[1][key])
    rel = abs(a / b - 1)
    print(f"{key}: {a:.6g} against {b:.6g}: {100 * rel:.3f} % (tolerance {100 * tol:g} %)")
    ok &= rel <= tol
sys.exit(0 if ok else 1)
