#!/usr/bin/env bash
# When the adaptive factors are estimated (Contact/Factor update = iteration,
# iteration and predictor, step): the default cup's full draw, axisymmetric
# and quarter (the models of benchmarks/convergence.sh, 1 rank), with
# adaptive-strict at time steps 0.25 (the default), 0.5 and 1 s, and with
# adaptive at 0.25 s. Per run: Newton iterations, strict passes, first and
# largest step, largest penetration, peak punch force, wall time.
# Writes doc/factor-update.csv and prints the table of doc/convergence.md.
# Usage: bash benchmarks/factor_update.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/factor-update
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
updates=("iteration" "iteration and predictor" "step")
cases=("adaptive-strict 0.25" "adaptive-strict 0.5" "adaptive-strict 1" "adaptive 0.25")
for model in axisymmetric quarter; do
  for c in "${cases[@]}"; do
    read -r strategy dt <<< "$c"
    for update in "${updates[@]}"; do
      name=$model-$strategy-$dt-${update// /-}
      [ "$FORCE" != --force ] && [ -f "$out/$name/run-summary.txt" ] && continue
      echo "== $name" >&2
      sets=()
      [ "$model" = quarter ] && sets=("${quarter[@]}")
      (cd "$root/prm" && "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} ${sets[@]+"${sets[@]}"} \
        --set "Contact/Penalty strategy=$strategy" \
        --set "Contact/Factor update=$update" \
        --set "Time stepping/Time step=$dt" \
        --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
        --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1 ||
        { tail -3 "$out/$name.log"; exit 1; }
    done
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/factor-update.csv" <<'PY'
import csv, sys
from run_tables import steps
from run_tables import summary, write
out, csv_path = sys.argv[1:3]
rows = []
for model in ["axisymmetric", "quarter"]:
    for strategy, dt in [("adaptive-strict", "0.25"), ("adaptive-strict", "0.5"),
                         ("adaptive-strict", "1"), ("adaptive", "0.25")]:
        for update in ["iteration", "iteration and predictor", "step"]:
            run = f"{out}/{model}-{strategy}-{dt}-{update.replace(' ', '-')}"
            h = steps(f"{run}")
            s = summary(run)
            newton = [int(r["newton_iterations"]) for r in h]
            rows.append(dict(model=model, strategy=strategy, dt=dt, update=update,
                             steps=len(h), newton=sum(newton),
                             per_step=sum(newton) / len(h),
                             passes=sum(int(r["strict_passes"]) for r in h),
                             first=newton[0], largest=max(newton),
                             cutbacks=sum(int(r["cutbacks"]) for r in h),
                             max_penetration=max(float(r["max_penetration"]) for r in h),
                             peak_force_kN=max(float(r["punch_force"]) for r in h) / 1e3,
                             wall=float(s["wall_time"])))
write(rows, csv_path, table_digits=4)
PY
