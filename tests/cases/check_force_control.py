"""Blank holder under force control: in every row of history.csv in which
the holder is engaged (holder_engaged = 1), its force equals the set force
within 1e-5 (the printed digits; the equation is solved
exactly at convergence): Tools/Blank holder/Force of the run's parameters.prm, one
number or a table 'travel:force, ...' taken at the row's punch travel
(linear in between, the end values beyond)."""
import os, re, sys
import results

out = sys.argv[1]
text = open(os.path.join(out, "parameters.prm")).read()
holder = text[text.index("subsection Blank holder"):]
value = re.search(r"set Force\s*=\s*([^\n#]+)", holder).group(1).strip()
if ":" in value:
    table = [tuple(float(x) for x in item.split(":")) for item in value.split(",")]
else:
    table = [(0.0, float(value))]


def set_force(travel):
    if travel <= table[0][0]:
        return table[0][1]
    for (a, fa), (b, fb) in zip(table, table[1:]):
        if travel <= b:
            return fa + (fb - fa) * (travel - a) / (b - a)
    return table[-1][1]


rows = [r for r in results.read(out)
        if r["holder_engaged"] == "1"]
assert rows, "no row with the holder engaged"
worst = max(abs(float(r["force_blank_holder"]) / set_force(float(r["punch_travel"])) - 1)
            for r in rows)
print(f"{len(rows)} rows with the holder engaged, set force {value} N, "
      f"worst relative deviation {worst:.2e} (limit 1e-5)")
sys.exit(0 if worst <= 1e-5 else 1)
