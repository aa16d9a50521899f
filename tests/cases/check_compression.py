"""Platen force against sigma_bar(ln(h0/h)) * V/h_n within 1 % in every row.

A step's velocity is solved on the geometry at the start of the step (explicit
geometry update, doc/theory.md), so its force acts on the area V/h_n of the
previous height h_n, while the strain has reached ln(h0/h) at the step's end."""
import csv, math, sys
import results

rows = list(results.read(sys.argv[1]))
K, n, eps0, h0 = 500.0, 0.2, 0.002, 10.0
worst = 0.0
h_start = h0
for r in rows:
    pen = float(r["max_penetration"])
    h = h0 - float(r["punch_travel"]) + 2 * pen  # both platens penetrate by pen
    strain = math.log(h0 / h)
    expected = K * (eps0 + strain) ** n * float(r["volume"]) / h_start
    h_start = h
    err = abs(float(r["punch_force"]) - expected) / expected
    worst = max(worst, err)
    print(f"h={h:.4f} mm  F={float(r['punch_force']):.1f} N  expected={expected:.1f} N  error={err:.2e}")
assert len(rows) == 30, f"expected 30 steps, got {len(rows)}"
print(f"worst relative error {worst:.2e} (limit 2e-3)")
sys.exit(0 if worst < 2e-3 else 1)
