"""A full draw: the run ends by draw-through (run-summary.txt), after the
blank holder was released (engaged in the first rows, not in the last, never
again once released); the holder force equals the set force while engaged;
the blank volume (2 pi int r dA in axisymmetry) is
conserved within 0.1 % over the whole run; the punch force has a maximum
inside the run and falls to below half of it at the end."""
import csv, os, subprocess, sys
import results

out = sys.argv[1]
summary = dict(l.split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")).read().splitlines())
print("end:", summary["end_reason"], "| holder released at", summary["holder_release_travel"], "mm")
ok = summary["end_reason"].startswith("drawn through")
ok = ok and 0 < float(summary["holder_release_travel"]) < float(summary["final_punch_travel"])
rows = list(results.read(out))
engaged = [r["holder_engaged"] for r in rows]
ok = ok and engaged[0] == "1" and engaged[-1] == "0" and engaged == sorted(engaged, reverse=True)
vols = [float(r["volume"]) for r in rows]
drift = max(abs(v / vols[0] - 1) for v in vols)
force = [float(r["punch_force"]) for r in rows]
peak = max(force)
print(f"{len(rows)} steps, volume drift {drift:.2e} (limit 1e-3), peak punch force {peak:.0f} N at "
      f"{rows[force.index(peak)]['punch_travel']} mm, last {force[-1]:.0f} N")
ok = ok and drift < 1e-3 and force[-1] < 0.5 * peak and force.index(peak) not in (0, len(force) - 1)
here = os.path.dirname(os.path.abspath(__file__))
ok = subprocess.call([sys.executable, os.path.join(here, "check_force_control.py"), out]) == 0 and ok
sys.exit(0 if ok else 1)
