"""adaptive-strict: max penetration <= delta in every row of history.csv."""
import csv, sys
import results

rows = list(results.read(sys.argv[1]))
delta = 1e-3
for r in rows:
    print(f"step {r['step']}: max penetration {float(r['max_penetration']):.4e} mm, "
          f"strict passes {r['strict_passes']}, eps {float(r['min_penalty']):.3g}..{float(r['max_penalty']):.3g} N/mm")
assert len(rows) == 4, "expected 4 steps"
worst = max(float(r["max_penetration"]) for r in rows)
print(f"worst {worst:.4e} mm (delta {delta})")
sys.exit(0 if worst <= delta * (1 + 1e-9) else 1)
