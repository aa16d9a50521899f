#!/usr/bin/env bash
# Newton's tolerances against accuracy: the default cup's full draw,
# axisymmetric and quarter (the models of benchmarks/convergence.sh, 1 rank),
# with fixed 1e5, adaptive and adaptive-strict, at Residual tolerance =
# Correction tolerance = 1e-8, 1e-6, 1e-5 and 1e-4. Per run: Newton
# iterations and, against the 1e-8 run of the same model and strategy, the
# largest deviation over the steps of each history column below, relative
# to that column's largest magnitude over the draw.
# Writes doc/tolerance.csv and prints the table of doc/convergence.md.
# Usage: bash benchmarks/tolerance.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/tolerance
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
for model in axisymmetric quarter; do
  for strategy in fixed adaptive adaptive-strict; do
    for tol in 1e-8 1e-6 1e-5 1e-4; do
      name=$model-$strategy-$tol
      [ "$FORCE" != --force ] && [ -f "$out/$name/run-summary.txt" ] && continue
      echo "== $name" >&2
      sets=()
      [ "$model" = quarter ] && sets=("${quarter[@]}")
      [ "$strategy" = fixed ] && sets+=(--set "Contact/Penalty factor=1e5")
      (cd "$root/prm" && "$exe" cup-drawing.prm ${sets[@]+"${sets[@]}"} \
        --set "Contact/Penalty strategy=$strategy" \
        --set "Nonlinear solver/Residual tolerance=$tol" \
        --set "Nonlinear solver/Correction tolerance=$tol" \
        --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
        --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1 ||
        { tail -3 "$out/$name.log"; exit 1; }
    done
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/tolerance.csv" <<'PY'
import csv, sys
from run_tables import steps
from run_tables import summary, write
out, csv_path = sys.argv[1:3]
columns = ["punch_force", "holder_displacement", "max_penetration", "min_thickness",
           "max_thinning_percent", "volume"]
rows = []
for model in ["axisymmetric", "quarter"]:
    for strategy in ["fixed", "adaptive", "adaptive-strict"]:
        ref = steps(f"{out}/{model}-{strategy}-1e-8")
        for tol in ["1e-8", "1e-6", "1e-5", "1e-4"]:
            run = f"{out}/{model}-{strategy}-{tol}"
            got = steps(f"{run}")
            s = summary(run)
            row = dict(model=model, strategy=strategy, tolerance=tol, steps=int(s["steps"]),
                       newton=int(s["newton_iterations"]),
                       per_step=int(s["newton_iterations"]) / int(s["steps"]))
            for c in columns:
                scale = max(abs(float(r[c])) for r in ref)
                # Runs that ended at another step compare over the common steps.
                row[c] = max(abs(float(a[c]) - float(b[c])) for a, b in zip(ref, got)) / scale
            rows.append(row)
write(rows, csv_path, table_digits=2)
PY
