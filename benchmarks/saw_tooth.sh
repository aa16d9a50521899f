#!/usr/bin/env bash
# The punch force's oscillation after the holder releases against the element
# length along the die radius and the time step (doc/user-guide.md, section
# 0.1): tests/cases/dc04-axisymmetric.prm drawn through on planforms 5-7, at
# 0.25 and 0.125 mm steps, and on planform 5 refined at the die radius.
# Usage: benchmarks/saw_tooth.sh [build directory]  (about 2 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build}/formsolve
out=$root/results/saw-tooth
mkdir -p "$out"
run() { # name, --set arguments...
  local name=$1; shift
  (cd "$root/tests/cases" && "$exe" dc04-axisymmetric.prm --set "Output/Output directory=$out/$name" \
     --set "Output/Report=false" "$@" > "$out/$name.log" 2>&1)
}
for r in 5 6 7; do
  for dt in 0.25 0.125; do
    run "r$r-dt$dt" --set "Mesh/Planform refinements=$r" --set "Time stepping/Time step=$dt"
  done
done
for level in 1 2; do
  run "r5-die$level" --set "Mesh refinement/Interval=4" --set "Mesh refinement/Die level=$level" \
      --set "Mesh refinement/Band width=2"
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
from run_tables import steps
import numpy as np
out = sys.argv[1]
print("| run | RMS oscillation (% of the mean force, free draw) | peak force (N) |")
print("|---|---|---|")
for name in sorted(d for d in os.listdir(out) if os.path.isdir(os.path.join(out, d))):
    rows = steps(os.path.join(out, name))
    s = np.array([float(r["punch_travel"]) for r in rows]); f = np.array([float(r["punch_force"]) for r in rows])
    free = [i for i, r in enumerate(rows) if float(r["holder_engaged"]) == 0][0]
    w = (s > s[free] + 1) & (s < s[-1] - 2.5)
    res = f[w] - np.polyval(np.polyfit(s[w], f[w], 3), s[w])
    print(f"| {name} | {100 * res.std() / f[w].mean():.1f} | {f.max():.0f} |")
PY
