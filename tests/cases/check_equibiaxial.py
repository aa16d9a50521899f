"""Equibiaxial stretching of a thin disk by compression between frictionless
platens: every column of sheet.csv has thickness h within 0.5 % and
(minor, major) = (eps, eps), eps = ln(h0/h)/2, within 1 %; h is the platen
distance at the end, h0 - travel + 2 penetration."""
import csv, math, os, sys
import results

out = sys.argv[1]
last = list(results.read(out))[-1]
h0 = 1.0
h = h0 - float(last["punch_travel"]) + 2 * float(last["max_penetration"])
eps = 0.5 * math.log(h0 / h)
cols = list(csv.DictReader(open(os.path.join(out, "sheet.csv"))))
wt = max(abs(float(c["thickness"]) / h - 1) for c in cols)
wmaj = max(abs(float(c["major_strain"]) / eps - 1) for c in cols)
wmin = max(abs(float(c["minor_strain"]) / eps - 1) for c in cols)
print(f"{len(cols)} columns, h = {h:.5f} mm, eps = {eps:.5f}: worst thickness {wt:.2e} (0.5 %), "
      f"major {wmaj:.2e}, minor {wmin:.2e} (1 %)")
sys.exit(0 if len(cols) > 10 and wt < 5e-3 and wmaj < 1e-2 and wmin < 1e-2 else 1)
