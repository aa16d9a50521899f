#!/usr/bin/env bash
# The direct solver's settings on formsolve's own matrices (Linear solver/
# Symmetric factorisation, Ordering; Nonlinear solver/Friction
# tangent): the quarter 3-D cup at planform level 5 (47.5k DoFs), fixed
# penalty, first 1.5 mm (6 steps), on 1 and 2 ranks; the same without friction
# (symmetric tangent: LU against LDL^T).
# Writes doc/direct-solver.csv and prints the table of doc/performance.md.
# Usage: bash benchmarks/direct_solver.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/direct-solver
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # name ranks sets...
  local name=$1 ranks=$2
  shift 2
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && mpirun -np "$ranks" "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} "$@" --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
}
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Contact/Penalty strategy=fixed"
  --set "Time stepping/End of run=stroke")
l5=("${quarter[@]}" --set "Mesh/Planform refinements=5" --set "Tools/Punch/Stroke=1.5")
frictionless=(--set "Tools/Punch/Friction coefficient=0" --set "Tools/Die/Friction coefficient=0"
  --set "Tools/Blank holder/Friction coefficient=0")
auto=(--set "Linear solver/Ordering=automatic")
lu=(--set "Linear solver/Symmetric factorisation=false")
runs=(
  "l5-mumps-auto 1" "l5-mumps-metis 1" "l5-mumps-metis-2ranks 2"
  "l5-nofriction-lu 1" "l5-nofriction-ldlt 1")
run l5-mumps-auto 1 "${l5[@]}" "${auto[@]}"
run l5-mumps-metis 1 "${l5[@]}"
run l5-mumps-metis-2ranks 2 "${l5[@]}"
run l5-nofriction-lu 1 "${l5[@]}" "${frictionless[@]}" "${lu[@]}"
run l5-nofriction-ldlt 1 "${l5[@]}" "${frictionless[@]}"
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/direct-solver.csv" "${runs[@]}" <<'PY'
import csv, re, sys
from run_tables import steps
out, csv_path = sys.argv[1:3]
rows = []
def section(log, name):
    m = re.search(r"\| " + re.escape(name) + r"\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s", log)
    if not m:
        return 0, 0.0
    t = float(m.group(2))
    return int(m.group(1)), t
for item in sys.argv[3:]:
    name, ranks = item.split()
    s = dict(l.rstrip("\n").split(" = ", 1) for l in open(f"{out}/{name}/run-summary.txt") if " = " in l)
    log = open(f"{out}/{name}.log").read()
    nf, tf = section(log, "linear solve: factorisation")
    ns, ts = section(log, "linear solve: substitution")
    _, tl = section(log, "linear solve")
    h = steps(f"{out}/{name}")
    dofs = float(s["dofs"])
    mem = float(s.get("factorisation_memory_mb", 0))
    rows.append(dict(run=name, ranks=ranks, dofs=s["dofs"], steps=s["steps"], newton=s["newton_iterations"],
                     cutbacks=s["cutbacks"], factorisations=nf,
                     s_per_factorisation=f"{tf / max(nf, 1):.3f}", s_per_substitution=f"{ts / max(ns, 1):.4f}",
                     linear_solve_s=f"{tl:.1f}", wall_s=f"{float(s['wall_time']):.1f}",
                     factor_memory_kB_per_dof=f"{mem * 1e3 / dofs:.2f}" if mem > 0 else "n/a",
                     peak_memory_MB=f"{float(s['peak_memory_kb_all_ranks']) / 1024:.0f}",
                     final_force_kN=f"{float(h[-1]['punch_force']) / 1e3:.4f}"))
with open(csv_path, "w") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
keys = list(rows[0])
print("| " + " | ".join(keys) + " |")
print("|" + "---|" * len(keys))
for r in rows:
    print("| " + " | ".join(str(r[k]) for k in keys) + " |")
PY
