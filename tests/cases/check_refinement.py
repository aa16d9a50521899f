"""refinement.csv of an adaptive run: every adaptation keeps the blank volume
within 0.1 %, the volume integral of equivalent strain within 1 % and that of
Oyane's damage integral within 0.1 %; the run
must have refined and coarsened cells after straining started (else the test
would check nothing). Optional second argument: the new cells per refined
cell without coarsening (7 in 3-D, the default; 3 in 2-D)."""
import csv, os, sys

rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "refinement.csv"))))
new_per_refined = float(sys.argv[2]) if len(sys.argv) > 2 else 7
ok, refined, coarsened = True, False, False
for r in rows:
    r = {k: float(v) for k, v in r.items()}
    dv = abs(r["volume_after"] - r["volume_before"]) / r["volume_before"]
    s0, s1 = r["strain_integral_before"], r["strain_integral_after"]
    ds = abs(s1 - s0) / s0 if s0 > 0 else 0.0
    d0, d1 = r["damage_integral_before"], r["damage_integral_after"]
    dd = abs(d1 - d0) / abs(d0) if d0 != 0 else 0.0
    grew = r["cells_after"] - r["cells_before"]
    print(f"step {r['step']:3.0f}: cells {r['cells_before']:.0f} -> {r['cells_after']:.0f}, "
          f"volume change {dv:.2e}, strain integral change {ds:.2e}, damage integral change {dd:.2e}")
    ok &= dv <= 1e-3 and ds <= 1e-2 and dd <= 1e-3
    if s0 > 0:
        refined |= r["flagged_refine"] > 0
        # 2^dim children per refined cell: fewer new cells means families
        # merged.
        coarsened |= r["flagged_coarsen"] > 0 and grew < new_per_refined * r["flagged_refine"]
print(f"refined after straining: {refined}, coarsened: {coarsened}")
sys.exit(0 if ok and refined and coarsened else 1)
