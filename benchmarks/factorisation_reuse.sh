#!/usr/bin/env bash
# Direct solver with the factorisation reused as a GMRES preconditioner
# (Linear solver/Reuse factorisation iterations, Reuse tolerance) against a
# fresh factorisation per matrix, 1 rank:
#   - the quarter 3-D cup at planform level 5 (47.5k DoFs), fixed penalty,
#     first 1.5 mm (6 steps);
#   - the quarter 3-D cup at level 3 (3255 DoFs), adaptive-strict, full draw.
# Writes doc/factorisation-reuse.csv and prints the table of doc/performance.md.
# Usage: bash benchmarks/factorisation_reuse.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/factorisation-reuse
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
run() { # name sets...
  local name=$1
  shift
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} "$@" --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
}
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4")
big=("${quarter[@]}" --set "Mesh/Planform refinements=5" --set "Contact/Penalty strategy=fixed"
  --set "Tools/Punch/Stroke=1.5" --set "Time stepping/End of run=stroke")
small=("${quarter[@]}" --set "Mesh/Planform refinements=3")
r20=(--set "Linear solver/Reuse factorisation iterations=20" --set "Linear solver/Reuse tolerance=1e-10")
r8=(--set "Linear solver/Reuse factorisation iterations=8" --set "Linear solver/Reuse tolerance=1e-6")
run l5-fresh "${big[@]}"
run l5-reuse20-1e-10 "${big[@]}" "${r20[@]}"
run l5-reuse8-1e-6 "${big[@]}" "${r8[@]}"
run l3-strict-fresh "${small[@]}"
run l3-strict-reuse20-1e-10 "${small[@]}" "${r20[@]}"
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/factorisation-reuse.csv" <<'PY'
import csv, os, re, sys
from run_tables import steps
out, csv_path = sys.argv[1:3]
rows = []
for name in ("l5-fresh", "l5-reuse20-1e-10", "l5-reuse8-1e-6", "l3-strict-fresh", "l3-strict-reuse20-1e-10"):
    s = dict(l.rstrip("\n").split(" = ", 1) for l in open(f"{out}/{name}/run-summary.txt") if " = " in l)
    log = open(f"{out}/{name}.log").read()
    lin = float(re.search(r"\| linear solve\s+\|\s+\d+ \|\s+([\d.]+)s", log).group(1))
    h = steps(f"{out}/{name}")
    rows.append(dict(run=name, dofs=s["dofs"], steps=s["steps"], newton=s["newton_iterations"],
                     linear_iterations=s["linear_iterations"], factorisations=s["factorisations"],
                     linear_solve_s=f"{lin:.1f}", wall_s=f"{float(s['wall_time']):.1f}", memory_MB=f"{float(s['peak_memory_kb_all_ranks']) / 1024:.0f}",
                     peak_force_kN=f"{max(float(r['punch_force']) for r in h) / 1e3:.4f}"))
with open(csv_path, "w") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
print("| run | DoFs | steps | Newton iterations | linear iterations | factorisations | linear solve (s) | wall (s) | peak memory (MB) | peak force (kN) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| " + " | ".join(str(v) for v in r.values()) + " |")
PY
