#!/usr/bin/env bash
# The first step over a grid of meshes, models, strategies and settings:
# Newton iterations of step 1 (failed attempts included), its cutbacks, and
# the iterations of the first step on the coarser mesh before it
# (Nonlinear solver/First step start; 0 where it starts from rest). Writes results/first-step/<tag>.csv; with several tags
# (REPORT_TAGS, oldest first, then this one) doc/first-step.csv and a table
# for doc/convergence.md.
# Usage: [REPORT_TAGS="before"] bash benchmarks/first_step.sh [--exe PATH --tag NAME]
#          [--set "Entry=value" ...]   (added to every run, e.g. a setting to compare)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
tag=current
extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --exe) exe=$(realpath "$2"); shift ;;
    --tag) tag=$2; shift ;;
    --set) extra+=(--set "$2"); shift ;;
    *) echo "unknown option $1"; exit 1 ;;
  esac
  shift
done
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/first-step
mkdir -p "$out"
csv=$out/$tag.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMP_NUM_THREADS=1
echo "model,planform,layers,strategy,setting,iterations,cutbacks,coarse" > "$csv"
run() { # model planform layers strategy setting sets...
  local model=$1 pf=$2 layers=$3 strategy=$4 setting=$5
  shift 5
  local sets=(--set "Geometry/Model=$model" --set "Mesh/Planform refinements=$pf"
    --set "Mesh/Layers through thickness=$layers" --set "Contact/Penalty strategy=$strategy"
    --set "Mesh refinement/Interval=0" --set "Time stepping/End of run=stroke"
    --set "Output/Output interval=0" --set "Output/Revolved copy=false"
    --set "Output/Output directory=$tmp/run" "${extra[@]}")
  [ "$strategy" = fixed ] && sets+=(--set "Contact/Penalty factor=1e5")
  rm -rf "$tmp/run"
  # 0.5 mm of stroke (one step at 0.5 s, more at shorter ones); step 1 is read.
  (cd "$root/prm" && "$exe" cup-drawing.prm "${sets[@]}" --set "Tools/Punch/Stroke=0.5" "$@") \
    > "$tmp/log" 2>&1 || { tail -3 "$tmp/log"; exit 1; }
  PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$tmp/run" "$model,$pf,$layers,$strategy,$setting" >> "$csv" <<'EOF'
import csv, sys
from run_tables import steps
row = steps(sys.argv[1])[0]
summary = dict(l.split(" = ", 1) for l in open(sys.argv[1] + "/run-summary.txt").read().splitlines()
               if " = " in l)
print(f"{sys.argv[2]},{row['newton_iterations']},{row['cutbacks']},"
      f"{summary.get('coarse_start_iterations', '0')}")
EOF
  tail -1 "$csv"
}
for strategy in fixed adaptive adaptive-strict; do
  for pf in 3 4 5 6 7; do
    for layers in 2 4; do
      run axisymmetric "$pf" "$layers" "$strategy" default
    done
  done
  for pf in 2 3 4 5; do
    for layers in 2 4; do
      run quarter "$pf" "$layers" "$strategy" default
    done
  done
  run axisymmetric 5 4 "$strategy" "punch friction 0" --set "Tools/Punch/Friction coefficient=0"
  run axisymmetric 5 4 "$strategy" "dt 0.1 s" --set "Time stepping/Time step=0.1"
  run axisymmetric 5 4 "$strategy" "dt 0.5 s" --set "Time stepping/Time step=0.5"
  run axisymmetric 5 4 "$strategy" "limiting rate 1e-3" --set "Material/Limiting strain rate=1e-3"
  run axisymmetric 5 4 "$strategy" "limiting rate 1e-5" --set "Material/Limiting strain rate=1e-5"
  run axisymmetric 5 4 "$strategy" "friction regularisation 1e-2" \
    --set "Contact/Friction regularisation velocity=1e-2"
done
if [ "$tag" = current ]; then
  tags=()
  for t in ${REPORT_TAGS:-before}; do [ -f "$out/$t.csv" ] && tags+=("$t"); done
  /usr/bin/python3 "$root/benchmarks/first_step_report.py" "$out" "$root/doc/first-step.csv" \
    "${tags[@]}" current
fi
