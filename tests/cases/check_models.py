"""Quarter 3-D against axisymmetric on the same short cup (same radial
resolution): punch force within 2 % at every travel from 2.5 mm on, where
the sheet has wrapped the punch nose. Before that the two discretisations
differ by more (the nose bends the sheet across one or two coarse elements;
doc/models.md). Also runs check_force_control on both.

With --thickness-strain TOL also the thickness strain ln(t_min/t0) of the
last common step within TOL (absolute).

Usage: check_models.py QUARTER_OUT AXISYMMETRIC_OUT [--thickness-strain TOL]"""
import csv, math, os, subprocess, sys
import results

def forces(out):
    # A force acts on the configuration at the start of its step.
    return {round(float(r["force_travel"]), 6): float(r["punch_force"])
            for r in results.read(out)}

quarter, axi = forces(sys.argv[1]), forces(sys.argv[2])
# A step cut in one run shifts its travels: compare the quarter's rows with
# the axisymmetric force interpolated linearly between its steps.
ta = sorted(axi)
def interpolate(t):
    for a, b in zip(ta, ta[1:]):
        if a - 1e-9 <= t <= b + 1e-9:
            return axi[a] + (axi[b] - axi[a]) * (t - a) / (b - a)
    return None
axi = {t: interpolate(t) for t in quarter}
common = sorted(t for t in quarter if axi[t] is not None and t >= 2.5 - 1e-9)
assert len(common) >= 8, f"too few common rows: {common}"
worst = max(abs(quarter[t] / axi[t] - 1) for t in common)
for t in common:
    print(f"travel {t:5.2f} mm: quarter {quarter[t]:9.1f} N, axisymmetric {axi[t]:9.1f} N")
print(f"worst relative difference {worst:.2e} (limit 2e-2)")
here = os.path.dirname(os.path.abspath(__file__))
ok = worst <= 2e-2
if "--thickness-strain" in sys.argv:
    tol = float(sys.argv[sys.argv.index("--thickness-strain") + 1])
    def thickness_strain(out):
        rows = list(results.read(out))
        last = [r for r in rows if abs(float(r["force_travel"]) - common[-1]) < 1e-6][0]
        t0 = float(rows[0]["min_thickness"]) / (1 - float(rows[0]["max_thinning_percent"]) / 100)
        return math.log(float(last["min_thickness"]) / t0)
    eq, ea = thickness_strain(sys.argv[1]), thickness_strain(sys.argv[2])
    print(f"thickness strain at {common[-1]} mm: quarter {eq:.4f}, axisymmetric {ea:.4f} (limit {tol})")
    ok = ok and abs(eq - ea) <= tol
for out in sys.argv[1:3]:
    ok = subprocess.call([sys.executable, os.path.join(here, "check_force_control.py"), out]) == 0 and ok
sys.exit(0 if ok else 1)
