"""refinement.csv of an adaptive run, per adaptation. Refinement alone keeps
the sheet's geometry, so the volume exactly (1e-12), and the volume
integrals of equivalent strain and Oyane's damage integral within 1e-4 (the
transfer keeps them in the reference configuration; the current one differs
by the volume errors inside a cell). Coarsening moves the sheet by at most
the coarsening shape tolerance: volume within 2.5e-4, strain integral within
5e-4 and damage integral within 2.5e-3 (measured 1.1e-4, 1.4e-4, 4.1e-4 at
0.01 mm). The run must have refined and coarsened cells after straining
started (else the test would check nothing). Optional second argument: the
new cells per refined cell without coarsening (7 in 3-D, the default; 3 in
2-D)."""
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
    # 2^dim children per refined cell: fewer new cells means families merged.
    merged = r["flagged_coarsen"] > 0 and grew < new_per_refined * r["flagged_refine"]
    limits = (2.5e-4, 5e-4, 2.5e-3) if merged else (1e-12, 1e-4, 1e-4)
    good = dv <= limits[0] and ds <= limits[1] and dd <= limits[2]
    print(f"step {r['step']:3.0f}: cells {r['cells_before']:.0f} -> {r['cells_after']:.0f}"
          f"{' (coarsened)' if merged else ''}, volume change {dv:.2e}, strain "
          f"integral change {ds:.2e}, damage integral change {dd:.2e}"
          f"{'' if good else '  FAIL'}")
    ok &= good
    if s0 > 0:
        refined |= r["flagged_refine"] > 0
        coarsened |= merged
print(f"refined after straining: {refined}, coarsened: {coarsened}")
sys.exit(0 if ok and refined and coarsened else 1)
