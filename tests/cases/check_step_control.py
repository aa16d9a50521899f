"""Step control: the run needed time-step cuts (cutbacks > 0 in some row,
and the first step's time step is below the nominal one) and still reached
the stroke; its punch force matches the reference run at the same travel
within 1 %.

Usage: check_step_control.py OUT REFERENCE_OUT"""
import csv, os, sys
import results

rows = list(results.read(sys.argv[1]))
# A force acts on the configuration at the start of its step (force_travel).
ref = {round(float(r["force_travel"]), 6): float(r["punch_force"])
       for r in results.read(sys.argv[2])}
cuts = sum(int(float(r["cutbacks"])) for r in rows)
print(f"{len(rows)} steps, {cuts} cut(s); time steps {[r['time_step'] for r in rows]}")
ok = cuts > 0 and abs(float(rows[-1]["punch_travel"]) - 3) < 1e-9
worst = 0
for r in rows:
    t = round(float(r["force_travel"]), 6)
    if t in ref:
        worst = max(worst, abs(float(r["punch_force"]) / ref[t] - 1))
print(f"worst relative force difference to the reference {worst:.2e} (limit 1e-2)")
sys.exit(0 if ok and worst <= 1e-2 else 1)
