"""An additional tool (Tools/Additional tools) in a run, from its history.csv,
solver.csv and parameters.prm.

  check_additional_tools.py OUT force NAME
    Motion = force: in every row the tool's force on the sheet along its
    Direction (force_along_<key>) equals its set Force within 0.5 %; every
    row has it engaged (the scene starts in contact). The blank holder under
    force control, if any, likewise (check_force_control.py).
  check_additional_tools.py OUT prescribed NAME
    Motion = prescribed: its position along Direction is Speed x time until
    it reaches Stroke, and Stroke exactly after (to 1e-9 mm); once there it
    carries force.
Both: the sheet's equilibrium along z (nothing but the tools holds it):
|sum of the tools' z forces| / sum of their magnitudes (force_imbalance_z)
<= Nonlinear solver/Residual tolerance in every row."""
import os, re, subprocess, sys
import results

out, mode, name = sys.argv[1:4]
key = name.lower().replace(" ", "_")
text = open(os.path.join(out, "parameters.prm")).read()


def entry(section, label, within=None):
    """The value of 'set label' in subsection 'section' (under 'within')."""
    body = text[text.index(f"subsection {within}"):] if within else text
    body = body[body.index(f"subsection {section}"):]
    return re.search(rf"set {label}\s*=\s*([^#\n]*)", body).group(1).strip()


rows = results.read(out)
assert rows, "no rows"
failures = []
tolerance = float(entry("Nonlinear solver", "Residual tolerance"))
worst = max(abs(float(r["force_imbalance_z"])) for r in rows)
print(f"force imbalance along z: worst {worst:.2e} (limit {tolerance:.0e})")
if worst > tolerance:
    failures.append("the tools' forces do not balance")

if mode == "force":
    target = float(entry(name, "Force", "Tools"))
    engaged = [r for r in rows if float(r[f"force_{key}"]) > 0]
    if len(engaged) != len(rows):
        failures.append(f"{name} carries no force in {len(rows) - len(engaged)} rows")
    dev = max(abs(float(r[f"force_along_{key}"]) / target - 1) for r in rows)
    print(f"{name}: set force {target} N, worst relative deviation {dev:.2e} "
          f"over {len(rows)} rows (limit 5e-3)")
    if dev > 5e-3:
        failures.append(f"{name} does not hold its set force")
    if "holder_engaged" in rows[0] and any(r["holder_engaged"] == "1" for r in rows):
        here = os.path.dirname(os.path.abspath(__file__))
        if subprocess.call([sys.executable, os.path.join(here, "check_force_control.py"), out]):
            failures.append("the blank holder does not hold its set force")
elif mode == "prescribed":
    speed = float(entry(name, "Speed", "Tools"))
    stroke = float(entry(name, "Stroke", "Tools"))
    dev = max(abs(float(r[f"position_{key}"]) -
                  min(speed * float(r["time"]), stroke or float("inf")))
              for r in rows)
    print(f"{name}: position against min(Speed x time, Stroke): worst {dev:.1e} mm (limit 1e-9)")
    if dev > 1e-9:
        failures.append(f"{name} is not where its motion puts it")
    if stroke > 0:
        landed = [r for r in rows if float(r[f"position_{key}"]) >= stroke - 1e-12]
        if not landed:
            failures.append(f"{name} never reached its stroke")
        elif min(float(r[f"force_{key}"]) for r in landed) <= 0:
            failures.append(f"{name} carries no force after it has closed")
        else:
            print(f"{name}: at its stroke from t = {landed[0]['time']} s, force "
                  f"{min(float(r[f'force_{key}']) for r in landed):.0f} N or more")
else:
    sys.exit(f"unknown mode {mode}")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
