"""Upsetting between frictionless platens: the platen force against the
closed form of the homogeneous deformation, F = sigma_bar(eps) V / h.

The velocities of a step are solved on the geometry at the start of the step
(explicit geometry update, doc/theory.md section 7), so step n's force acts
on the area V / h_{n-1} of the previous height, and the strain grows by the
height change over that height: eps_n = sum_i (h_{i-1} - h_i) / h_{i-1}. The
height h includes the penetration into both platens.

Usage: check_upsetting.py OUT TOLERANCE [OTHER_OUT OTHER_TOLERANCE]
With OTHER_OUT, the punch forces must also agree with that run's, row by row,
within OTHER_TOLERANCE (relative)."""
import csv, sys
import results

K, n, eps0, h0 = 500.0, 0.2, 0.002, 10.0
rows = list(results.read(sys.argv[1]))
tolerance = float(sys.argv[2])
assert len(rows) == 30, f"expected 30 steps, got {len(rows)}"
worst, h_prev, eps = 0.0, h0, 0.0
for r in rows:
    h = h0 - float(r["punch_travel"]) + 2 * float(r["max_penetration"])
    eps += (h_prev - h) / h_prev
    expected = K * (eps0 + eps) ** n * float(r["volume"]) / h_prev
    h_prev = h
    err = abs(float(r["punch_force"]) / expected - 1)
    worst = max(worst, err)
print(f"closed form: worst relative error {worst:.2e} (limit {tolerance:g}), "
      f"last force {float(rows[-1]['punch_force']):.1f} N")
ok = worst < tolerance
if len(sys.argv) > 3:
    other = list(results.read(sys.argv[3]))
    assert len(other) == len(rows)
    diff = max(abs(float(a["punch_force"]) / float(b["punch_force"]) - 1)
               for a, b in zip(rows, other))
    print(f"against {sys.argv[3]}: worst relative force difference {diff:.2e} "
          f"(limit {sys.argv[4]})")
    ok = ok and diff < float(sys.argv[4])
sys.exit(0 if ok else 1)
