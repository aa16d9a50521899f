#!/usr/bin/env bash
# The iterative path (issue 11, part 4): GMRES (right-preconditioned, so the
# true residual must fall by Linear solver/Tolerance = 1e-8) with ML algebraic
# multigrid on formsolve's real tangents, against the direct solver. The
# quarter 3-D cup, fixed penalty, first step (0.25 mm, from rest: it holds the
# hardest solves), 1 rank, Max iterations = 1000, Fallback to direct = true
# (a solve that fails is done by MUMPS and counted).
#   - near null space and smoother at planform level 3;
#   - DoFs (levels 2-4), cell aspect (layers 2, 4, 8), rigid-zone contrast
#     (Material/Limiting strain rate) and the volumetric penalty, each varied
#     alone with rigid-body modes and line Gauss-Seidel.
# Writes doc/iterative.csv and prints the table of doc/performance.md.
# Usage: bash benchmarks/iterative.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/iterative
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
runs=()
run() { # name level layers sets...
  local name=$1 level=$2 layers=$3
  shift 3
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} --set "Geometry/Model=quarter" \
      --set "Mesh refinement/Interval=0" --set "Mesh/Layers through thickness=$layers" \
      --set "Mesh/Planform refinements=$level" --set "Contact/Penalty strategy=fixed" \
      --set "Tools/Punch/Stroke=0.25" --set "Time stepping/End of run=stroke" \
      --set "Nonlinear solver/Log iterations=true" --set "Linear solver/Max iterations=1000" \
      --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
      --set "Output/Output directory=$out/$name" "${sets[@]}") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
  runs+=("$name|$level|$layers|$*")
}
iterative="Linear solver/Type=iterative"
line="Linear solver/AMG smoother=line Gauss-Seidel"
for level in 2 3 4; do
  run "l$level-direct" "$level" 4 "Linear solver/Type=direct"
done
run l3-translations-chebyshev 3 4 "$iterative" "Linear solver/AMG null space=translations"
run l3-rbm-chebyshev 3 4 "$iterative"
run l3-rbm-sgs 3 4 "$iterative" "Linear solver/AMG smoother=symmetric Gauss-Seidel"
run l3-translations-line 3 4 "$iterative" "Linear solver/AMG null space=translations" "$line"
for level in 2 3 4; do
  run "l$level-rbm-line" "$level" 4 "$iterative" "$line"
done
for layers in 2 8; do
  run "l3-layers$layers-rbm-line" 3 "$layers" "$iterative" "$line"
done
for rate in 1e-2 1e-3; do
  run "l3-limiting$rate-rbm-line" 3 4 "$iterative" "$line" "Material/Limiting strain rate=$rate"
done
for alpha in 1e2 1e3; do
  run "l3-penalty$alpha-rbm-line" 3 4 "$iterative" "$line" "Material/Volumetric penalty=$alpha"
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/iterative.csv" "${runs[@]}" <<'PY'
import re, statistics, sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
radius, thickness = 77 / 2, 0.78  # prm/cup-drawing.prm
rows = []
for item in sys.argv[3:]:
    name, level, layers, sets = item.split("|")
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    newton = int(s["newton_iterations"])
    direct = "Type=iterative" not in sets
    fallbacks, _ = section(log, "linear solve: factorisation")
    # Per Newton iteration: the solve and, with the holder engaged, the
    # bordered solve; a fallback adds Max iterations + 1.
    per_iteration = [int(n) for n in re.findall(r"linear=(\d+)", log)]
    converged = [n for n in per_iteration if n < 1000]
    _, linear_s = section(log, "linear solve")
    aspect = radius / 2 ** (int(level) + 1) / (thickness / int(layers))
    rows.append(dict(run=name, dofs=int(float(s["dofs"])), layers=int(layers), cell_aspect=round(aspect, 1),
                     newton=newton, solves_failed="-" if direct else f"{fallbacks}/{newton}",
                     gmres_per_newton_median="-" if direct or not converged else int(statistics.median(converged)),
                     gmres_per_newton_max="-" if direct or not converged else max(converged),
                     linear_s_per_newton=linear_s / newton, wall_s=float(s["wall_time"])))
write(rows, csv_path, 4, 3)
PY
