"""Penetration equals (platen force / contact area) / penalty in every row.
The contact area is that of the step's start geometry (see check_compression.py)."""
import csv, sys
import results

rows = list(results.read(sys.argv[1]))
penalty, h0 = 1e4, 10.0
worst = 0.0
h_start = h0
for r in rows:
    pen = float(r["max_penetration"])
    h = h0 - float(r["punch_travel"]) + 2 * pen
    area = float(r["volume"]) / h_start
    h_start = h
    expected = float(r["punch_force"]) / area / penalty
    err = abs(pen - expected) / expected
    worst = max(worst, err)
    print(f"penetration={pen:.6e} mm  expected={expected:.6e} mm  error={err:.2e}")
assert len(rows) > 0
print(f"worst relative error {worst:.2e} (limit 1e-3)")
sys.exit(0 if worst < 1e-3 else 1)
