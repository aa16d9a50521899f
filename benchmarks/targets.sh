#!/usr/bin/env bash
# The speed targets of issue 10 on the default cup's full draw (1 rank, the
# models of benchmarks/convergence.sh): adaptive-strict (delta = 1e-3 mm)
# against fixed 1e5, 3e5 and 1e6 N/mm^3 and the augmented Lagrangian on
# fixed 1e5. Every run twice, one after the other, so that the wall times
# show their spread; run it on an otherwise idle machine.
# Writes doc/targets.csv and prints the table of doc/convergence.md.
# Usage: bash benchmarks/targets.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/targets
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
method() { # name -> parameters
  case $1 in
    fixed-1e5) echo "Contact/Penalty strategy=fixed;Contact/Penalty factor=1e5" ;;
    fixed-3e5) echo "Contact/Penalty strategy=fixed;Contact/Penalty factor=3e5" ;;
    fixed-1e6) echo "Contact/Penalty strategy=fixed;Contact/Penalty factor=1e6" ;;
    augmented-lagrangian) echo "Contact/Penalty strategy=augmented-lagrangian;Contact/Penalty factor=1e5" ;;
    adaptive-strict) echo "Contact/Penalty strategy=adaptive-strict" ;;
  esac
}
methods="fixed-1e5 fixed-3e5 fixed-1e6 augmented-lagrangian adaptive-strict"
for model in axisymmetric quarter; do
  for m in $methods; do
    for repeat in 1 2; do
      name=$model-$m-$repeat
      [ "$FORCE" != --force ] && [ -f "$out/$name/run-summary.txt" ] && continue
      echo "== $name" >&2
      sets=()
      [ "$model" = quarter ] && sets=("${quarter[@]}")
      IFS=';' read -ra entries <<< "$(method "$m")"
      for e in "${entries[@]}"; do sets+=(--set "$e"); done
      (cd "$root/prm" && "$exe" cup-drawing.prm "${sets[@]}" \
        --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
        --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1 ||
        { tail -3 "$out/$name.log"; exit 1; }
    done
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/targets.csv" $methods <<'PY'
import sys
from run_tables import summary, write
out, csv_path, methods = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = []
for model in ["axisymmetric", "quarter"]:
    runs = {m: [summary(f"{out}/{model}-{m}-{k}") for k in (1, 2)] for m in methods}
    strict = [float(s["wall_time"]) for s in runs["adaptive-strict"]]
    for m in methods:
        s1, s2 = runs[m]
        wall = [float(s1["wall_time"]), float(s2["wall_time"])]
        # adaptive-strict's time over this method's: the range over the pairs of runs.
        ratios = [a / b for a in strict for b in wall]
        rows.append(dict(model=model, method=m, newton=int(s1["newton_iterations"]),
                         per_step=int(s1["newton_iterations"]) / int(s1["steps"]),
                         # the first step's iterations on the coarser mesh, not in newton
                         coarse=int(s1.get("coarse_start_iterations", 0)),
                         wall_1=wall[0], wall_2=wall[1],
                         strict_over_this_min=min(ratios), strict_over_this_max=max(ratios),
                         max_penetration_mm=float(s1["max_penetration"]),
                         peak_force_kN=float(s1["peak_punch_force"]) / 1e3))
write(rows, csv_path)
PY
