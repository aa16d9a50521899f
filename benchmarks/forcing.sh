#!/usr/bin/env bash
# Inexact Newton (Nonlinear solver/Forcing) with factorisations reused between
# close velocities: the quarter 3-D cup at 262k DoFs (planform level 6, 6
# layers), 2 ranks, single-precision factors, Reuse tolerance 1e-6, Reuse
# factorisation iterations 10, first 2 mm. One run without forcing and one
# per Reuse velocity change with Forcing = 1. Needs both cores for about
# 30 min. Runs in results/forcing/<name>/ and <name>.log; the table
# (doc/performance.md, "Inexact Newton") is printed at the end.
# Usage: bash benchmarks/forcing.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/forcing
mkdir -p "$out"
git -C "$root" rev-parse --short HEAD > "$out/commit"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() {
  local name=$1
  shift
  (cd "$root/prm" && /usr/bin/time -f "%e" mpirun -np 2 "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} \
    --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
    --set "Mesh/Layers through thickness=6" --set "Mesh/Planform refinements=6" \
    --set "Output/Output directory=$out/$name" --set "Output/Revolved copy=false" \
    --set "Output/Output interval=0" --set "Output/Report=false" \
    --set "Tools/Punch/Stroke=2" --set "Time stepping/End of run=stroke" \
    --set "Linear solver/Factor precision=single" \
    --set "Linear solver/Reuse tolerance=1e-6" \
    --set "Linear solver/Reuse factorisation iterations=10" "$@" \
    > "$out/$name.log" 2> "$out/$name.time")
}
run base --set "Linear solver/Reuse velocity change=2e-3"
for theta in 2e-3 1e-2 3e-2 5e-2 1; do
  run "forcing-$theta" --set "Linear solver/Reuse velocity change=$theta" \
    --set "Nonlinear solver/Forcing=1"
done
echo "| run | Newton it. | factorisations | factorisation (s) | substitution (s) | linear solve (s) | wall (s) | peak force (kN) | max penetration (mm) |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in base forcing-2e-3 forcing-1e-2 forcing-3e-2 forcing-5e-2 forcing-1; do
  s=$out/$name/run-summary.txt
  get() { grep "^$1 = " "$s" | cut -d' ' -f3; }
  sec() { grep -E "^\| $1 +\|" "$out/$name.log" | awk -F'|' '{print $4}' | tr -d ' s'; }
  echo "| $name | $(get newton_iterations) | $(get factorisations) | $(sec 'linear solve: factorisation') | $(sec 'linear solve: substitution') | $(sec 'linear solve') | $(tail -1 "$out/$name.time") | $(get peak_punch_force) | $(get max_penetration) |"
done
