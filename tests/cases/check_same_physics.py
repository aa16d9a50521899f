"""A solver setting that takes another path to the same converged steps:
history.csv against a reference, row by row, in what the engineer reads
(punch, die and holder forces, volume, largest equivalent strain, minimum
thickness, largest Oyane integral, rim radius) within RELATIVE of the
reference's value (or of the force's scale for forces), the same number of
steps, and no node deeper than the allowed penetration delta. The contact
details (factors, locked pairs, the penetration below delta) follow the
iteration path and are not compared.
Usage: check_same_physics.py OUT REFERENCE RELATIVE [DELTA]"""
import csv, sys
import results

out, reference, relative = sys.argv[1], sys.argv[2], float(sys.argv[3])
delta = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-3
rows = list(results.read(out))
ref = results.read(reference)
ok = len(rows) == len(ref)
print(f"{len(rows)} steps, reference {len(ref)}")
forces = ("punch_force", "force_die", "force_blank_holder")
scale = max(abs(float(r[k])) for r in ref for k in forces)
worst = {}
for r, s in zip(rows, ref):
    for k in forces + ("volume", "max_equivalent_strain", "min_thickness", "max_oyane", "rim_radius"):
        a, b = float(r[k]), float(s[k])
        e = abs(a - b) / (scale if k in forces else max(abs(b), 1e-12))
        worst[k] = max(worst.get(k, 0), e)
for k, e in worst.items():
    print(f"{k}: worst relative difference {e:.2e} ({'ok' if e <= relative else 'TOO LARGE'})")
    ok = ok and e <= relative
deepest = max(float(r["max_penetration"]) for r in rows)
print(f"deepest penetration {deepest:.3e} mm (delta {delta:g})")
ok = ok and deepest <= delta * (1 + 1e-9)
sys.exit(0 if ok else 1)
