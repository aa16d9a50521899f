"""The plane-strain channel (channel-short.prm) in every row of history.csv:
- equilibrium: the die carries the punch and the holder, |F_die - F_punch -
  F_bh| <= 2e-7 F_die (5.8e-8 measured: Newton's tolerance);
- the holder presses with its set force (force control), within 1e-6;
- the strip's volume, 2 (half section) x the width, stays that of the blank,
  L W t, within 1e-3 (3.4e-4 measured: the volumetric penalty's
  compressibility under the holder's pressure);
and in sheet.csv no strain across the section: one of every column's two
in-plane strains is 0 (below 1e-12; the minor one where the section
stretches, the major one where it shortens)."""
import csv, os, sys
import results

out = sys.argv[1]
L, W, T, F_SET = 350.0, 35.0, 0.78, 19600.0
rows = list(results.read(out))
assert len(rows) >= 3, f"only {len(rows)} steps"
worst_eq = max(abs(float(r["force_die"]) - float(r["force_punch"]) - float(r["force_blank_holder"]))
               / float(r["force_die"]) for r in rows)
worst_bh = max(abs(float(r["force_blank_holder"]) / F_SET - 1) for r in rows)
worst_v = max(abs(float(r["volume"]) / (L * W * T) - 1) for r in rows)
sheet = list(csv.DictReader(open(os.path.join(out, "sheet.csv"))))
worst_across = max(min(abs(float(c["minor_strain"])), abs(float(c["major_strain"]))) for c in sheet)
print(f"{len(rows)} rows: |F_die - F_punch - F_bh| / F_die <= {worst_eq:.2e}, holder force off by "
      f"{worst_bh:.2e}, volume off by {worst_v:.2e}; {len(sheet)} columns: strain across the section "
      f"<= {worst_across:.1e}")
ok = worst_eq <= 2e-7 and worst_bh <= 1e-6 and worst_v <= 1e-3 and worst_across <= 1e-12
sys.exit(0 if ok else 1)
