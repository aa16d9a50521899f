#!/usr/bin/env bash
# Factorisation reuse with and without the velocity-change rule (Linear
# solver/Reuse velocity change), the first 2 mm of the default case:
# - the quarter cup at 262k DoFs (planform level 6, 6 layers), 2 ranks,
#   single-precision factors, Reuse tolerance 1e-6 (about 25 min in all);
# - the quarter cup at levels 3 (full draw) and 5 (2 mm), 1 rank, double
#   factors.
# Writes results/reuse-velocity/<run>/ and <run>.log; doc/performance.md
# ("Factorisation reuse") reports them.
# Usage: bash benchmarks/reuse_velocity.sh [large|small|all]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/reuse-velocity
mkdir -p "$out"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
git -C "$root" rev-parse --short HEAD > "$out/commit"
cd "$root/prm"
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Output/Output interval=0" --set "Output/Revolved copy=false" --set "Output/Report=false")
stroke=(--set "Tools/Punch/Stroke=2" --set "Time stepping/End of run=stroke")
run() { # NAME RANKS ARGS...
  local name=$1 ranks=$2; shift 2
  mpirun -np "$ranks" "$exe" cup-drawing.prm "${quarter[@]}" \
    --set "Output/Output directory=$out/$name" "$@" > "$out/$name.log"
  echo "$name: $(grep '^done' "$out/$name.log" | cut -d';' -f1)"
  grep -E '^\| (Total|linear solve)' "$out/$name.log"
}
what=${1:-all}
if [ "$what" != small ]; then
  large=(--set "Mesh/Layers through thickness=6" --set "Mesh/Planform refinements=6"
    --set "Linear solver/Factor precision=single" --set "Linear solver/Reuse tolerance=1e-6" "${stroke[@]}")
  run l6-fresh 2 "${large[@]}"
  run l6-reuse10 2 "${large[@]}" --set "Linear solver/Reuse factorisation iterations=10"
  run l6-reuse10-2e-3 2 "${large[@]}" --set "Linear solver/Reuse factorisation iterations=10" \
    --set "Linear solver/Reuse velocity change=2e-3"
  run l6-reuse15-5e-3 2 "${large[@]}" --set "Linear solver/Reuse factorisation iterations=15" \
    --set "Linear solver/Reuse velocity change=5e-3"
fi
if [ "$what" != large ]; then
  small=(--set "Mesh/Layers through thickness=4")
  rv=(--set "Linear solver/Reuse factorisation iterations=10" --set "Linear solver/Reuse velocity change=2e-3")
  run l3-fresh 1 "${small[@]}" --set "Mesh/Planform refinements=3"
  run l3-reuse-2e-3 1 "${small[@]}" --set "Mesh/Planform refinements=3" "${rv[@]}"
  run l3-reuse-2e-3-tol1e-6 1 "${small[@]}" --set "Mesh/Planform refinements=3" "${rv[@]}" \
    --set "Linear solver/Reuse tolerance=1e-6"
  run l5-fresh 1 "${small[@]}" --set "Mesh/Planform refinements=5" "${stroke[@]}"
  run l5-reuse-2e-3 1 "${small[@]}" --set "Mesh/Planform refinements=5" "${stroke[@]}" "${rv[@]}"
  run l5-reuse-2e-3-tol1e-6 1 "${small[@]}" --set "Mesh/Planform refinements=5" "${stroke[@]}" "${rv[@]}" \
    --set "Linear solver/Reuse tolerance=1e-6"
fi
