"""Blank holder under force control: in every row of history.csv in which
the holder is engaged (holder_engaged = 1), its force equals the set force
(Tools/Blank holder/Force in the run's parameters.prm) within 0.5 %."""
import csv, os, re, sys
import results

out = sys.argv[1]
text = open(os.path.join(out, "parameters.prm")).read()
holder = text[text.index("subsection Blank holder"):]
target = float(re.search(r"set Force\s*=\s*([-0-9.eE+]+)", holder).group(1))
rows = [r for r in results.read(out)
        if r["holder_engaged"] == "1"]
assert rows, "no row with the holder engaged"
worst = max(abs(float(r["force_blank_holder"]) / target - 1) for r in rows)
print(f"{len(rows)} rows with the holder engaged, set force {target} N, "
      f"worst relative deviation {worst:.2e} (limit 5e-3)")
sys.exit(0 if worst <= 5e-3 else 1)
